#include "marker/peen/block_snake.hpp"

#include <algorithm>
#include <optional>

namespace mark {
namespace {

struct Run {
  int left;
  int right;
};

// One character's dot matrix: the dots in each cell (a cell may hold several dots when they come
// from strokes) and whether the cell has been struck.
class CharMatrix {
 public:
  // The matrix origin is the character's own (0, 0) cell; cells left of or above it (which a
  // source should not produce) shift the origin so nothing falls outside.
  CharMatrix(const DotText& text, const std::vector<std::size_t>& dots) {
    int min_col = 0, min_row = 0, max_col = 0, max_row = 0;
    for (std::size_t i : dots) {
      const DotCell& c = text.dots[i].cell;
      min_col = std::min(min_col, c.col), max_col = std::max(max_col, c.col);
      min_row = std::min(min_row, c.row), max_row = std::max(max_row, c.row);
    }
    origin_ = {min_col, min_row};
    cols_ = max_col - min_col + 1;
    rows_ = max_row - min_row + 1;
    cells_.resize(static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_));
    struck_.assign(cells_.size(), false);
    for (std::size_t i : dots) {
      const DotCell& c = text.dots[i].cell;
      cells_[index(c.col - min_col, c.row - min_row)].push_back(i);
    }
  }

  int cols() const { return cols_; }
  int rows() const { return rows_; }
  // A dot still to strike at (col, row); false outside the matrix.
  bool pending(int col, int row) const {
    if (col < 0 || row < 0 || col >= cols_ || row >= rows_) return false;
    const std::size_t i = index(col, row);
    return !cells_[i].empty() && !struck_[i];
  }
  // The run of pending dots on `row` that contains `col` (which must be pending).
  Run run_at(int col, int row) const {
    Run r{col, col};
    while (pending(r.left - 1, row)) --r.left;
    while (pending(r.right + 1, row)) ++r.right;
    return r;
  }
  const std::vector<std::size_t>& dots(int col, int row) const { return cells_[index(col, row)]; }
  void strike(int col, int row) { struck_[index(col, row)] = true; }
  // The character's own cell for matrix position (col, row).
  DotCell cell(int col, int row) const { return {col + origin_.col, row + origin_.row}; }

 private:
  std::size_t index(int col, int row) const { return static_cast<std::size_t>(row * cols_ + col); }
  DotCell origin_;
  int cols_ = 0, rows_ = 0;
  std::vector<std::vector<std::size_t>> cells_;
  std::vector<bool> struck_;
};

class BlockSnake {
 public:
  BlockSnake(const DotText& text, std::size_t character, const std::vector<std::size_t>& dots,
             const Box& window, bool corners, PeenPlan& plan)
      : text_(text), character_(character), m_(text, dots), window_(window), corners_(corners),
        plan_(plan) {}

  void run() {
    while (const std::optional<DotCell> start = search_start()) {  // step 1
      std::optional<DotCell> next = start;
      while (next) {
        trace_block(*next);  // steps 2–5
        next = pop_start();  // step 6
      }
    }
  }

 private:
  // Step 1: from the origin, rows downward, alternating direction along the rows.
  std::optional<DotCell> search_start() const {
    for (int row = 0; row < m_.rows(); ++row)
      for (int k = 0; k < m_.cols(); ++k) {
        const int col = row % 2 == 0 ? k : m_.cols() - 1 - k;
        if (m_.pending(col, row)) return DotCell{col, row};
      }
    return std::nullopt;
  }

  std::optional<DotCell> pop_start() {
    while (!stack_.empty()) {
      const DotCell c = stack_.back();
      stack_.pop_back();
      if (m_.pending(c.col, c.row)) return c;
    }
    return std::nullopt;
  }

  // Strikes cells from `from` to `to` inclusive along the row, every dot of each cell.
  void strike_span(int row, int from, int to) {
    const int step = to >= from ? 1 : -1;
    for (int col = from;; col += step) {
      std::vector<std::size_t> cell = m_.dots(col, row);
      // Several dots in one cell (stroke dots): take them in the direction of travel.
      std::sort(cell.begin(), cell.end(), [&](std::size_t a, std::size_t b) {
        return step * text_.dots[a].pos_mm.x() < step * text_.dots[b].pos_mm.x();
      });
      for (std::size_t i : cell) plan_.stops.push_back({text_.dots[i].pos_mm, i});
      m_.strike(col, row);
      if (col == to) break;
    }
  }

  // One axis at a time toward matrix cell `target`: the corner where the head turns, along the
  // matrix's Y first (the patent's one-way axis), else along its X first when that corner would
  // leave the window (rotated or sheared characters), else straight.
  void turn_toward(DotCell target) {
    if (!corners_) return;
    const Point from = plan_.stops.empty() ? plan_.home_mm : plan_.stops.back().pos_mm;
    const Affine& frame = text_.cell_frames.at(character_);
    const Point f = frame.inverse() * from;
    const DotCell t = m_.cell(target.col, target.row);
    const Point to = frame * Point(t.col, t.row);
    const double tol = 1e-3 * text_.pitch_mm;
    for (const Point& c : {Point(f.x(), t.row), Point(t.col, f.y())}) {
      const Point corner = frame * c;
      if ((corner - from).norm() <= tol || (corner - to).norm() <= tol) return;  // one axis already
      if (window_.contains(Box{corner, corner}, 1e-9)) {
        plan_.stops.push_back({corner, std::nullopt});
        return;
      }
    }
  }

  // Steps 2–5 for one block.
  void trace_block(DotCell start) {
    turn_toward(start);
    int row = start.row;
    int x = start.col;  // the head's column
    Run run = m_.run_at(x, row);
    while (true) {
      int x1 = 0, x2 = 0;  // this row's X travel [X1, X2], ending at X2
      if (x <= run.left) {
        strike_span(row, run.left, run.right);
        x1 = std::min(x, run.left), x2 = run.right;
        dir_ = x2 > x1 ? 1 : dir_;
      } else if (x >= run.right) {
        strike_span(row, run.right, run.left);
        x1 = std::max(x, run.right), x2 = run.left;
        dir_ = x2 < x1 ? -1 : dir_;
      } else {
        // Steps 3–4: an X two-way point. Nearer end first (ties: keep the last direction),
        // back past the two-way point, then to the other end.
        const int to_right = run.right - x, to_left = x - run.left;
        const bool right_first = to_right < to_left || (to_right == to_left && dir_ > 0);
        if (right_first) {
          strike_span(row, x, run.right);
          strike_span(row, x - 1, run.left);
          x1 = run.right, x2 = run.left, dir_ = -1;
        } else {
          strike_span(row, x, run.left);
          strike_span(row, x + 1, run.right);
          x1 = run.left, x2 = run.right, dir_ = 1;
        }
      }
      // Step 5: sense the next row over [X2, X1] from X2.
      const std::optional<Run> next = sense(row + 1, x2, x1);
      if (!next) return;
      ++row;  // the one-way Y step; the head keeps column X2
      x = x2;
      run = *next;
      // The track moves one axis at a time: when the step down lands beside the run, the head
      // turns there (a stop without a strike) before running along the row.
      if (x < run.left) turn_toward({run.left, row});
      if (x > run.right) turn_toward({run.right, row});
    }
  }

  // The first run of pending dots met on `row` scanning from x2 toward x1 (this block's next
  // row); the start of the second run met is pushed as a next-block start point.
  std::optional<Run> sense(int row, int x2, int x1) {
    const int step = x1 >= x2 ? 1 : -1;
    std::optional<Run> first;
    for (int col = x2; step * (x1 - col) >= 0; col += step) {
      if (!m_.pending(col, row)) continue;
      if (!first) {
        first = m_.run_at(col, row);
        col = step > 0 ? first->right : first->left;  // skip the rest of this run
      } else {
        stack_.push_back({col, row});
        break;
      }
    }
    return first;
  }

  const DotText& text_;
  std::size_t character_;
  CharMatrix m_;
  Box window_;
  bool corners_;
  PeenPlan& plan_;
  std::vector<DotCell> stack_;  // next-block start points
  int dir_ = 1;                 // last direction of travel along X
};

}  // namespace

PeenPlan plan_block_snake(const DotText& text, const Box& window, bool one_axis_at_a_time) {
  PeenPlan plan;
  plan.planner = "block";
  plan.home_mm = Point(window.min.x(), window.max.y());
  std::vector<std::vector<std::size_t>> by_char(text.characters);
  for (std::size_t i = 0; i < text.dots.size(); ++i) by_char.at(text.dots[i].character).push_back(i);
  for (std::size_t c = 0; c < by_char.size(); ++c)
    if (!by_char[c].empty()) BlockSnake(text, c, by_char[c], window, one_axis_at_a_time, plan).run();
  return plan;
}

}  // namespace mark
