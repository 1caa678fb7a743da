#pragma once
// One interface for every device the engine drives: the simulated scanner, a USB vector board
// (BJJCZ LMC), a point DAC, the gravure stylus head. Every device runs jobs through one
// lifecycle, the same state machine (driver/lifecycle.hpp, which each device embeds):
//
//   idle ─begin_job─► running ─end_job─► done | failed
//    ▲  │                │  └──(a fault)──► failed
//    │  └──abort()──┐    └──abort()──► aborted          (laser off now, and off until reset)
//    │              ▼
//    └──reset()── done | aborted | failed               (clears the fault)
//
// - begin_job only from idle. From running or a final state it throws DeviceStateError: the
//   job before must end and, once ended, the device must be reset (a station re-arms it).
// - end_job from running waits for the device and gives done, aborted (abort() or the host
//   halting it: the drain on a stop or an underrun) or failed (a fault). From a final state it
//   gives the same report again; from idle (no job) it throws DeviceStateError.
// - abort() from idle or running → aborted, laser off at once and for the rest of the job;
//   from a final state it changes nothing (the laser is already off, a failed job keeps its
//   fault). noexcept, never blocks for long, callable from any thread (a station calls it from
//   its network thread) and any number of times. The first ending wins: a job aborted stays
//   aborted when something fails afterwards (the failure is the stop's consequence), a job
//   failed stays failed when it is aborted afterwards.
// - reset() from a final state → idle; idle stays idle; while running it throws
//   DeviceStateError (abort the job or end it first). It may throw DeviceFaultError when the
//   device cannot be brought back (a board that was unplugged).
// - Feeding work outside a running job: write() (samples) throws DeviceStateError, so the drain
//   stops at once and halts the device; submit() (commands) after abort() sends nothing and
//   returns, so the producer's loop runs out; submit() in any other state but running throws
//   DeviceStateError. The simulated scanner alone also takes samples while idle, as a bare sink
//   (an implicit job: the emulated board's plant, verification runs).
// - Misuse of the lifecycle throws one type, DeviceStateError, naming the device, the call and
//   the state. (A job that does not fit the device — its field, its pens, its length — is not
//   misuse of the lifecycle: begin_job refuses it with the device's own error and the device
//   stays idle.)
//
// Devices take their work at one of two levels (describe().level):
// - samples: fixed-rate devices (the simulated scanner, an XY2-100 output, the gravure stylus).
//   They are a SampleDevice<T>: the line memory and the fixed-rate drain feed them T samples
//   (ringbuffer/sink.hpp), and the drain emits the sample type's safe sample (laser off, stylus
//   lifted) on underrun, abort and at the end of the job.
// - commands: vector boards (LMC, RTC class) that run their own clock. They are a
//   CommandDevice: the job hands them DeviceCommands (driver/device_command.hpp) converted from
//   the plan — jumps, marks, arcs where the board has them (chords otherwise), dwells — and the
//   pen's delays and laser settings go to the board as parameters (JobHeader::pens), so the host
//   never applies its own laser delay line or scanner delays a second time.
//
// Faults carry a category and a message; the report of a job says how far it got, so the
// caller can say what was and was not marked. Devices are re-armable: a station runs for months.
#include <cstdint>
#include <exception>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "driver/device_command.hpp"
#include "driver/device_error.hpp"
#include "driver/laser_source.hpp"
#include "driver/vec2.hpp"
#include "ringbuffer/sink.hpp"

namespace mark {

enum class DeviceLevel { samples, commands };

enum class DeviceState {
  idle,     // ready for begin_job
  running,  // between begin_job and end_job
  done,     // the job ran to its end
  aborted,  // abort() was called (cancel, Ctrl-C): laser off
  failed    // a fault stopped the job: laser off
};

enum class FaultCategory {
  transport,     // the link to the device failed (USB transfer error, unplug)
  timeout,       // the device did not answer in time
  underrun,      // the device (or the drain feeding it) ran out of samples mid-job
  out_of_field,  // a coordinate outside the device's field was refused before it was sent
  device         // the device reported a fault of its own
};

std::string_view to_string(DeviceLevel level);
std::string_view to_string(DeviceState state);
std::string_view to_string(FaultCategory category);

struct DeviceFault {
  FaultCategory category = FaultCategory::device;
  std::string message;     // one line naming the device and what happened
  // Sample-level: index of the first sample the device did not output as commanded.
  // Command-level: index of the first command of the job it did not execute.
  std::uint64_t at = 0;
};

// Thrown by devices (and by the job runner on their behalf) when a fault stops a job.
class DeviceFaultError : public DeviceError {
 public:
  explicit DeviceFaultError(DeviceFault fault)
      : DeviceError(fault.message), fault_(std::move(fault)) {}
  const DeviceFault& fault() const { return fault_; }

 private:
  DeviceFault fault_;
};

// Misuse of the lifecycle: a call the device's state does not allow (begin_job while running,
// reset while running, end_job with no job, write after the job ended). One type for every
// device; the message names the device, the call and the state.
class DeviceStateError : public DeviceError {
 public:
  DeviceStateError(std::string device, std::string call, DeviceState state, std::string_view why);
  const std::string& device() const { return device_; }
  const std::string& call() const { return call_; }
  DeviceState state() const { return state_; }

 private:
  std::string device_, call_;
  DeviceState state_;
};

// The fault an exception from a device stands for (the drain keeps the exception a device threw):
// a DeviceFaultError's own fault, any other error as category `device` at sample `at`.
DeviceFault fault_from(std::exception_ptr error, std::uint64_t at);

// What a device is and what it accepts. Field: a square centred on the origin, |x|, |y| ≤
// field_mm / 2, in the field frame (mm).
struct DeviceDescription {
  std::string name;                 // e.g. "sim SL10", "lmc 0123456789"
  DeviceLevel level = DeviceLevel::samples;
  double field_mm = 110;
  double tick_s = 10e-6;            // sample period (samples) or the board's own clock (commands)
  // Command level: whether arcs can be sent as arcs; if not, the job converts them to chords
  // within chord_tolerance_mm.
  bool arcs = false;
  double chord_tolerance_mm = 0.005;
  double max_speed_mm_s = 0;        // fastest jump or mark the device executes (0: no limit known)
  double max_dwell_s = 0;           // longest single dwell command (0: no limit)
  bool laser_settings = false;      // power / frequency / pulse width can be set per pen
  // Samples the device buffers itself beyond what the drain hands it (a DAC's FIFO); the line
  // memory's lead is sized so such a device never starves. 0 for the simulator.
  std::size_t fifo_samples = 0;
};

// A pen as a command-level device applies it: speeds, delays and laser settings. Sample-level
// devices use only `laser` (the simulator scales its dose by the power).
struct DevicePen {
  double mark_speed_mm_s = 1000;
  double jump_speed_mm_s = 5000;
  double laser_on_delay_s = 0;
  double laser_off_delay_s = 0;
  double jump_delay_s = 0;
  double mark_delay_s = 0;
  double polygon_delay_s = 0;
  LaserSettings laser;
};

struct JobHeader {
  std::string name;                   // for messages and logs
  double field_mm = 110;              // the job's field; must fit the device's
  std::vector<DevicePen> pens;        // at least one; DeviceCommand::pen indexes it
  // Sample level: how many samples the job will hand over (0: unknown). Used to size buffers
  // before the first sample so the drain thread never allocates, and for progress.
  std::uint64_t expected_samples = 0;
  // Where the lit beam will go (polylines in mm, as planned): a simulator sizes its dose
  // raster from it before the first sample. Other devices ignore it.
  std::vector<std::vector<Vec2>> lit_paths;
};

// The device's own figures for a job, for `--json` and the audit log. Keys name their units
// (`commands`, `packets`, `device_time_s`).
using DeviceFigures = std::vector<std::pair<std::string, double>>;

struct DeviceReport {
  DeviceState outcome = DeviceState::done;  // done, aborted or failed
  std::optional<DeviceFault> fault;         // set when failed
  std::uint64_t samples_out = 0;            // sample level: samples output
  std::uint64_t commands_done = 0;          // command level: commands executed
  double device_time_s = 0;                 // time the device spent on the job
  DeviceFigures figures;
};

struct DeviceStatus {
  DeviceState state = DeviceState::idle;
  Vec2 position{0, 0};           // last known commanded (or measured) position, mm
  bool laser_on = false;
  std::optional<DeviceFault> fault;
  std::uint64_t progress = 0;    // samples output or commands executed in this job
};

class CommandDevice;
template <class T>
class SampleDevice;

// The transitions and what each call may throw are the lifecycle at the top of this file.
class Device {
 public:
  virtual ~Device() = default;

  virtual DeviceDescription describe() const = 0;
  // idle → running. Throws DeviceStateError in any other state; DeviceFaultError (the device
  // cannot start) or the device's own error for a header that does not fit it (then it stays
  // idle).
  virtual void begin_job(const JobHeader& header) = 0;
  // Waits until the device has finished everything it was given (or stopped); running → done,
  // or the state abort()/a fault left. Never throws for a fault: the report carries it. Throws
  // DeviceStateError when no job was begun (idle).
  virtual DeviceReport end_job() = 0;
  // Any state, any thread, any time: laser (stylus) off now; the rest of the job is not
  // executed. Idempotent. Must not throw or block for long (a USB stop is sent, not awaited).
  virtual void abort() noexcept = 0;
  virtual DeviceStatus status() const = 0;
  // done / aborted / failed → idle (clears the fault); idle stays idle; DeviceStateError while
  // running. Throws DeviceFaultError if the device cannot be brought back (e.g. unplugged).
  virtual void reset() = 0;

  // What the job runner feeds: samples of type T (null if the device takes another kind or
  // commands), or device commands (null for a sample-level device).
  template <class T>
  SampleDevice<T>* as_sample_device();
  virtual CommandDevice* as_command_device() { return nullptr; }
};

// A fixed-rate device: the drain writes T samples to it (Sink<T>::write on the drain thread,
// Sink<T>::halt on a fault or abort). The drain, not the device, emits safe samples.
template <class T>
class SampleDevice : public Device, public Sink<T> {};

template <class T>
SampleDevice<T>* Device::as_sample_device() {
  // The one place the sample type is asked for: the runner dispatches on the answer.
  return dynamic_cast<SampleDevice<T>*>(this);
}

// A vector board: the job submits device commands in order, from the producer thread, while
// the board executes them on its own clock. submit() may block for flow control; it throws
// DeviceFaultError on a fault (and leaves the laser off), after which only abort / end_job /
// status / reset are meaningful.
class CommandDevice : public Device {
 public:
  virtual void submit(std::span<const DeviceCommand> commands) = 0;
  CommandDevice* as_command_device() override { return this; }
};

}  // namespace mark
