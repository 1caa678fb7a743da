#pragma once
// How the part answers the laser: a Gaussian beam of a given 1/e² diameter, and a fluence
// threshold above which the surface turns (dark on steel by annealing, light on anodised
// aluminium). The threshold is set the way a user calibrates a material: a single line marked
// at a reference speed comes out a reference width wide. A faster line is then narrower and,
// fast enough, vanishes — the effect that limits how fast a code can be marked and still read.
//
// Fluence of a straight line marked at speed v with the beam's 1/e² radius w, at distance r
// from its centre: F(r) = (1/v)·√(2/π)/w · exp(−2r²/w²)  (seconds of full power per mm²,
// the dose raster's unit).
namespace mark {

struct MarkResponse {
  // 1/e² beam diameter on the part: a fiber laser on an F160 lens, the job files' default spot.
  double spot_diameter_mm = 0.04;
  double reference_speed_mm_s = 1000;   // a single line at this speed ...
  double reference_width_mm = 0.04;     // ... marks this wide

  double beam_radius_mm() const { return spot_diameter_mm / 2; }
  // Fluence threshold F_th = F(reference_width/2) at the reference speed, s/mm².
  double threshold_s_mm2() const;
  // Width of a single line marked at `speed` (0 when its peak stays below the threshold).
  double line_width_mm(double speed_mm_s) const;
  // Fastest speed at which a single line still marks at all.
  double vanishing_speed_mm_s() const;
  // Speed at which a single line marks one beam diameter wide: the material's energy per mm is
  // full power at this speed (the reference speed when the reference line is one spot wide).
  double spot_line_speed_mm_s() const;
};

// Throws std::invalid_argument naming the parameter when one is outside its range
// (spot 0.001 .. 5 mm, speed 1 .. 100 000 mm/s, width 0.001 .. 3 spot diameters).
void check_mark_response(const MarkResponse& response);

}  // namespace mark
