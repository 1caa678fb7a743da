#include "marker/cli/cli.hpp"

#include <CLI/CLI.hpp>
#include <iostream>

#include "base/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/suggestions.hpp"
#include "marker/output/output_file.hpp"
#include "marker/store/store_error.hpp"

namespace mark::cli {

int run(int argc, char** argv) {
  CLI::App app{"marker — laser galvo marking engine"};
  app.require_subcommand(1);
  std::vector<Command> commands = all_commands();
  for (Command& c : commands) c.attach(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0 as CLI11 prints them; every real mistake on the command line
    // (an unknown option, a value outside its range, a missing argument) is one line and exit 1,
    // like every other refusal.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "marker: " << parse_error_line(app, e) << "\n";
    return 1;
  }
  // Ctrl-C / SIGTERM become a stop request the command polls; a command stopped that way
  // exits 130 with nothing half-done.
  interrupt_flag().reset();
  InterruptScope interrupts(interrupt_flag());
  // A command that wrote a file to standard output ("-o -") gets it back when it ends.
  struct ReleaseStandardOutput {
    ~ReleaseStandardOutput() { release_standard_output(); }
  } release;
  try {
    for (Command& c : commands)
      if (c.parsed()) return c.run();
  } catch (const Interrupted& e) {
    std::cerr << "marker: " << e.what() << "\n";
    return kExitInterrupted;
  } catch (const StoreError& e) {
    // A wait for the store that Ctrl-C ended is an interruption, not a failure.
    std::cerr << "marker: " << e.what() << "\n";
    return e.kind() == StoreErrorKind::cancelled ? kExitInterrupted : 1;
  } catch (const std::exception& e) {
    std::cerr << "marker: " << e.what() << "\n";
    return 1;
  }
  return 1;
}

}  // namespace mark::cli
