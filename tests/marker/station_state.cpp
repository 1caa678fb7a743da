// Every test of this executable keeps the station's state (the default serial store and the
// outcome journals, marker/store/store_location.hpp) in a folder of its own, never in the
// home of whoever runs the tests: set before any test runs, removed at exit. A test that needs
// a store of its own points XDG_STATE_HOME elsewhere (test::use_station_state).
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

struct StationState {
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("marker-tests-state-" + std::to_string(::getpid()));
  StationState() {
    ::unsetenv("STATE_DIRECTORY");
    ::setenv("XDG_STATE_HOME", dir.c_str(), 1);
  }
  ~StationState() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

const StationState state;

}  // namespace
