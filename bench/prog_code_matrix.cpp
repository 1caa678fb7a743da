// Reader agreement over the code matrix, on marked codes: every Data Matrix size (10 × 10 …
// 144 × 144 and the six rectangles), QR versions 1 … 40 and Code 128 / GS1-128 at 0°, 33° and
// 90°, each marked on the simulated scanner (square modules, the default pen on SL10), pictured
// by the default reader's camera and read by ZXing, libdmtx and ZBar. One line per code: which
// readers decoded it exactly, the verdict and, for a 2-D code, its ISO/IEC TR 29158 grade.
// The unit tests read pictures of codes as meant at every size (reader_agreement_test.cpp);
// this is the full sweep through the laser, too slow for the suite.
//
//   code_matrix [--module MM] [--qr-step N] [--json]
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "marker/codes/iso_grade.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/simulate_plan.hpp"

namespace {

using namespace mark;

struct Case {
  std::string name;
  CodeObject code;
};

nlohmann::json run(const Case& c, const HeadModel& head) {
  JobSpec job;
  job.codes.push_back(c.code);
  job.head = head;
  job.pen = pen_for_head(head, CornerStrategy::blanking, 1000);
  nlohmann::json out = {{"code", c.name}};
  const auto t = std::chrono::steady_clock::now();
  try {
    const SimulatedJob r = simulate_job(job);
    const CodeVerification& v = r.codes.front();
    for (const ReaderOutcome& o : v.readers)
      out["readers"][o.reader] = !o.supported ? "n/a" : o.data_match ? "reads" : o.decoded ? "MISREAD" : "no read";
    out["pass"] = v.data_match;
    out["decided_by"] = v.decided_by;
    out["modules_wrong"] = v.modules_wrong;
    out["grade"] = v.grade ? std::string(1, grade_letter(v.grade->overall)) : "-";
  } catch (const std::exception& e) {
    out["error"] = e.what();
  }
  out["cpu_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"reader agreement over every Data Matrix size, QR version and linear angle, marked on the simulator"};
  double module_mm = 0.25;
  int qr_step = 1;
  bool json = false;
  app.add_option("--module", module_mm, "module size, mm")->capture_default_str();
  app.add_option("--qr-step", qr_step, "every N-th QR version")->capture_default_str()->check(CLI::Range(1, 40));
  app.add_flag("--json", json, "print one JSON array");
  CLI11_PARSE(app, argc, argv);
  const HeadModel head = *find_head("SL10");

  std::vector<Case> cases;
  for (const MatrixSize& s : datamatrix_sizes()) {
    Case c{"datamatrix " + std::to_string(s.rows) + "x" + std::to_string(s.cols), {}};
    c.code.spec.data = "SN 2026-000123";
    c.code.spec.matrix_rows = s.rows;
    c.code.spec.matrix_cols = s.cols;
    if (s.rows * s.cols < 200) c.code.spec.data = "SN42";
    c.code.layout.module_mm = module_mm;
    cases.push_back(c);
  }
  for (int version = 1; version <= 40; version += qr_step) {
    Case c{"qr version " + std::to_string(version), {}};
    c.code.spec.symbology = Symbology::qr;
    c.code.spec.data = "SN 2026-000123";
    c.code.spec.qr_version = version;
    c.code.layout.module_mm = module_mm;
    cases.push_back(c);
  }
  for (const Symbology s : {Symbology::code128, Symbology::gs1_128})
    for (const double angle : {0.0, 33.0, 90.0}) {
      Case c{std::string(to_string(s)) + " at " + std::to_string(static_cast<int>(angle)) + " deg", {}};
      c.code.spec.symbology = s;
      c.code.spec.data = is_gs1(s) ? "(01)09506000134352(17)261231(10)LOT42" : "SN-2026-000123";
      c.code.layout.module_mm = module_mm;
      c.code.layout.angle_deg = angle;
      cases.push_back(c);
    }

  nlohmann::json all = nlohmann::json::array();
  for (const Case& c : cases) {
    const nlohmann::json r = run(c, head);
    all.push_back(r);
    if (json) continue;
    if (r.contains("error")) {
      std::printf("%-24s error: %s\n", c.name.c_str(), r["error"].get<std::string>().c_str());
    } else {
      std::printf("%-24s zxing %-8s libdmtx %-8s zbar %-8s %s (%s), grade %s, %zu modules wrong, %.1f s\n",
                  c.name.c_str(), r["readers"]["zxing"].get<std::string>().c_str(),
                  r["readers"]["libdmtx"].get<std::string>().c_str(), r["readers"]["zbar"].get<std::string>().c_str(),
                  r["pass"].get<bool>() ? "PASS" : "FAIL", r["decided_by"].get<std::string>().c_str(),
                  r["grade"].get<std::string>().c_str(), r["modules_wrong"].get<std::size_t>(), r["cpu_s"].get<double>());
    }
    std::fflush(stdout);
  }
  if (json) std::cout << all.dump(2) << "\n";
  return 0;
}
