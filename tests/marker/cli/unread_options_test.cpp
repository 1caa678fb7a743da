// Options and job-file keys that nothing in the run reads are refused in one line naming what
// would make them apply, never accepted and ignored (issue 19: "options that do not apply are
// accepted silently"). The command line and a job file's pen refuse a pen setting for the same
// reason, word for word after the place they name.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "base/error.hpp"
#include "driver/sim/head_model.hpp"
#include "marker/cli/pen_options.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/limits/pen_settings.hpp"
#include "marker/production/job_file.hpp"
#include "tests/marker/cli_runner.hpp"

namespace mark {
namespace {

// The refusal of `marker mark A …` in virtual time, without "marker: " and the newline; "" when it ran.
std::string mark_error(std::vector<std::string> args) {
  args.insert(args.begin(), {"mark", "A"});
  args.push_back("--virtual-time");
  const test::CliResult r = test::run_cli(args);
  if (r.code == 0) return "";
  std::string err = r.err.substr(r.err.rfind("marker: ") + 8);
  while (!err.empty() && err.back() == '\n') err.pop_back();
  return err;
}

std::string pen_job_error(const std::string& corner, const std::string& key, const std::string& value) {
  const std::string text = R"({"format": "marker-job/1", "head": {"model": "SL10"}, "pens": {"p": {"corner": ")" +
                           corner + R"(", ")" + key + R"(": )" + value +
                           R"(}}, "objects": [{"name": "t", "template": "A"}]})";
  try {
    parse_job(text, "j.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A value inside every pen setting's range, for the setting.
std::string value_for(const SettingRef& s) {
  if (const auto* c = std::get_if<const Choice*>(&s)) return (*c)->names().front();
  const Quantity* q = std::get<const Quantity*>(s);
  if (q == &kBlankAngle) return "10";
  return q->bounds.min <= 0.5 && 0.5 <= q->bounds.max ? "0.5" : std::to_string(static_cast<int>(q->bounds.min));
}

TEST(UnreadOptions, ACornerSettingOnAnotherCornerIsRefusedAlikeByCommandLineAndJobFile) {
  int checked = 0;
  for (const auto& [list, reader, other] :
       {std::tuple{std::span<const SettingRef>(kDelaysPenSettings), "delays", "blanking"},
        std::tuple{std::span<const SettingRef>(kBlankingPenSettings), "blanking", "delays"}}) {
    for (const SettingRef& s : list) {
      const SettingName& n = name_of(s);
      SCOPED_TRACE(std::string(n.flag));
      const std::string why = std::string("only a pen with corner ") + reader + " reads it (this pen's corner is " +
                              other + ")";
      EXPECT_EQ(mark_error({"--corner", other, std::string(n.flag), value_for(s)}),
                std::string(n.flag) + " does not apply: " + why);
      EXPECT_EQ(pen_job_error(other, std::string(n.key), value_for(s)), "j.json: pens.p." + std::string(n.key) + ": " + why);
      // The pen that reads it takes it, both ways.
      EXPECT_EQ(mark_error({"--corner", reader, std::string(n.flag), value_for(s)}), "");
      EXPECT_EQ(pen_job_error(reader, std::string(n.key), value_for(s)), "");
      // A pen with no corner strategy reads neither.
      EXPECT_NE(pen_job_error("none", std::string(n.key), value_for(s)), "");
      ++checked;
    }
  }
  EXPECT_EQ(checked, 10);
}

TEST(UnreadOptions, LookAheadSettingsNeedTheLookAheadPlanner) {
  for (const SettingRef& s : kLookaheadPenSettings) {
    const std::string flag(name_of(s).flag);
    SCOPED_TRACE(flag);
    EXPECT_EQ(mark_error({flag, value_for(s)}),
              flag + " does not apply: only the look-ahead planner reads it (give --lookahead or --feed-forward)");
  }
  EXPECT_EQ(mark_error({"--lookahead", "--junction-dv", "50"}), "");
  // Feed-forward plans the speeds too, and so does a model given by hand.
  EXPECT_EQ(mark_error({"--feed-forward", "--junction-dv", "50"}), "");
  EXPECT_EQ(mark_error({"--ff-lag-us", "100", "--junction-dv", "50"}), "");
}

TEST(UnreadOptions, FillCodeHeadAndBoardOptionsWithoutWhatReadsThem) {
  EXPECT_EQ(mark_error({"--hatch-spacing", "0.05"}),
            "--hatch-spacing does not apply: only a hatch fill reads it (give --fill hatch, or --code)");
  EXPECT_EQ(mark_error({"--contour-passes", "2"}),
            "--contour-passes does not apply: only a hatch fill reads it (give --fill hatch, or --code)");
  EXPECT_EQ(mark_error({"--fill-rule", "evenodd"}),
            "--fill-rule does not apply: only a filled text reads it (give --fill hatch)");
  EXPECT_EQ(mark_error({"--code-module", "0.3"}),
            "--code-module does not apply: only a code reads it (give --code SYMBOLOGY:DATA)");
  EXPECT_EQ(mark_error({"--code", "datamatrix:A1", "--code-dot-size", "0.8"}),
            "--code-dot-size does not apply: only dot-style modules read it (give --code-style dot)");
  EXPECT_EQ(mark_error({"--head-zeta", "0.7"}),
            "--head-zeta does not apply: head SL10 is first order (give --head-model second)");
  EXPECT_EQ(mark_error({"--head-model", "second", "--head-zeta", "0.7"}), "");
  // A correction file the simulated scanner would never load (it need not even exist).
  EXPECT_EQ(mark_error({"--cor", "/nonexistent.cor"}),
            "--cor does not apply: only an LMC board reads it (give --device lmc…)");
  EXPECT_EQ(mark_error({"--no-swap-xy"}), "--no-swap-xy does not apply: only an LMC board reads it (give --device lmc…)");
  EXPECT_EQ(mark_error({"--corner", "none", "--tracking-error-us", "100"}),
            "--tracking-error-us does not apply: only a pen with corner blanking or delays reads it (this pen's "
            "corner is none)");
  const test::CliResult code = test::run_cli({"code", "qr", "A1", "--dot", "circle"});
  EXPECT_NE(code.code, 0);
  EXPECT_NE(code.err.find("--dot does not apply: only dot-style modules read it (give --style dot)"), std::string::npos)
      << code.err;
}

// cps prints a pen as options (pen_args_string) for `marker mark` to reproduce it: it must name
// only options that pen reads, or its own output would be refused.
TEST(UnreadOptions, APensOptionsAsPrintedAreAllRead) {
  for (CornerStrategy corner : {CornerStrategy::blanking, CornerStrategy::delays, CornerStrategy::none}) {
    const Pen pen = pen_for_head(head_sl10(), corner, 1000, 10e-6);
    const std::string args = cli::pen_args_string(pen);
    SCOPED_TRACE(args);
    std::vector<std::string> words;
    for (std::size_t at = 0; at < args.size();) {
      const std::size_t end = std::min(args.find(' ', at), args.size());
      if (end > at) words.push_back(args.substr(at, end - at));
      at = end + 1;
    }
    EXPECT_EQ(mark_error(words), "");
  }
}

}  // namespace
}  // namespace mark
