// The `marker` command: thin; every subcommand lives in marker/cli/.
#include "marker/cli/cli.hpp"

int main(int argc, char** argv) { return mark::cli::run(argc, argv); }
