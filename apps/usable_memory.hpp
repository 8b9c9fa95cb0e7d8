// The memory this process may use: the machine's, or less where the process's address-space limit
// (ulimit -v) or its control group's memory limit says so.
#pragma once

#include <optional>
#include <string>

namespace rotorsweep::apps {

/// Bytes: the smallest of the physical memory, RLIMIT_AS and the cgroup limit (v2 memory.max, v1
/// memory.limit_in_bytes); limits that are not set do not count.
double usable_memory_bytes();

/// Where `bytes` do not fit in 80 % of usable_memory_bytes(): "<what> needs about X GiB<how>, more than
/// 80 % of the Y GiB this process may use (...); <advice>".
std::optional<std::string> memory_refusal(double bytes, const std::string& what, const std::string& how,
                                          const std::string& advice);

/// Whether `bytes` fit; when not, says memory_refusal's words on stderr after "error: " and returns false
/// (the command then exits 2 before allocating).
bool fits_in_memory(double bytes, const std::string& what, const std::string& how, const std::string& advice);

}  // namespace rotorsweep::apps
