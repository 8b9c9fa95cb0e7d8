// The memory this process may use: the machine's, or less where the process's address-space limit
// (ulimit -v) or its control group's memory limit says so.
#pragma once

namespace rotorsweep::apps {

/// Bytes: the smallest of the physical memory, RLIMIT_AS and the cgroup limit (v2 memory.max, v1
/// memory.limit_in_bytes); limits that are not set do not count.
double usable_memory_bytes();

}  // namespace rotorsweep::apps
