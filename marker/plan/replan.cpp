#include "marker/plan/replan.hpp"

#include "marker/plan/plan_builder.hpp"

namespace mark {

Replanner::Replanner(const Pen& pen, StrokeOrder order, const Point& home)
    : pen_(pen), order_(order), home_(home) {
  plan_.pen = pen;
  plan_.home = home;
}

const Plan& Replanner::update(const Figure& figure) {
  const std::size_t n = figure.glyphs.size();
  if (order_ != StrokeOrder::glyph) {
    plan_ = plan_figure(figure, pen_, order_, home_);
    bounds_ = plan_.bounds();
    replanned_ = n;
    return plan_;
  }
  count_plan();  // planned again from its first changed glyph: one plan of this part
  std::vector<GlyphKey> keys(n);
  for (std::size_t g = 0; g < n; ++g) {
    const PlacedGlyph& p = figure.glyphs[g];
    keys[g] = {p.code_point, p.shape, p.origin, p.rotation_rad};
  }
  std::size_t k = 0;  // first glyph whose commands must be planned again
  while (k < n && k < keys_.size() && keys[k] == keys_[k]) ++k;
  if (k == n && n == keys_.size()) {
    replanned_ = 0;
    return plan_;
  }
  Before state;
  state.pen_at = home_;
  state.bounds.add(home_);
  if (k < before_.size()) state = before_[k];
  before_.resize(k);
  plan_.commands.erase(plan_.commands.begin() + static_cast<std::ptrdiff_t>(state.command), plan_.commands.end());
  PlanBuilder b{plan_.pen, plan_.commands,
                plan_.commands.empty() ? home_ : plan_.commands.back().end(), {}};
  for (std::size_t g = k; g < n; ++g) {
    state.command = plan_.commands.size();
    before_.push_back(state);
    strokes_.clear();
    append_glyph_strokes(figure, g, strokes_);
    for (const Stroke& s : strokes_) {
      state.jump_mm += (s.start() - state.pen_at).norm();
      state.pen_at = s.end();
      ++state.strokes;
      switch (pen_.corner) {
        case CornerStrategy::none: plan_stroke_plain(b, s); break;
        case CornerStrategy::delays: plan_stroke_delays(b, s); break;
        case CornerStrategy::blanking: plan_stroke_blanking(b, s); break;
      }
    }
    for (std::size_t c = state.command; c < plan_.commands.size(); ++c)
      state.bounds.add(plan_.commands[c].path.bounds());
  }
  plan_.strokes = state.strokes;
  plan_.jump_length_mm = state.jump_mm;
  bounds_ = state.bounds;
  keys_ = std::move(keys);
  replanned_ = n - k;
  return plan_;
}

}  // namespace mark
