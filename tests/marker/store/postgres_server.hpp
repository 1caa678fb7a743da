#pragma once
// A private PostgreSQL server for one test: initdb + pg_ctl from Debian's server binaries in a
// temporary folder, listening on a Unix socket only, stopped (and its folder removed) when the
// object goes — also when the test fails. initdb refuses to run as root, so under root the
// server runs as the unprivileged user `nobody` (runuser); its clients connect over the socket
// as the database superuser `marker` with trust authentication.
#include <pwd.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mark::test {

class PostgresServer {
 public:
  // The tests check concurrency (row locks, one transaction per allocation, no duplicates or
  // gaps between stations), not crash durability — that is the server's own job, and the kill
  // test proves ours on SQLite. So this throw-away server does not flush to disk: every commit
  // waiting for an fsync made 8 × 1000 parts take 139 s on a loaded machine.
  static constexpr const char* kNoFlush =
      " -c fsync=off -c synchronous_commit=off -c full_page_writes=off";

  // The first /usr/lib/postgresql/*/bin holding initdb and pg_ctl; empty if none.
  static std::filesystem::path find_binaries() {
    const std::filesystem::path root = "/usr/lib/postgresql";
    std::error_code ec;
    std::filesystem::path best;
    for (const auto& e : std::filesystem::directory_iterator(root, ec)) {
      const auto bin = e.path() / "bin";
      if (std::filesystem::exists(bin / "initdb") && std::filesystem::exists(bin / "pg_ctl") &&
          (best.empty() || bin > best))
        best = bin;
    }
    return best;
  }

  // `durable`: the server flushes every commit to disk, as a plant's does (the benchmarks' figures);
  // the tests' servers do not (kNoFlush).
  explicit PostgresServer(const std::filesystem::path& bin, bool durable = false) : bin_(bin) {
    dir_ = std::filesystem::temp_directory_path() / ("marker-pg-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    as_ = ::geteuid() == 0 ? "runuser -u nobody -- " : "";
    if (::geteuid() == 0) {
      const passwd* nobody = ::getpwnam("nobody");
      if (!nobody) throw std::runtime_error("running as root and there is no user 'nobody'");
      std::filesystem::permissions(dir_, std::filesystem::perms::all);
      if (::chown(dir_.c_str(), nobody->pw_uid, nobody->pw_gid) != 0)
        throw std::runtime_error("cannot hand " + dir_.string() + " to nobody");
    }
    run(as_ + (bin_ / "initdb").string() + " -D " + data() + " -U marker -A trust -E UTF8 " +
            "--no-sync --no-instructions",
        "initdb");
    started_ = true;  // from here on the destructor stops whatever was started
    run(as_ + (bin_ / "pg_ctl").string() + " -D " + data() + " -l " + (dir_ / "server.log").string() +
            " -w -t 60 -o \"-k " + dir_.string() + " -c listen_addresses='' -c max_connections=40" +
            (durable ? "" : kNoFlush) + "\" start",
        "pg_ctl start");
  }
  ~PostgresServer() {
    if (started_)
      std::system((as_ + (bin_ / "pg_ctl").string() + " -D " + data() + " -m immediate -w stop >/dev/null 2>&1").c_str());
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  PostgresServer(const PostgresServer&) = delete;
  PostgresServer& operator=(const PostgresServer&) = delete;

  // libpq URI of the server's `postgres` database over the socket.
  std::string url() const { return "postgresql:///postgres?host=" + dir_.string() + "&user=marker"; }

 private:
  std::string data() const { return (dir_ / "data").string(); }
  void run(const std::string& cmd, const char* what) {
    const std::string log = (dir_ / "setup.log").string();
    if (std::system((cmd + " >>" + log + " 2>&1").c_str()) != 0) {
      std::ifstream in(log);
      std::stringstream text;
      text << in.rdbuf();
      throw std::runtime_error(std::string(what) + " failed: " + text.str());
    }
  }

  std::filesystem::path bin_;
  std::filesystem::path dir_;
  std::string as_;
  bool started_ = false;
};

}  // namespace mark::test
