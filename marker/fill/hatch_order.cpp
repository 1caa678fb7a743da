#include "marker/fill/hatch_order.hpp"

#include <algorithm>
#include <array>

#include "marker/order/visit_order.hpp"

namespace mark {
namespace {

// Pieces of consecutive rows that overlap one to one, bottom row first.
using Block = std::vector<std::size_t>;

bool overlap(const HatchPiece& a, const HatchPiece& b) { return a.x0 < b.x1 && b.x0 < a.x1; }

std::vector<Block> make_blocks(const std::vector<HatchPiece>& pieces) {
  std::vector<Block> blocks;
  // Pieces come row by row, left to right. For each piece of the previous row: the block it
  // ends, and how many pieces of the current row it overlaps (and vice versa).
  std::size_t prev_begin = 0, prev_end = 0;  // previous row's pieces [begin, end)
  std::vector<std::size_t> block_of(pieces.size(), 0);
  for (std::size_t begin = 0; begin < pieces.size();) {
    std::size_t end = begin;
    while (end < pieces.size() && pieces[end].row == pieces[begin].row) ++end;
    const bool adjacent = prev_end > prev_begin && pieces[prev_begin].row + 1 == pieces[begin].row;
    for (std::size_t i = begin; i < end; ++i) {
      std::size_t match = SIZE_MAX;
      if (adjacent) {
        std::size_t count = 0;
        for (std::size_t j = prev_begin; j < prev_end; ++j)
          if (overlap(pieces[i], pieces[j])) match = j, ++count;
        if (count == 1) {
          // The previous piece must overlap only this one as well.
          std::size_t back = 0;
          for (std::size_t k = begin; k < end; ++k) back += overlap(pieces[match], pieces[k]);
          if (back != 1) match = SIZE_MAX;
        } else {
          match = SIZE_MAX;
        }
      }
      if (match == SIZE_MAX) {
        block_of[i] = blocks.size();
        blocks.push_back({i});
      } else {
        block_of[i] = block_of[match];
        blocks[block_of[i]].push_back(i);
      }
    }
    prev_begin = begin;
    prev_end = end;
    begin = end;
  }
  return blocks;
}

// A block drawn from its first row (or from its last, `from_top`), its first line left to right
// (or right to left, `flip`); serpentine lines alternate, one-way lines all run left to right.
std::vector<HatchLine> draw_block(const Block& b, const std::vector<HatchPiece>& pieces,
                                  const HatchFrame& f, HatchDirection dir, bool from_top, bool flip) {
  std::vector<HatchLine> out;
  out.reserve(b.size());
  for (std::size_t n = 0; n < b.size(); ++n) {
    const HatchPiece& p = pieces[b[from_top ? b.size() - 1 - n : n]];
    const double y = f.row_y(p.row);
    bool reverse = dir == HatchDirection::bidirectional ? ((n % 2 == 1) != flip) : false;
    const Point a = f.to_field(p.x0, y), c = f.to_field(p.x1, y);
    out.push_back(reverse ? HatchLine{c, a} : HatchLine{a, c});
  }
  return out;
}

}  // namespace

double hatch_jump_length_mm(const std::vector<HatchLine>& lines, const Point& at) {
  double len = 0;
  Point p = at;
  for (const HatchLine& l : lines) {
    len += (l.start - p).norm();
    p = l.end;
  }
  return len;
}

std::vector<HatchLine> order_hatch(const std::vector<HatchPiece>& pieces, const HatchFrame& frame,
                                   HatchDirection direction, HatchOrder order, Point& at) {
  std::vector<HatchLine> out;
  out.reserve(pieces.size());
  if (pieces.empty()) return out;
  if (order == HatchOrder::raster) {
    for (const HatchPiece& p : pieces) {
      const double y = frame.row_y(p.row);
      out.push_back({frame.to_field(p.x0, y), frame.to_field(p.x1, y)});
    }
    at = out.back().end;
    return out;
  }
  const std::vector<Block> blocks = make_blocks(pieces);
  // Each block as a visiting item: forward = from its first row, reversed = from its last row
  // (the serpentine traced backwards, or the one-way lines taken top down).
  std::vector<VisitItem> items;
  items.reserve(blocks.size());
  for (const Block& b : blocks) {
    const std::vector<HatchLine> up = draw_block(b, pieces, frame, direction, false, false);
    const std::vector<HatchLine> down =
        direction == HatchDirection::bidirectional
            ? std::vector<HatchLine>{}
            : draw_block(b, pieces, frame, direction, true, false);
    if (direction == HatchDirection::bidirectional)
      items.push_back(VisitItem::stroke(up.front().start, up.back().end));
    else
      items.push_back({up.front().start, up.back().end, true, down.front().start, down.back().end});
  }
  for (const VisitStep& step : plan_visit_order(items, at)) {
    const Block& b = blocks[step.item];
    // Of the ways into this block that match the visiting order's choice of end, take the one
    // whose first line starts nearest to the beam (a serpentine can begin at either side).
    std::vector<HatchLine> best;
    double best_d = INFINITY;
    for (bool flip : {false, true}) {
      if (flip && direction == HatchDirection::unidirectional) continue;
      std::vector<HatchLine> lines = draw_block(b, pieces, frame, direction, step.reversed, flip);
      const double d = (lines.front().start - at).norm();
      if (d < best_d) best_d = d, best = std::move(lines);
    }
    at = best.back().end;
    out.insert(out.end(), best.begin(), best.end());
  }
  return out;
}

}  // namespace mark
