#include "marker/locus/path_walker.hpp"

#include "fonts/overloaded.hpp"

namespace mark {

void PathWalker::start(const Element& e, std::uint32_t steps) {
  kind_ = e.kind();
  n_ = steps;
  end_ = e.end();
  std::visit(Overloaded{[&](const Line& l) {
                          p0_ = l.start;
                          d_ = (l.end - l.start) / static_cast<double>(steps);
                        },
                        [&](const CircularArc& a) {
                          p0_ = a.center;
                          r_ = a.radius;
                          cos_ = std::cos(a.start_angle);
                          sin_ = std::sin(a.start_angle);
                          const double step = a.sweep / steps;
                          rot_c_ = std::cos(step);
                          rot_s_ = std::sin(step);
                        },
                        [&](const EllipticalArc&) {
                          table_.build(e);
                          cursor_ = 0;
                          ds_ = table_.length() / steps;
                        }},
             e.geometry());
}

}  // namespace mark
