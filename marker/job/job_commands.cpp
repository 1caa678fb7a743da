// A job on a command-level device (a vector board): the plan becomes device commands, checked
// against the device's field before begin_job, submitted in chunks as they are converted; a
// watcher turns a stop request into device.abort() whether the board is taking commands or
// finishing them.
#include <algorithm>
#include <limits>

#include "base/error.hpp"
#include "marker/job/board_watcher.hpp"
#include "marker/job/device_program.hpp"
#include "marker/job/job_run.hpp"
#include "marker/job/program_stream.hpp"

namespace mark {

void run_commands(const JobSpec& spec, const JobOptions& options, CommandDevice& device,
                  JobResult& result) {
  if (options.inject.kind == Injection::Kind::underrun)
    throw InputError("--inject underrun applies to sample-level devices; " +
                     device.describe().name + " runs its own clock");
  const DeviceDescription desc = device.describe();
  // Converted while it is submitted (a worker thread, for big plans that lie in the field); a
  // plan that may leave the field is converted whole here, and a point outside it throws
  // before begin_job.
  ProgramStream stream(result.job.plan, spec.laser, desc);
  JobHeader header = job_header(spec, result.job, desc);
  header.pens.front() = stream.pen();
  device.begin_job(header);

  BoardStopWatcher watcher(device, options.stop);

  const std::uint64_t abort_at = options.inject.kind == Injection::Kind::abort
                                     ? options.inject.at
                                     : std::numeric_limits<std::uint64_t>::max();
  constexpr std::size_t kChunk = 256;
  std::optional<DeviceFault> fault;
  for (std::size_t i = 0;;) {
    std::span<const DeviceCommand> chunk;
    try {
      // Up to the injected abort, and at least one command to know whether there are more.
      const std::uint64_t before_abort = abort_at > i ? abort_at - i : 0;
      chunk = stream.next(i, std::clamp<std::uint64_t>(before_abort, 1, kChunk));
    } catch (const DeviceFaultError& e) {
      // The worker met a point it could not convert (the plan's reach said it could not): the
      // board has part of the job, so it is stopped like on any fault.
      watcher.stop_board();
      fault = e.fault();
      break;
    } catch (...) {
      watcher.stop_board();  // whatever went wrong, the board is not left running with the laser
      throw;
    }
    if (chunk.empty()) break;
    if (watcher.stop_requested() || i >= abort_at) {
      watcher.stop_board();
      break;
    }
    try {
      device.submit(chunk);
    } catch (const DeviceFaultError& e) {
      fault = e.fault();
      break;
    } catch (...) {
      watcher.stop_board();
      throw;
    }
    i += chunk.size();
  }
  result.device = device.end_job();
  watcher.finish();

  const DeviceProgram program = stream.finish();
  result.commands = program.commands.size();
  result.mark_time_s = result.device.device_time_s;
  if (!result.device.fault && fault) result.device.fault = fault;
  result.outcome = result.device.fault ? JobOutcome::failed : job_outcome(result.device.outcome);
  result.fault = result.device.fault;
  if (result.outcome != JobOutcome::done) {
    result.stopped_at = result.device.commands_done;
    result.ink_marked = ink_fraction(program, result.device.commands_done);
  }
  if (const double latency = watcher.stop_latency_us(); latency >= 0) result.stop_latency_us = latency;
}

}  // namespace mark
