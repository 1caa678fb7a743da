#pragma once
// The part source the station fuzz targets run against: marks at once, records what it was
// asked, and refuses what a job would refuse (a variable no template uses, an unknown counter).
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "marker/station/station.hpp"

namespace mark::fuzz {

class NullSource : public mark::PartSource {
 public:
  mark::PartResult mark_next(const mark::StopFlag&) override {
    ++asked;
    mark::PartResult p;
    p.mark_id = ++n;
    p.serials["sn"] = n;
    p.texts.push_back({"o", "SN " + std::to_string(n), true});
    p.recorded.stored = true;
    return p;
  }
  void abort_device() noexcept override { ++asked; }
  void reset_device() override { ++asked; }
  void set_variable(const std::string& name, const std::string&) override {
    ++asked;
    if (name != "lot") throw mark::InputError("no template uses {var:" + name + "}");
  }
  std::vector<mark::ObjectText> preview(std::map<std::string, std::int64_t>* s) override {
    ++asked;
    (*s)["sn"] = n + 1;
    return {{"o", "SN", true}};
  }
  std::optional<std::int64_t> next_serial(const std::string& c) override {
    ++asked;
    if (c != "sn") throw mark::InputError("no counter " + c);
    return n + 1;
  }
  void load(const std::string& job) override {
    ++asked;
    name_ = job;
  }
  std::string job() const override { return name_; }
  std::int64_t n = 0;
  int asked = 0;  // calls from the station: a command ran
  std::string name_ = "fuzz.json";
};

}  // namespace mark::fuzz
