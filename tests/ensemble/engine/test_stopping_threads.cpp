// run_on_threads, the CPU sweeps' threads driver: every thread works until the work runs out, an
// outside stop or the first exception stops them all, and that exception reaches the caller.
#include <atomic>
#include <catch2/catch.hpp>
#include <stdexcept>

#include "ensemble/engine/stopping_threads.hpp"

using rotorsweep::ensemble::run_on_threads;

TEST_CASE("run_on_threads runs every thread until the work runs out", "[engine]") {
  std::atomic<int> threads{0}, taken{0};
  std::atomic<int> next{0};
  run_on_threads(
      3, [] { return false; },
      [&](const auto& stopped) {
        ++threads;
        while (!stopped() && next.fetch_add(1) < 1000) ++taken;
      });
  CHECK(threads == 3);
  CHECK(taken == 1000);
}

TEST_CASE("run_on_threads: the first exception stops the other threads and reaches the caller", "[engine]") {
  std::atomic<int> returned{0};
  std::atomic<bool> thrown{false};
  const auto work = [&](const auto& stopped) {
    if (!thrown.exchange(true)) throw std::runtime_error("the first");
    while (!stopped()) {  // the others spin until the failure stops them
    }
    ++returned;
  };
  CHECK_THROWS_WITH(run_on_threads(
                        3, [] { return false; }, work),
                    "the first");
  CHECK(returned == 2);  // every other thread saw the stop and returned
}

TEST_CASE("run_on_threads: an outside stop stops every thread", "[engine]") {
  std::atomic<bool> outside{false};
  std::atomic<int> returned{0};
  run_on_threads(
      2, [&] { return outside.load(); },
      [&](const auto& stopped) {
        outside = true;  // any thread may raise it
        while (!stopped()) {
        }
        ++returned;
      });
  CHECK(returned == 2);
}
