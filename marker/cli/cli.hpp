#pragma once
// The `marker` command line: one subcommand per file in this folder, registered in cli.cpp.
namespace mark::cli {
int run(int argc, char** argv);
}
