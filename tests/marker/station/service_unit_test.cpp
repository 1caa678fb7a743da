// packaging/marker-station.service, checked by systemd's own parser (systemd-analyze verify)
// with ExecStart pointed at the built binary (verify insists the program exists), and the
// settings the station's safety depends on read back from the file.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// systemd-analyze verify on `unit` written to a fresh directory: its exit status and output.
std::pair<int, std::string> verify(const std::string& unit) {
  const auto dir = std::filesystem::temp_directory_path() / ("marker-unit-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / "marker-station.service";
  std::ofstream(path) << unit;
  FILE* p = ::popen(("systemd-analyze verify " + path.string() + " 2>&1").c_str(), "r");
  std::string out;
  char chunk[1024];
  for (std::size_t n; (n = std::fread(chunk, 1, sizeof chunk, p)) > 0;) out.append(chunk, n);
  const int status = ::pclose(p);
  std::filesystem::remove_all(dir);
  return {status, out};
}

std::string with_built_binary(std::string unit) {
  const std::string installed = "/usr/local/bin/marker", built = std::string(MARKER_BINARY_DIR) + "/marker/marker";
  for (std::size_t at; (at = unit.find(installed)) != std::string::npos;) unit.replace(at, installed.size(), built);
  return unit;
}

TEST(ServiceUnit, SystemdVerifiesTheStationUnit) {
  if (std::system("command -v systemd-analyze >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "systemd-analyze is not installed: the unit is not verified here";
  const std::string unit = read(std::string(MARKER_SOURCE_DIR) + "/packaging/marker-station.service");
  ASSERT_FALSE(unit.empty());
  const auto [status, out] = verify(with_built_binary(unit));
  EXPECT_EQ(status, 0) << out;
  EXPECT_EQ(out, "");
  // The check can fail: a misspelt setting is reported.
  std::string misspelt = unit;
  misspelt.insert(misspelt.find("[Install]"), "ProtectSystm=strict\n");
  const auto [bad_status, bad_out] = verify(with_built_binary(misspelt));
  EXPECT_NE(bad_out.find("Unknown key 'ProtectSystm' in section [Service]"), std::string::npos) << bad_out;
}

TEST(ServiceUnit, RunsAsItsOwnUserWithTheHardeningTheStationNeeds) {
  const std::string unit = read(std::string(MARKER_SOURCE_DIR) + "/packaging/marker-station.service");
  std::set<std::string> lines;
  std::istringstream in(unit);
  for (std::string l; std::getline(in, l);) lines.insert(l);
  for (const char* want : {"User=marker", "StateDirectory=marker", "KillSignal=SIGTERM", "Restart=on-failure",
                           "NoNewPrivileges=yes", "ProtectSystem=strict", "ProtectHome=yes", "PrivateTmp=yes",
                           "DevicePolicy=closed", "DeviceAllow=char-usb_device rw", "SupplementaryGroups=plugdev"})
    EXPECT_TRUE(lines.count(want)) << want;
  EXPECT_NE(unit.find("ExecStart=/usr/local/bin/marker serve --job /etc/marker/job.json "), std::string::npos);
  EXPECT_NE(unit.find("--store /var/lib/marker/serials.sqlite"), std::string::npos);
}

}  // namespace
