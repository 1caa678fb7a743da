#pragma once
// One gravure stylus sample at the stylus clock (200 kHz, 5 µs): the drive the amplifier sends
// to the engraving head, in micrometres of stylus travel (the head's static gain is 1 µm per
// µm of drive), measured as depth below the cylinder surface — positive cuts into the copper,
// negative holds the diamond above it. The drive has already been through the tuning filters
// (notch / emphasis biquads), so it is not the toolpath itself: at high frequencies it is
// several times larger than the depth it produces.
//
// `lifted` retracts the whole head clear of the cylinder: nothing cuts while it is set, however
// the stylus swings. Only the safe sample sets it; a device that sees it keeps the head
// retracted for the rest of the job (like a laser that stays off after an underrun).
namespace mark {

struct StylusSample {
  float drive_um = 0;
  bool lifted = false;
};

// Where the safe sample leaves the stylus: this far above the surface, and the head retracted.
inline constexpr float kStylusSafeDrive_um = -20.0f;

// The safe sample (ringbuffer/sample_traits.hpp): the stylus lifted clear of the cylinder.
// Deliberately not the last depth, which would keep cutting.
inline StylusSample safe_sample(const StylusSample&) { return {kStylusSafeDrive_um, true}; }

}  // namespace mark
