// The station's state machine and command lines against a part source the test controls:
// a part that waits until the test lets it end, so the states in between can be seen.
#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <mutex>

#include "base/error.hpp"
#include "marker/station/station.hpp"
#include "marker/station/station_commands.hpp"

namespace mark {
namespace {

class HeldSource : public PartSource {
 public:
  PartResult mark_next(const StopFlag& stop) override {
    std::unique_lock lock(m_);
    if (refuse_next) { refuse_next = false; throw InputError("objects[0]: no glyph for 'é'"); }
    started_ = true;
    cv_.notify_all();
    cv_.wait(lock, [&] { return released_ || stop.requested(); });
    released_ = false;
    started_ = false;
    PartResult p;
    p.mark_id = ++ids_;
    p.serials["SN"] = next_++;
    p.texts.push_back({"sn", "SN " + std::to_string(p.serials["SN"]) + " " + lot_, true});
    p.outcome = stop.requested() ? JobOutcome::aborted : fail_next ? JobOutcome::failed : JobOutcome::done;
    if (p.outcome == JobOutcome::failed) p.message = "galvo X position error";
    fail_next = false;
    p.recorded.stored = true;
    return p;
  }
  void abort_device() noexcept override { ++aborts; }
  void reset_device() override { ++resets; }
  void set_variable(const std::string& name, const std::string& value) override {
    if (name != "lot") throw InputError("SET " + name + ": no template uses {var:" + name + "}");
    lot_ = value;
  }
  std::vector<ObjectText> preview(std::map<std::string, std::int64_t>* serials) override {
    (*serials)["SN"] = next_;
    return {{"sn", "SN " + std::to_string(next_) + " " + lot_, true}};
  }
  std::optional<std::int64_t> next_serial(const std::string& counter) override {
    if (counter != "SN") throw InputError("SERIAL " + counter + ": the job uses no counter of that name");
    return next_;
  }
  void load(const std::string& job) override { job_ = job; }
  std::string job() const override { return job_; }

  void wait_started() {
    std::unique_lock lock(m_);
    cv_.wait(lock, [&] { return started_; });
  }
  void release() {
    std::lock_guard lock(m_);
    released_ = true;
    cv_.notify_all();
  }
  void wake() { cv_.notify_all(); }  // a stop request is seen at the next wake

  std::atomic<int> aborts{0}, resets{0};
  bool refuse_next = false, fail_next = false;

 private:
  std::mutex m_;
  std::condition_variable cv_;
  bool started_ = false, released_ = false;
  std::int64_t ids_ = 0, next_ = 1000;
  std::string lot_ = "A1", job_ = "plate.json";
};

TEST(Station, MarkRepliesWithTextSerialAndOutcome) {
  HeldSource src;
  Station st(src);
  std::thread t([&] { src.wait_started(); src.release(); });
  EXPECT_EQ(station_command(st, "MARK"), "OK id=1 outcome=done SN=1000 text=\"SN 1000 A1\" mark_time_s=0.000000");
  t.join();
  EXPECT_EQ(station_command(st, "SERIAL SN"), "OK SN=1001");
  EXPECT_EQ(station_command(st, "STATUS"), "OK state=idle job=plate.json parts=1 done=1 last_id=1 last_outcome=done");
}

TEST(Station, TriggerWhileMarkingIsBusyNotQueued) {
  HeldSource src;
  Station st(src);
  EXPECT_EQ(station_command(st, "mark async"), "OK started");
  src.wait_started();
  EXPECT_EQ(st.status().state, StationState::marking);
  EXPECT_EQ(station_command(st, "MARK").substr(0, 8), "ERR busy");
  EXPECT_EQ(station_command(st, "MARK ASYNC").substr(0, 8), "ERR busy");
  EXPECT_EQ(station_command(st, "SET lot B2").substr(0, 8), "ERR busy");
  EXPECT_EQ(station_command(st, "STATUS").substr(0, 19), "OK state=marking jo");
  src.release();
  st.wait_idle();
  // One part ran: the refused triggers consumed nothing.
  EXPECT_EQ(st.status().parts, 1u);
  EXPECT_EQ(station_command(st, "SERIAL SN"), "OK SN=1001");
}

TEST(Station, AbortMidMarkTurnsLaserOffAndPartIsAborted) {
  HeldSource src;
  Station st(src);
  ASSERT_EQ(station_command(st, "MARK ASYNC"), "OK started");
  src.wait_started();
  EXPECT_EQ(station_command(st, "ABORT"), "OK laser_off state_was=marking");
  src.wake();
  st.wait_idle();
  EXPECT_EQ(src.aborts.load(), 1);
  const StationStatus s = st.status();
  EXPECT_EQ(s.state, StationState::idle);  // an aborted part is not a fault
  ASSERT_TRUE(s.last);
  EXPECT_EQ(s.last->outcome, JobOutcome::aborted);
  EXPECT_EQ(s.outcomes.at("aborted"), 1u);
  // The next mark runs again (the stop request is cleared at its start).
  std::thread t([&] { src.wait_started(); src.release(); });
  EXPECT_EQ(station_command(st, "MARK").substr(0, 27), "OK id=2 outcome=done SN=100");
  t.join();
}

TEST(Station, AbortInEveryStateTurnsLaserOff) {
  HeldSource src;
  Station st(src);
  EXPECT_EQ(station_command(st, "ABORT"), "OK laser_off state_was=idle");
  EXPECT_EQ(station_command(st, "PAUSE"), "OK state=paused");
  EXPECT_EQ(station_command(st, "ABORT"), "OK laser_off state_was=paused");
  EXPECT_EQ(src.aborts.load(), 2);
  EXPECT_EQ(st.status().state, StationState::paused);
}

TEST(Station, FailedPartNeedsReset) {
  HeldSource src;
  Station st(src);
  src.fail_next = true;
  std::thread t([&] { src.wait_started(); src.release(); });
  const std::string r = station_command(st, "MARK");
  t.join();
  EXPECT_EQ(r.substr(0, 33), "ERR failed id=1 outcome=failed SN");
  EXPECT_NE(r.find("message=\"galvo X position error\""), std::string::npos) << r;
  EXPECT_EQ(st.status().state, StationState::error);
  EXPECT_EQ(station_command(st, "MARK").substr(0, 9), "ERR error");
  EXPECT_EQ(station_command(st, "RESUME").substr(0, 9), "ERR error");
  EXPECT_EQ(station_command(st, "RESET"), "OK state=idle");
  EXPECT_EQ(src.resets.load(), 1);
}

TEST(Station, PausedRefusesTriggers) {
  HeldSource src;
  Station st(src);
  EXPECT_EQ(station_command(st, "PAUSE"), "OK state=paused");
  EXPECT_EQ(station_command(st, "MARK").substr(0, 10), "ERR paused");
  EXPECT_EQ(station_command(st, "RESUME"), "OK state=idle");
  EXPECT_EQ(st.status().parts, 0u);
}

TEST(Station, RefusedPartConsumesNothingAndStaysIdle) {
  HeldSource src;
  Station st(src);
  src.refuse_next = true;
  EXPECT_EQ(station_command(st, "MARK"), "ERR refused objects[0]: no glyph for 'é'");
  EXPECT_EQ(st.status().state, StationState::idle);
  EXPECT_EQ(st.status().parts, 0u);
  EXPECT_EQ(station_command(st, "SERIAL SN"), "OK SN=1000");
}

TEST(Station, SetPreviewLoadAndBadLines) {
  HeldSource src;
  Station st(src);
  EXPECT_EQ(station_command(st, "SET lot B 7"), "OK lot=\"B 7\"");
  EXPECT_EQ(station_command(st, "PREVIEW"), "OK SN=1000 text=\"SN 1000 B 7\"");
  EXPECT_EQ(station_command(st, "SET size 3"), "ERR refused SET size: no template uses {var:size}");
  EXPECT_EQ(station_command(st, "SET lot"), "ERR syntax SET takes a variable name and a value: SET <var> <value>");
  EXPECT_EQ(station_command(st, "LOAD other.json\r"), "OK job=other.json");
  EXPECT_EQ(station_command(st, "SERIAL XX"), "ERR notfound SERIAL XX: the job uses no counter of that name");
  EXPECT_EQ(station_command(st, "STATUS now"), "ERR syntax STATUS takes no argument (got \"now\")");
  EXPECT_EQ(station_command(st, "FIRE").substr(0, 29), "ERR unknown no command \"FIRE\"");
  EXPECT_EQ(station_command(st, std::string(5000, 'A')).substr(0, 11), "ERR toolong");
  EXPECT_EQ(station_command(st, "MARK\tX").substr(0, 10), "ERR syntax");
  EXPECT_EQ(st.status().parts, 0u);
}

TEST(Station, ReplyValueQuotes) {
  EXPECT_EQ(reply_value("A17"), "A17");
  EXPECT_EQ(reply_value(""), "\"\"");
  EXPECT_EQ(reply_value("a \"b\"\n\\"), "\"a \\\"b\\\"\\n\\\\\"");
}

}  // namespace
}  // namespace mark
