// Test support: a host emulation's members on every core (they are independent: each writes its own
// slot), so that the host's side of a device check keeps up with the device's.
#pragma once

#include <cstddef>
#include <exception>

namespace rotorsweep::testing {

/// run(k) for k < count on OpenMP's threads (dynamic: members take unequal times); the first exception
/// is rethrown once all have returned. run must not use Catch2's assertions (they are not thread-safe).
template <class Run>
void for_each_member_in_parallel(std::size_t count, Run&& run) {
  std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic)
  for (std::ptrdiff_t k = 0; k < std::ptrdiff_t(count); ++k) {
    try {
      run(std::size_t(k));
    } catch (...) {
#pragma omp critical(parallel_members_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace rotorsweep::testing
