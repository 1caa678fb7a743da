#include "rs274.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

namespace mark::test {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The numbers between the parentheses of "NAME(a, b, c)".
std::vector<double> args_of(const std::string& line, std::size_t open) {
  std::vector<double> v;
  const std::size_t close = line.find(')', open);
  std::stringstream ss(line.substr(open + 1, close - open - 1));
  std::string tok;
  while (std::getline(ss, tok, ',')) v.push_back(std::strtod(tok.c_str(), nullptr));
  return v;
}

std::vector<CanonMove> parse(const std::string& text) {
  std::vector<CanonMove> moves;
  Eigen::Vector3d pos(0, 0, 0), g5x(0, 0, 0), g92(0, 0, 0);
  double to_mm = 1;
  std::stringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t n = line.find("N..... ");
    if (n == std::string::npos) continue;
    const std::string call = line.substr(n + 7);
    const std::size_t open = call.find('(');
    if (open == std::string::npos) continue;
    const std::string name = call.substr(0, open);
    if (name == "USE_LENGTH_UNITS") {
      to_mm = call.find("INCHES") != std::string::npos ? 25.4 : 1.0;
      continue;
    }
    if (name == "COMMENT" || name == "MESSAGE") continue;
    const std::vector<double> a = args_of(call, open);
    if (name == "SET_G5X_OFFSET") {
      g5x = Eigen::Vector3d(a[1], a[2], a[3]) * to_mm;
    } else if (name == "SET_G92_OFFSET") {
      g92 = Eigen::Vector3d(a[0], a[1], a[2]) * to_mm;
    } else if (name == "SET_XY_ROTATION") {
      EXPECT_EQ(a[0], 0.0) << "the programs never rotate the coordinate system";
    } else if (name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED") {
      CanonMove m;
      m.kind = name == "STRAIGHT_FEED" ? CanonMove::feed : CanonMove::traverse;
      m.start = pos;
      m.end = Eigen::Vector3d(a[0], a[1], a[2]) * to_mm + g5x + g92;
      pos = m.end;
      moves.push_back(m);
    } else if (name == "ARC_FEED") {
      CanonMove m;
      m.kind = CanonMove::arc;
      m.start = pos;
      const Eigen::Vector3d off = g5x + g92;
      m.end = Eigen::Vector3d(a[0] * to_mm + off.x(), a[1] * to_mm + off.y(), a[5] * to_mm + off.z());
      m.center = Point(a[2] * to_mm + off.x(), a[3] * to_mm + off.y());
      m.turn = static_cast<int>(a[4]);
      pos = m.end;
      moves.push_back(m);
    }
  }
  return moves;
}

// Where rs274 may be: $RS274, then the build's and the source tree's build/rs274/.
std::vector<fs::path> rs274_candidates() {
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("RS274")) candidates.emplace_back(env);
  candidates.emplace_back(fs::path(MARKER_BINARY_DIR) / "rs274" / "rs274");
  const fs::path in_source = fs::path(MARKER_SOURCE_DIR) / "build" / "rs274" / "rs274";
  if (in_source.lexically_normal() != candidates.back().lexically_normal()) candidates.push_back(in_source);
  return candidates;
}

}  // namespace

Element CanonMove::path() const {
  const Point s(start.x(), start.y()), e(end.x(), end.y());
  if (kind != arc) return Element::line(s, e);
  const double r = (s - center).norm();
  const double a0 = std::atan2(s.y() - center.y(), s.x() - center.x());
  double sweep = std::atan2(e.y() - center.y(), e.x() - center.x()) - a0;
  const double two_pi = 2 * std::numbers::pi;
  if (turn > 0) {
    while (sweep <= 0) sweep += two_pi;
  } else {
    while (sweep >= 0) sweep -= two_pi;
  }
  return Element::arc(center, r, a0, sweep);
}

std::string rs274_path() {
  for (const fs::path& p : rs274_candidates())
    if (fs::exists(p)) return p.string();
  return {};
}

std::string rs274_missing() {
  if (!rs274_path().empty()) return {};
  const std::vector<fs::path> c = rs274_candidates();
  std::string where = "$RS274";
  for (std::size_t i = std::getenv("RS274") ? 1 : 0; i < c.size(); ++i) where += ", " + c[i].string();
  return "LinuxCNC rs274 not found (looked in " + where +
         "): the G-code is not validated; run scripts/fetch_rs274.sh (scripts/setup.sh does) with access to the "
         "Debian mirror";
}

Rs274Run run_rs274(const std::string& program, const std::string& name, const std::string& tool_table) {
  Rs274Run run;
  const std::string exe = rs274_path();
  if (exe.empty()) {
    ADD_FAILURE() << rs274_missing();
    return run;
  }
  const fs::path dir = fs::path(MARKER_BINARY_DIR) / "cnc_programs";
  fs::create_directories(dir);
  const fs::path file = dir / (name + ".ngc");
  std::ofstream(file) << program;
  run.file = file.string();
  const fs::path out = dir / (name + ".canon"), err = dir / (name + ".err");
  std::string env;
  if (!tool_table.empty()) {
    const fs::path tbl = dir / (name + ".tbl");
    std::ofstream(tbl) << tool_table << "\n";
    env = "RS274_TOOL_TABLE='" + tbl.string() + "' ";
  }
  const std::string cmd = env + "'" + exe + "' '" + file.string() + "' > '" + out.string() + "' 2> '" +
                          err.string() + "' < /dev/null";
  const int status = std::system(cmd.c_str());
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.output = slurp(out);
  run.errors = slurp(err);
  run.moves = parse(run.output);
  return run;
}

}  // namespace mark::test
