// The OpenMP thread count of a run, one rule for --threads, Python's threads= and OMP_NUM_THREADS:
// an integer from 1 to max_threads, checked before anything runs or is written.
#pragma once

#include <omp.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace rotorsweep::ensemble {

inline constexpr int max_threads = 4096;

/// A thread count outside 1 … max_threads, with where it came from.
struct ThreadCountError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// `requested` when > 0; for 0 (the default), OMP_NUM_THREADS's first value where it is set, else
/// the cores OpenMP finds. Throws ThreadCountError for a count outside 1 … max_threads.
inline int thread_count(int requested, const char* what = "--threads") {
  const std::string range = "must be an integer from 1 to " + std::to_string(max_threads);
  if (requested < 0 || requested > max_threads)
    throw ThreadCountError(std::string(what) + " = " + std::to_string(requested) + ": " + range +
                           " (or the default: OMP_NUM_THREADS, else every core)");
  if (requested > 0) return requested;
  if (const char* text = std::getenv("OMP_NUM_THREADS"); text && *text) {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end == text || (*end != '\0' && *end != ',') || value < 1 || value > max_threads)
      throw ThreadCountError(std::string("OMP_NUM_THREADS = '") + text + "': " + range);
  }
  return omp_get_max_threads();
}

}  // namespace rotorsweep::ensemble
