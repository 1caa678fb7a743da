#include "marker/codes/verify.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "marker/codes/code_reader.hpp"
#include "marker/codes/code_view.hpp"
#include "marker/codes/dot_closing.hpp"
#include "marker/codes/module_grid.hpp"
#include "marker/codes/symbol_map.hpp"
#include "marker/codes/synthetic_aperture.hpp"

namespace mark {
namespace {

constexpr int kSamplesPerSide = 8;  // points per module side where its marked share is sampled

// Share of the module's area (sampled on a grid, in the code's own frame) that is marked.
double module_share(const PlacedCode& code, const GreyImage& marked, int row, int col) {
  const Box b = code.module_box(row, col);
  double on = 0;
  for (int v = 0; v < kSamplesPerSide; ++v)
    for (int u = 0; u < kSamplesPerSide; ++u) {
      const Point local(b.min.x() + (u + 0.5) / kSamplesPerSide * b.width(),
                        b.min.y() + (v + 0.5) / kSamplesPerSide * b.height());
      const Point p = code.to_field * local;
      on += sample(marked, Eigen::Vector2d(marked.column_of(p.x()), marked.row_of(p.y()))) / 255.0;
    }
  return on / (kSamplesPerSide * kSamplesPerSide);
}

// Fill and spill against the part's marked share: every module of the symbol, and for an
// inverted code the quiet zone too (it is marked then).
void part_figures(const PlacedCode& code, const GreyImage& marked, CodeVerification& v) {
  const bool linear = is_linear(code.matrix.symbology);
  const int q = code.layout.invert ? code.quiet_modules : 0;
  const int qr = linear ? 0 : q;
  double fill_sum = 0, spill_sum = 0, fill_min = 1;
  std::size_t fill_n = 0, spill_n = 0;
  for (int r = -qr; r < code.matrix.rows + qr; ++r)
    for (int c = -q; c < code.matrix.cols + q; ++c) {
      const bool inside = r >= 0 && r < code.matrix.rows && c >= 0 && c < code.matrix.cols;
      const bool to_mark = (inside && code.matrix.dark(r, c)) != code.layout.invert;
      const double share = module_share(code, marked, r, c);
      if (to_mark) fill_sum += share, ++fill_n, fill_min = std::min(fill_min, share);
      else spill_sum += share, ++spill_n;
    }
  v.fill_ratio = fill_n ? fill_sum / static_cast<double>(fill_n) : 0;
  v.fill_ratio_min = fill_n ? fill_min : 0;
  v.spill_ratio = spill_n ? spill_sum / static_cast<double>(spill_n) : 0;
}

// A linear code's bars sampled along their middle against the threshold between them.
std::size_t linear_modules_wrong(const GreyImage& aperture, const PlacedCode& code, const ModuleGrid& grid) {
  std::vector<double> grey;
  for (int c = 0; c < code.matrix.cols; ++c) grey.push_back(sample(aperture, grid.at(0, c)));
  double lo = 255, hi = 0;
  for (double g : grey) lo = std::min(lo, g), hi = std::max(hi, g);
  const double t = (lo + hi) / 2;
  std::size_t wrong = 0;
  for (int c = 0; c < code.matrix.cols; ++c) wrong += (grey[static_cast<std::size_t>(c)] < t) != code.matrix.dark(0, c);
  return wrong;
}

// The readers' verdict: which decide, and whether the code passes.
void decide(const std::string& named, CodeVerification& v) {
  const auto outcome = [&](std::string_view name) {
    return std::find_if(v.readers.begin(), v.readers.end(), [&](const ReaderOutcome& o) { return o.reader == name; });
  };
  std::vector<const ReaderOutcome*> deciding;
  if (!named.empty()) {
    deciding.push_back(&*outcome(named));
    v.decided_by = named;
  } else {
    for (const ReaderOutcome& o : v.readers)
      if (o.supported) deciding.push_back(&o);
    v.decided_by = deciding.size() >= 2 ? "any two" : "the only reader";
  }
  std::size_t exact = 0;
  for (const ReaderOutcome* o : deciding) {
    exact += o->data_match;
    if (o->decoded && v.reader.empty()) v.reader = o->reader, v.decoded_data = o->data;
    v.decoded = v.decoded || o->decoded;
  }
  // A reader that read other data than meant fails the code whoever decides: a misread.
  const bool misread = std::any_of(v.readers.begin(), v.readers.end(),
                                   [](const ReaderOutcome& o) { return o.decoded && !o.data_match; });
  const std::size_t needed = named.empty() && deciding.size() >= 2 ? 2 : 1;
  v.data_match = !misread && exact >= needed;
  if (v.reader.empty() && !deciding.empty()) v.reader = deciding.front()->reader;
}

}  // namespace

void check_reader_choice(const std::string& name, const PlacedCode& code, const std::string& option) {
  if (name.empty()) return;
  const CodeReader* r = &named_code_reader(name, option);
  if (!r->supports(code.matrix.symbology, code.matrix.rows, code.matrix.cols))
    throw InputError(option + " " + name + " does not read " + std::string(to_string(code.matrix.symbology)) + " " +
                     std::to_string(code.matrix.rows) + "x" + std::to_string(code.matrix.cols) +
                     "; leave it out to let the readers that do decide");
}

CodeVerification verify_code(const PlacedCode& code, const CodeSpec& spec, const CodePicture& pic,
                             const VerifyOptions& o) {
  CodeVerification v;
  v.expected_data = expected_decoded_data(spec);
  v.module_um = code.module_mm * 1000;
  v.camera_px_um = pic.picture.pixel_mm * 1000;
  const GreyImage& picture = pic.picture;
  const bool linear = is_linear(code.matrix.symbology);
  const double module_px = code.module_mm / picture.pixel_mm;
  // Dots are connected before anything reads them: the gap between two touching dots' diagonal
  // neighbours is (√2 − 1) of a module, and more when the dots are smaller than the module.
  const GreyImage connected =
      code.layout.style == ModuleStyle::dot
          ? close_marks(picture, (1.45 - code.layout.dot_share) * module_px, !code.layout.invert)
          : GreyImage{};
  const GreyImage aperture =
      synthetic_aperture(code.layout.style == ModuleStyle::dot ? connected : picture, o.aperture_modules * module_px);

  // A 2-D code's readers read the camera's picture (dots closed), as a reader on the line does:
  // the synthetic aperture is the verifier's measuring tool, and its averaging costs libdmtx the
  // edges of a moderate-contrast mark it reads in the picture. A linear code is read along scan
  // lines through the aperture (as ISO/IEC 15416's scan profile is), turned upright first: ZBar
  // misses Code 128 in a sharp, noisy picture it reads through the aperture.
  const SymbolInfo symbol{code.matrix.symbology, code.matrix.rows, code.matrix.cols};
  const GreyImage& camera = code.layout.style == ModuleStyle::dot ? connected : picture;
  const GreyImage upright = linear ? code_frame_view(aperture, code, 2 * code.module_mm) : GreyImage{};
  const GreyImage& seen = linear ? upright : camera;
  const CodeReader* measuring = nullptr;
  for (const CodeReader* r : code_readers()) {
    ReaderOutcome out;
    out.reader = std::string(r->name());
    out.supported = r->supports(symbol.symbology, symbol.rows, symbol.cols);
    if (out.supported) {
      ReadResult read = r->read(seen, symbol);
      // A 2-D code a reader misses in the sharp picture is tried once more through the
      // aperture, as a fixed-mount reader tries its smoothing filter: at the camera's 15 µm the
      // scallops of pulses 33 µm apart (1000 mm/s at 30 kHz) break ZXing's edge tracing on a mark
      // libdmtx reads.
      if (!read.decoded && !linear) read = r->read(aperture, symbol);
      out.decoded = read.decoded;
      out.data = read.data;
      out.data_match = read.decoded && read.data == v.expected_data;
      if (read.decoded && !measuring && read.module_x_px > 0) {
        measuring = r;
        v.module_x_um = read.module_x_px * v.camera_px_um;
        if (read.module_y_px > 0) {
          v.module_y_um = read.module_y_px * v.camera_px_um;
          const double mean = (*v.module_x_um + *v.module_y_um) / 2;
          v.axial_nonuniformity_pct = 100 * std::abs(*v.module_x_um - *v.module_y_um) / mean;
        }
      }
    }
    v.readers.push_back(std::move(out));
  }
  decide(o.reader, v);
  if (measuring && measuring->name() != v.reader) {
    // The pitch is the one the reporting reader measured, or none.
    v.module_x_um.reset(), v.module_y_um.reset(), v.axial_nonuniformity_pct.reset();
  }

  // The intended grid fitted to the picture; the grade of a 2-D symbol on it.
  const ModuleGrid grid = fit_grid(aperture, module_refs(code.matrix, 1), intended_grid(code, picture));
  if (linear) {
    v.modules_wrong = linear_modules_wrong(aperture, code, grid);
  } else {
    v.grade = iso_grade(aperture, code.matrix, symbol_map(code.matrix), grid, v.data_match);
    v.grade->aperture_modules = o.aperture_modules;
    v.modules_wrong = v.grade->modules_wrong;
  }
  if (pic.marked) part_figures(code, *pic.marked, v);
  return v;
}

std::optional<std::string> grade_shortfall(const CodeVerification& v, int min_grade) {
  if (!v.data_match) return std::string(v.decoded ? "misread or not agreed" : "not decoded");
  if (!v.grade || v.grade->overall >= min_grade) return std::nullopt;
  const IsoGrade& g = *v.grade;
  std::string why = std::string("grade ") + grade_letter(g.overall) + " (";
  std::string low;
  const auto add = [&](const char* name, int grade) {
    if (grade < min_grade) low += (low.empty() ? "" : ", ") + std::string(name) + " " + grade_letter(grade);
  };
  add("cell contrast", g.cell_contrast_grade);
  add("cell modulation", g.cell_modulation_grade);
  add("fixed pattern damage", g.fixed_pattern_grade);
  add("axial non-uniformity", g.axial_nonuniformity_grade);
  add("grid non-uniformity", g.grid_nonuniformity_grade);
  add("unused error correction", g.unused_error_correction_grade);
  return why + low + ")";
}

}  // namespace mark
