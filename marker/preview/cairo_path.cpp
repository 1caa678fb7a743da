#include "marker/preview/cairo_path.hpp"

#include <cmath>

#include "fonts/overloaded.hpp"

namespace mark {

void append_element(cairo_t* cr, const Element& element) {
  const Point s = element.start();
  bool connected = false;
  if (cairo_has_current_point(cr)) {
    double x, y;
    cairo_get_current_point(cr, &x, &y);
    connected = std::abs(x - s.x()) < 1e-9 && std::abs(y - s.y()) < 1e-9;
  }
  if (!connected) cairo_move_to(cr, s.x(), s.y());
  std::visit(Overloaded{
                 [&](const Line& l) { cairo_line_to(cr, l.end.x(), l.end.y()); },
                 [&](const CircularArc& a) {
                   const double a1 = a.start_angle + a.sweep;
                   if (a.sweep >= 0)
                     cairo_arc(cr, a.center.x(), a.center.y(), a.radius, a.start_angle, a1);
                   else
                     cairo_arc_negative(cr, a.center.x(), a.center.y(), a.radius, a.start_angle, a1);
                 },
                 [&](const EllipticalArc& e) {
                   cairo_matrix_t saved;
                   cairo_get_matrix(cr, &saved);
                   cairo_translate(cr, e.center.x(), e.center.y());
                   cairo_rotate(cr, e.rotation);
                   cairo_scale(cr, e.rx, e.ry);
                   const double t1 = e.start_param + e.sweep;
                   if (e.sweep >= 0)
                     cairo_arc(cr, 0, 0, 1, e.start_param, t1);
                   else
                     cairo_arc_negative(cr, 0, 0, 1, e.start_param, t1);
                   cairo_set_matrix(cr, &saved);
                 }},
             element.geometry());
}

}  // namespace mark
