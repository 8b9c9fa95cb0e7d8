// usable_memory_bytes from sysconf, getrlimit and the cgroup files (absent or "max": no limit), and the
// check every command makes before it allocates.
#include "usable_memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

namespace rotorsweep::apps {

namespace {

/// The number in the first line of `path`, or 0 when it is missing, "max" or not a number.
double limit_in_file(const char* path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text)) return 0;
  try {
    return std::stod(text);
  } catch (const std::exception&) {
    return 0;
  }
}

}  // namespace

double usable_memory_bytes() {
  double usable = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
  rlimit address_space{};
  if (::getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY)
    usable = std::min(usable, double(address_space.rlim_cur));
  for (const char* file : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"})
    if (const double limit = limit_in_file(file); limit > 0) usable = std::min(usable, limit);
  return usable;
}

std::optional<std::string> memory_refusal(double bytes, const std::string& what, const std::string& how,
                                          const std::string& advice) {
  const double usable = usable_memory_bytes();
  if (bytes <= 0.8 * usable) return std::nullopt;
  char amounts[160];
  std::snprintf(amounts, sizeof amounts, "%.3g GiB", bytes / 0x1p30);
  std::string text = what + " needs about " + amounts + how + ", more than 80 % of the ";
  std::snprintf(amounts, sizeof amounts, "%.3g GiB", usable / 0x1p30);
  return text + amounts + " this process may use (the machine's memory, ulimit -v or its cgroup's limit); " +
         advice;
}

bool fits_in_memory(double bytes, const std::string& what, const std::string& how, const std::string& advice) {
  const auto refusal = memory_refusal(bytes, what, how, advice);
  if (refusal) std::fprintf(stderr, "error: %s\n", refusal->c_str());
  return !refusal;
}

}  // namespace rotorsweep::apps
