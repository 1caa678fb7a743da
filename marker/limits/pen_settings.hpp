#pragma once
// The settings of a laser pen: the planner's motion settings and the laser source's, as
// `marker mark` / `marker code` options and as a job file's pens (one declaration each,
// setting.hpp). Speeds and the tick also depend on the head (its positioning limit, 20 % of its
// τ): those limits are applied with limited_range() once the head is known. Defaults that come
// from the head's tracking error τ are computed by pen_for_profile (marker/job/head_pen.hpp).
#include "marker/limits/setting.hpp"

namespace mark {

inline constexpr Choice kCorner{{"--corner", "corner", "corner strategy"}, "blanking, delays, none", "blanking"};
inline constexpr Quantity kMarkSpeed{
    {"--speed", "speed_mm_s", "marking speed (with --lookahead: the most; at most the head's positioning limit)"},
    {0.001, 100000, "mm/s"},
    1000,
    "1000; `mark` and `job new`: `auto`"};
// `mark --speed auto` and `job new --speed auto` (marker/job/auto_speed.hpp: its cap and shrink).
inline constexpr std::string_view kAutoSpeed = "auto";
inline constexpr std::string_view kAutoSpeedHelp =
    "the fastest (up to 1000 mm/s) at which the head's lag shrinks the tightest curve by at most 8 µm";
inline constexpr Quantity kJumpSpeed{{"--jump-speed", "jump_speed_mm_s", "jump speed (at most the head's positioning limit)"},
                                     {1, 100000, "mm/s"},
                                     {},
                                     "half the head's positioning limit"};
inline constexpr Quantity kTick{{"--tick", "tick_us", "locus tick (at most 20 % of the head's τ)"}, {1, 1000, "µs"}, 10};
inline constexpr Text kHeadProfile{
    {"--head-profile", "", "the planner's model of the head: a profile from `marker head identify`"},
    {},
    "the head's datasheet values"};
inline constexpr Toggle kLookahead{
    {"--lookahead", "", "plan the speed along every move within the head's acceleration (docs/speed.md)"}};
inline constexpr Toggle kFeedForward{
    {"--feed-forward", "",
     "pre-compensate every command by the head model so the beam follows the path (implies --lookahead)"}};

// Delays and lags: a few τ of the slowest head at most; 100 ms is far beyond any of them.
inline constexpr Bounds kDelayBounds{0, 100000, "µs"};
inline constexpr Quantity kLaserOnDelay{
    {"--laser-on-delay-us", "laser_on_delay_us", "laser-on edges delayed against the mirrors"},
    kDelayBounds, {}, "blanking τ; delays 0.6τ; none 0"};
inline constexpr Quantity kLaserOffDelay{
    {"--laser-off-delay-us", "laser_off_delay_us", "laser-off edges delayed against the mirrors"},
    kDelayBounds, {}, "blanking τ; delays 1.2τ; none 0"};
inline constexpr Quantity kJumpDelay{{"--jump-delay-us", "jump_delay_us", "delays: wait after every jump"},
                                     kDelayBounds, {}, "delays 2τ"};
inline constexpr Quantity kJumpSettle{
    {"--jump-settle-um", "jump_settle_um",
     "delays: lengthen jump delays until the transient is this small (0: the fixed jump delay only)"},
    {0, 1000, "µm"}, {}, "delays 1"};
inline constexpr Quantity kMarkDelay{{"--mark-delay-us", "mark_delay_us", "delays: wait after a stroke's last mark"},
                                     kDelayBounds, {}, "delays τ"};
inline constexpr Quantity kPolygonDelay{
    {"--polygon-delay-us", "polygon_delay_us", "delays: lit wait at a corner × (1 − cos φ)"},
    kDelayBounds, {}, "delays 0.5τ"};
inline constexpr Quantity kBlankAngle{
    {"--blank-angle-deg", "blank_angle_deg", "blanking: corners turning more than this are blanked"},
    {0, 180, "degrees"}, 8};
// Blanking run-ins and run-outs: a few v·τ (under 1 mm at any head's speed); more only costs time.
inline constexpr Bounds kExtensionBounds{0, 10, "mm"};
inline constexpr Quantity kRunIn{{"--run-in", "run_in_mm", "blanking run-in length"},
                                 kExtensionBounds, {}, "sized by the head's settling; feed-forward 1 × v²/(2a)"};
inline constexpr Quantity kMinRunIn{{"--min-run-in", "min_run_in_mm", "blanking: shortest automatic run-in"},
                                    kExtensionBounds, {}, "1 × v·τ"};
inline constexpr Quantity kRunOut{{"--run-out", "run_out_mm", "blanking run-out length"},
                                  kExtensionBounds, {}, "1 × v·τ; feed-forward 1 × v²/(2a)"};
inline constexpr Quantity kSettle{
    {"--settle-um", "settle_um",
     "blanking: transient left when the laser switches on (0: run-ins at their shortest only)"},
    {0, 1000, "µm"}, 1};
inline constexpr Quantity kJoinSpeed{
    {"--join-speed", "join_speed_mm_s",
     "blanking: speed of the line joining run-out and run-in (0: the jump speed; at most the head's positioning "
     "limit)"},
    {0, 100000, "mm/s"}, {}, "the jump speed"};
inline constexpr Quantity kTrackingError{
    {"--tracking-error-us", "", "the lag the delays and run-ins are sized for"}, kDelayBounds, {}, "τ"};
inline constexpr Bounds kAccelBounds{0, 1e10, "mm/s²"};
inline constexpr Quantity kAccel{
    {"--accel", "", "look-ahead: acceleration on lit moves and arrivals (above 0, at most the head's)"},
    kAccelBounds, {}, "0.5 × the profile's max accel"};
inline constexpr Quantity kJumpAccel{
    {"--jump-accel", "", "look-ahead: acceleration on laser-off moves (above 0, at most the head's)"},
    kAccelBounds, {}, "0.8 × the profile's max accel"};
inline constexpr Quantity kCurveAccel{
    {"--curve-accel", "", "look-ahead: centripetal acceleration on curves (above 0, at most the head's)"},
    kAccelBounds, {}, "0.5 × the profile's max accel"};
inline constexpr Quantity kAccelLimit{
    {"--accel-limit", "",
     "look-ahead: the head's acceleration limit, shared by tangential and centripetal on curves (0: no check)"},
    kAccelBounds, {}, "the profile's max accel"};
inline constexpr Bounds kPenSpeedBounds{0, 100000, "mm/s"};
inline constexpr Quantity kJunctionDv{
    {"--junction-dv", "", "look-ahead: velocity step allowed at a turn without a stop"}, kPenSpeedBounds, 100};
inline constexpr Quantity kLaserSwitchSpeed{
    {"--laser-switch-speed", "", "look-ahead: speed the laser may switch at where the path runs straight on"},
    kPenSpeedBounds, 0};
inline constexpr Quantity kMinLitSpeed{
    {"--min-lit-speed", "", "look-ahead: lit moves are dark below this speed"}, kPenSpeedBounds, {},
    "3 % of the marking speed"};
inline constexpr Quantity kFfLag{{"--ff-lag-us", "", "feed-forward: the model's ramp lag (τ or 2ζ/ωn)"},
                                 kDelayBounds, {}, "feed-forward: τ or 2ζ/ωn"};
inline constexpr Quantity kFfInertia{{"--ff-inertia-us2", "", "feed-forward: the model's 1/ωn² (0: first order)"},
                                     {0, 1e10, "µs²"}, {}, "feed-forward: 1/ωn² (second order)"};
// Input shaping (marker/plan/input_shaper.hpp). The resonance is checked against the tick as
// well (at most a quarter of the tick rate, so its half period spans two ticks).
inline constexpr Quantity kShaperHz{
    {"--shaper-hz", "", "look-ahead: shape the locus against a mirror resonance at this frequency (0: off)"},
    {100, 250000, "Hz", false, true}, 0};
inline constexpr Quantity kShaperZeta{
    {"--shaper-zeta", "", "look-ahead: the damping ratio of that resonance"}, {0, 0.5, ""}, 0.02};
inline constexpr Choice kShaper{
    {"--shaper", "", "look-ahead: input shaper, zv (2 impulses, 1/2 period) or zvd (3 impulses, a whole period)"},
    "zv, zvd", "zv"};

// The laser source (driver/laser_source.hpp: each one's limits).
inline constexpr Choice kLaserSource{
    {"--source", "source", "laser source: fiber (Q-switched), mopa, co2, uv"}, "fiber, mopa, co2, uv", "fiber"};
inline constexpr Quantity kPower{{"--power", "power_pct", "laser power, % of the source"}, {0, 100, "%"}, 100};
// The widest any source runs (driver/laser_source.hpp: MOPA 1 .. 4000 kHz); each source's own
// range is checked against the pen's source.
inline constexpr Quantity kFrequency{
    {"--frequency", "frequency_khz", "pulse repetition rate (Q-switch; each source runs its own range, docs/lmc.md)"},
    {1, 4000, "kHz"}, 30};
inline constexpr Quantity kPulseWidth{
    {"--pulse-width", "pulse_width_ns", "MOPA pulse width (0: the source's default; LMC --source mopa)"},
    {0, 1e6, "ns"}, 0};
inline constexpr Count kPasses{
    {"--passes", "passes",
     "times each object is marked: after a pass the mirrors jump, laser off, back to where the pass began "
     "marking and its commands run again"},
    {1, 100}, 1};

// The pen settings only one corner strategy or the look-ahead planner reads
// (marker/plan/plan_delays.cpp, plan_blanking.cpp, speed_plan.cpp). Given to a pen that does not
// use them they would be accepted and change nothing: the user who set a polygon delay on a
// blanking pen believes the corners got it. Both the command line and job files refuse them
// through pen_setting_unread().
inline constexpr SettingRef kDelaysPenSettings[] = {&kJumpDelay, &kJumpSettle, &kMarkDelay, &kPolygonDelay};
inline constexpr SettingRef kBlankingPenSettings[] = {&kBlankAngle, &kRunIn,  &kMinRunIn,
                                                      &kRunOut,     &kSettle, &kJoinSpeed};
inline constexpr SettingRef kLookaheadPenSettings[] = {&kAccel,      &kJumpAccel,        &kCurveAccel, &kAccelLimit,
                                                       &kJunctionDv, &kLaserSwitchSpeed, &kMinLitSpeed,
                                                       &kShaperHz,   &kShaperZeta,       &kShaper};

// Why a pen with this corner strategy ("blanking", "delays", "none") and planner (look-ahead or
// feed-forward on, or off) never reads `s`: "only a pen with corner delays reads it (this pen's
// corner is blanking)"; nullopt when it does.
std::optional<std::string> pen_setting_unread(const SettingRef& s, std::string_view corner, bool lookahead);

inline constexpr SettingRef kPenSettingList[] = {
    &kCorner,      &kMarkSpeed,      &kJumpSpeed,   &kTick,       &kHeadProfile, &kLookahead,   &kFeedForward,
    &kLaserOnDelay, &kLaserOffDelay, &kJumpDelay,   &kJumpSettle, &kMarkDelay,   &kPolygonDelay, &kBlankAngle,
    &kRunIn,       &kMinRunIn,       &kRunOut,      &kSettle,     &kJoinSpeed,   &kTrackingError, &kAccel,
    &kJumpAccel,   &kCurveAccel,     &kAccelLimit,  &kJunctionDv, &kLaserSwitchSpeed, &kMinLitSpeed, &kFfLag,
    &kFfInertia,   &kShaperHz,       &kShaperZeta,  &kShaper,     &kPower,          &kFrequency,   &kPulseWidth, &kLaserSource, &kPasses};
inline constexpr SettingTable kPenSettings{"pen", "Pen", "pens.NAME", kPenSettingList};

}  // namespace mark
