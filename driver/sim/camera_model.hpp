#pragma once
// The camera of a fixed-mount DPM code reader looking at the simulated part: what a reader or a
// verifier really gets, not the part itself. From the part (part_image.hpp: marked share and
// reflectance on the raster's pixels, binned to the camera's pixel — the pixel's own area) the
// picture goes through
//   1. the lens: diffraction of the working f-number at the light's wavelength (a Gaussian of
//      σ = 0.42·λ·N on the sensor, the usual fit to the Airy core) and an optional defocus blur
//      disc, both scaled onto the part by the magnification;
//   2. the light: a diffuse dome whose illumination falls off toward the corners of the sensor
//      (cos⁴ and vignetting, as a quadratic falloff to the corner);
//   3. the exposure: set the way TR 29158 calibrates a verifier, the lighter surface (bare, or a
//      dark part's light marks) at `exposure_pct` of full scale in the middle of the picture;
//   4. the sensor: shot noise of `full_well_ke` electrons at full scale and read noise, from a
//      seeded generator, so a picture is the same every time; then rounded to 8 bits.
// The defaults are those of a 1.2 MP reader (docs/codes.md says which and why).
#include <cstdint>

#include "base/grey_image.hpp"
#include "driver/sim/dose_raster.hpp"
#include "driver/sim/mark_response.hpp"
#include "driver/sim/part_image.hpp"

namespace mark {

struct CameraSettings {
  int sensor_width_px = 1280;     // 1.2 MP global-shutter sensor, 1280 × 960 …
  int sensor_height_px = 960;
  double sensor_pixel_um = 3.75;  // … of 3.75 µm pixels
  // Pixel size on the part. 0: the reader is set up so the code's window fills at most the
  // sensor, never closer than its closest focus (min_pixel_um); either way a whole multiple of
  // the dose raster's pixel.
  double pixel_um = 0;
  double min_pixel_um = 15;
  double f_number = 5.6;          // working f-number on the sensor side
  double wavelength_nm = 625;     // red LED light
  double defocus_um = 0;          // blur disc diameter on the part from being out of focus
  double falloff_pct = 10;        // illumination lost at the corners of the sensor
  double exposure_pct = 78;       // the lighter surface at this share of full scale
  double full_well_ke = 10;       // electrons at full scale (shot noise)
  double read_noise_grey = 1;     // rms, in grey levels
  std::uint32_t seed = 1;         // sensor noise
  PartLook look;                  // the material as the light sees it
};

// Throws std::invalid_argument naming the setting outside its range.
void check_camera_settings(const CameraSettings& settings);

// The camera's pixel on the part for a window (mm): pixel_um, or the automatic choice; a whole
// multiple of raster_pixel_mm.
double camera_pixel_mm(const CameraSettings& settings, const FieldWindow& window, double raster_pixel_mm);

// The PSF's standard deviation on the part (mm) for a camera pixel of pixel_mm.
double camera_blur_mm(const CameraSettings& settings, double pixel_mm);

struct PartPhoto {
  GreyImage picture;  // what the camera delivers
  // The part's marked share (0..255) at the finest whole divisor of the camera's pixel that is
  // no coarser than the truth pixel asked for: the part's own truth, for figures.
  GreyImage marked;
};

// The window photographed: the part rendered, binned to the camera's pixel, then lens, light,
// exposure and sensor. A window larger than the sensor's field at that pixel is cut to it about
// its middle, as a reader aimed there sees it. `dark_part`: the part is dark and its marks light
// (bare and mark reflectance swapped). Throws std::invalid_argument for settings outside their
// ranges.
PartPhoto photograph(const DoseRaster& dose, const FieldWindow& window, const MarkResponse& response,
                     const CameraSettings& settings, bool dark_part = false, double truth_pixel_mm = 0.025);

// Lens, light, exposure and sensor applied to a part already rendered at the camera's pixel
// (with settings.look, or its dark-part swap: the exposure is set by the lighter surface).
GreyImage camera_picture(const PartImage& part, const CameraSettings& settings);

}  // namespace mark
