#pragma once
// Real-time scheduling for the drain thread and locked memory for the process, where the
// system permits (root, CAP_SYS_NICE / CAP_IPC_LOCK, or generous RLIMIT_RTPRIO /
// RLIMIT_MEMLOCK). Both only ask: a refusal is reported, never fatal — the job's figures say
// whether they were granted, so a lateness figure can be read for what it is.

namespace mark {

// SCHED_FIFO at `priority` (1..99) for the calling thread. True if granted.
bool request_realtime_priority(int priority) noexcept;

// Lock every page the process has mapped now into RAM (mlockall(MCL_CURRENT)): the buffers a
// job sized before its first sample cannot be paged out under it. MCL_FUTURE is not asked for:
// with a small RLIMIT_MEMLOCK it makes later allocations fail. True if granted.
bool lock_memory() noexcept;
void unlock_memory() noexcept;

}  // namespace mark
