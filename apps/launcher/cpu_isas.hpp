// Which of rotorsweep's instruction sets this CPU (and its operating system) can execute:
// the x86-64 levels v1 (sse2), v3 (avx2) and v4 (avx512), as the CPU reports them at run time.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace rotorsweep::launcher {

/// Every instruction set a portable build can hold, narrowest first.
inline constexpr std::array<std::string_view, 3> known_isas{"sse2", "avx2", "avx512"};

/// The known sets this CPU runs, narrowest first (empty off x86-64).
inline std::vector<std::string> runnable_isas() {
  std::vector<std::string> runnable;
#if defined(__x86_64__)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("x86-64")) runnable.emplace_back("sse2");
  if (__builtin_cpu_supports("x86-64-v3")) runnable.emplace_back("avx2");
  if (__builtin_cpu_supports("x86-64-v4")) runnable.emplace_back("avx512");
#endif
  return runnable;
}

}  // namespace rotorsweep::launcher
