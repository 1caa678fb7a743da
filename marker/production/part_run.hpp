#pragma once
// Marking the parts of a production job one after the other, on one device, with one serial
// store. A part's life:
//
//   1. allocate — one store transaction renders every object's text from the counter values
//      the part consumes, lays it out and plans it (only the characters that changed since the
//      last part: JobCompiler), makes every refusal (a glyph missing, the field left), and
//      commits the values with the audit row: durably, before the first sample reaches the
//      device. A refusal rolls the transaction back: nothing consumed, nothing logged.
//   2. mark — every object in file order with its own pen (motion and laser settings, passes),
//      each as one device job (run_compiled_job). The first object that does not end `done`
//      ends the part: the objects after it are not started.
//   3. verify — a part marked to its end is good only when every code read back decodes to its
//      data (part_verdict.hpp); else it is rejected, naming the object and why.
//   4. record — the part's outcome (done only if every object is done and the part verified;
//      rejected; else the aborted or failed object's outcome), with the device's figures and,
//      when the options carry an evaluator (the simulated scanner's: marker/job/sim_evaluator.hpp),
//      each object's quality, pulse figures and codes read back. An aborted, failed or rejected
//      part's numbers are void for good.
//
// A re-mark marks the texts of an earlier row again, in a row of its own linked to it, and
// consumes no number.
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "marker/job/job.hpp"
#include "marker/job/job_compiler.hpp"
#include "marker/production/part_texts.hpp"
#include "marker/store/serial_store.hpp"

namespace mark {

enum class PartPhase { allocating, marking, recording, finished };

struct ObjectRun {
  std::string name;
  std::string pen;
  std::string text;
  bool started = false;  // false: an earlier object ended the part
  JobResult result;      // when started (quality etc. from the options' evaluator)
};

// Where a part's start goes, on the steady clock (the drain's DrainStats::first_write is on it
// too): trigger-to-first-sample broken down (bench/prog_station_tcp.cpp).
struct PartTimes {
  std::chrono::steady_clock::time_point started{};    // mark_next called (a re-mark leaves these unset)
  std::chrono::steady_clock::time_point committed{};  // the allocation committed durably
  double compile_s = 0;  // inside the allocation: rendering, layout, planning (and any require check)
};

struct PartResult {
  std::int64_t mark_id = 0;
  std::optional<std::int64_t> remark_of;
  std::vector<ObjectText> texts;                 // every object's rendered text
  std::map<std::string, std::int64_t> serials;   // counter values consumed (a re-mark: the original's)
  std::optional<std::int64_t> data_row;          // the data-list row taken (1: the first after the header)
  std::string note;                              // what the store noticed (a clock stepped back)
  JobOutcome outcome = JobOutcome::done;  // the device's: how far the marking got
  // Marked to its end but not verified (a code not read back): scrap. The message says which
  // object failed and why; stopped_object is its index.
  bool rejected = false;
  std::string message;  // aborted / failed / rejected: which object, where, and why
  std::optional<std::size_t> stopped_object;     // its index
  std::vector<ObjectRun> objects;
  std::string device;                            // describe().name
  double mark_time_s = 0;                        // device time over the objects
  std::uint64_t samples = 0;
  // With an evaluator: the worst figure of any object (class: the lowest object's), and the
  // widest pulse spacing (with its overlap).
  std::optional<Quality> quality;
  std::optional<PulseFigures> pulses;

  // How the outcome was recorded: in the store, or kept in the station's outcome journal until
  // the store takes it; record_error says why neither took it (the row is then closed aborted
  // at the station's next start).
  OutcomeWrite recorded;
  std::string record_error;
  PartTimes times;

  std::string text() const;  // the texts joined by new lines
  bool good() const { return outcome == JobOutcome::done && !rejected; }
  // As the audit log names it: done, aborted, failed or rejected.
  std::string_view outcome_name() const;
};

struct PartOptions {
  JobOptions job;  // for every object's device job (stop flag, injection, virtual time, evaluator)
  // Told at each step of a part with the values it consumed (so far): the kill test's probe.
  std::function<void(PartPhase, const std::map<std::string, std::int64_t>& serials)> phase;
  std::string remark_reason;  // a re-mark's reason, kept in its audit row
  bool allow_changed_job = false;  // a re-mark with a job file changed since (noted in its row)
  // Told after each object's device job with what it marked (its plan), before the next object
  // starts: where the simulated scanner's dose and trace of that object are read, since the
  // next job clears them (marker/production/part_picture.hpp).
  std::function<void(std::size_t object, const JobResult& marked)> object_marked;
};

class PartRunner {
 public:
  // The job, its fonts, the device and the store are the caller's and outlive the runner.
  // `context` is the station's (start_station has been called). Throws InputError when an
  // object's pen cannot run on the device (a sample-level device has one clock).
  PartRunner(const JobFile& job, const JobFonts& fonts, std::map<std::string, std::string> variables,
             Device& device, SerialStore& store, MarkContext context);

  // The next part: allocate, mark, record. Refusals before allocation throw InputError (nothing
  // consumed); a device that cannot start throws after the part is recorded failed.
  PartResult mark_next(SysTime now, const PartOptions& options);
  // Row `original` marked again.
  PartResult remark(std::int64_t original, SysTime now, const PartOptions& options);

  // The texts the next part would mark with these counter values: the variables, and the data
  // list's next untaken row (read-only; InputError when every row is taken). A preview's.
  std::vector<ObjectText> next_texts(SysTime now, const std::map<std::string, std::int64_t>& serials);

  // The variables of the parts from now on (a station's SET between parts); job_variables
  // checked them against the job's templates.
  void set_variables(std::map<std::string, std::string> variables) { variables_ = std::move(variables); }
  const std::map<std::string, std::string>& variables() const { return variables_; }

 private:
  // Each object planned for the device; an object with a "require" is also judged on a fresh
  // simulated scanner, and a part the simulator says falls short is refused (InputError, before
  // anything fires; inside the allocation nothing is consumed).
  std::vector<CompiledJob> compile(const std::vector<ObjectText>& texts);
  DataPick data_pick() const;  // the data list's rows from the next this run may take
  void refuse_predicted_shortfall(std::size_t object, const std::string& text, const CompiledJob& compiled,
                                  const Point& home);
  // Object `i`'s job with the part's text in it.
  JobSpec marked_spec(std::size_t i, const std::string& text) const;
  PartResult run(PartResult part, std::vector<CompiledJob> compiled, const PartOptions& options);
  // Totals, the worst quality, the widest pulse spacing and the message of a part that stopped.
  void summarise(PartResult& part) const;
  void record(PartResult& part, const PartOptions& options);  // the outcome, in the store
  Point device_position() const;

  const JobFile& job_;
  std::map<std::string, std::string> variables_;
  Device& device_;
  SerialStore& store_;
  MarkContext context_;
  std::map<std::string, CounterSpec> counters_;  // the ones the templates use
  std::vector<JobCompiler> compilers_;           // one per object, in file order
  // For an object with a "require" on a device that does not take samples: its plan for the
  // simulator's prediction (a sample-level device's own plan serves for both).
  std::vector<std::optional<JobCompiler>> predictors_;
  std::optional<DataList> data_;                 // the job's data list, if any
  std::size_t next_row_ = 0;                     // rows before it were taken (by this run or earlier)
  // Where the device's mirrors are before the next part: each object is planned from where the
  // one before it ended (its last command), the first from where the last part ended.
  Point mirrors_{0, 0};
};

}  // namespace mark
