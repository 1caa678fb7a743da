#pragma once
// The parts `marker serve` marks: the job file on one open device with the station's serial
// store, through PartRunner (allocate → mark → record), the same path as `marker mark --job`.
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "marker/cli/device_factory.hpp"
#include "marker/cli/mark_job.hpp"
#include "marker/production/part_run.hpp"
#include "marker/station/station.hpp"

namespace mark::cli {

class JobSource : public PartSource {
 public:
  // Opens the store (the station started: journal replayed, open rows closed), the job, its
  // fonts and the device. Throws InputError as `marker mark --job` does.
  explicit JobSource(MarkJobArgs args);
  ~JobSource() override;

  PartResult mark_next(const StopFlag& stop) override;
  void abort_device() noexcept override;
  void reset_device() override;
  void set_variable(const std::string& name, const std::string& value) override;
  std::vector<ObjectText> preview(std::map<std::string, std::int64_t>* serials) override;
  // The next part's picture, as `marker job check --preview` draws it (part_preview.hpp).
  std::string preview_png() override;
  std::optional<std::int64_t> next_serial(const std::string& counter) override;
  void load(const std::string& job) override;
  std::string job() const override { return args_.job; }
  // The device the station marks on (open for the station's life): board I/O reaches its ports.
  Device& device() { return *opened_.device; }
  // Through a read-only open of the store of its own (a snapshot, as `marker log`), opened at the
  // first read: the station's connection stays the marking thread's alone.
  void read_log(const AuditFilter& filter, const std::function<bool(const AuditRow&)>& row) override;

 private:
  struct Loaded;  // a job file with its fonts, variables and runner
  std::unique_ptr<Loaded> open_job(const std::string& path, const std::map<std::string, std::string>& sets);

  MarkJobArgs args_;
  std::unique_ptr<SerialStore> store_;
  OpenedDevice opened_;
  std::string device_spec_;
  std::unique_ptr<Loaded> loaded_;
  PartOptions options_;
  std::mutex log_mutex_;  // the log reader is shared by every HTTP request
  std::unique_ptr<SerialStore> log_store_;
};

}  // namespace mark::cli
