#pragma once
// Where a station keeps its state — the serial store and the outcome journals — when no
// --store is given. The store is the station's, not a job's: copying, moving or renaming a job
// file, or reaching it through a symlink, marks into the same store. The folder is the first of:
//
//   $STATE_DIRECTORY           set by systemd for a unit with StateDirectory=marker (that is,
//                              /var/lib/marker): the station running as a service
//   $XDG_STATE_HOME/marker     the XDG base directory for state
//   $HOME/.local/state/marker  its default
//   /var/lib/marker            a process without a home
//
// (relative values are ignored, as the XDG specification asks).
#include <string>

namespace mark {

std::string station_state_dir();
// station_state_dir()/serials.sqlite
std::string default_store_path();
// station_state_dir()/journal
std::string default_journal_dir();
// Where stores were kept before they were the station's: beside the job
// ("bracket.json" → "bracket.serials.sqlite"). Only read to tell a user where an old store is.
std::string job_side_store_path(const std::string& job_path);
bool is_postgres_url(const std::string& location);

}  // namespace mark
