// run_chunks_two_in_flight, the device executors' chunk pipeline: chunk i in slot i mod 2, each started
// before the one before it is finished, every started chunk finished, nothing started once stopped,
// and work that a finish leaves (reruns) started after it.
#include <array>
#include <catch2/catch.hpp>
#include <string>

#include "ensemble/engine/chunk_pipeline.hpp"

using rotorsweep::ensemble::run_chunks_two_in_flight;

namespace {

/// The pipeline's calls over `chunks` chunks ("s0" starts slot 0, "f0" finishes it), stopped once
/// `stop_after` chunks were finished.
std::string calls(int chunks, int stop_after, bool* halted = nullptr) {
  std::string log;
  int started = 0, finished = 0;
  const bool h = run_chunks_two_in_flight(
      [&](std::size_t slot) {
        if (started == chunks) return false;
        ++started;
        log += {'s', char('0' + slot), ' '};
        return true;
      },
      [&](std::size_t slot) {
        ++finished;
        log += {'f', char('0' + slot), ' '};
      },
      [&] { return finished >= stop_after; });
  if (halted) *halted = h;
  return log;
}

}  // namespace

TEST_CASE("the chunk pipeline starts each chunk before it finishes the one before", "[engine]") {
  bool halted = true;
  CHECK(calls(0, 99, &halted).empty());
  CHECK_FALSE(halted);
  CHECK(calls(1, 99) == "s0 f0 ");
  CHECK(calls(2, 99) == "s0 s1 f0 f1 ");
  CHECK(calls(5, 99, &halted) == "s0 s1 f0 s0 f1 s1 f0 s0 f1 f0 ");
  CHECK_FALSE(halted);
}

TEST_CASE("a stopped chunk pipeline starts nothing more and finishes what it started", "[engine]") {
  bool halted = false;
  CHECK(calls(5, 0, &halted).empty());
  CHECK(halted);
  CHECK(calls(5, 1, &halted) == "s0 s1 f0 f1 ");
  CHECK(halted);
  CHECK(calls(5, 2, &halted) == "s0 s1 f0 s0 f1 f0 ");
  CHECK(halted);
}

namespace {

/// The pipeline's calls over `plan` chunks of the plan ("s0p"), each of which leaves one chunk of
/// reruns when it finishes ("s1r"), which leave none.
std::string calls_with_reruns(int plan) {
  std::string log;
  int reruns = 0;
  std::array<bool, 2> rerun_in{};
  run_chunks_two_in_flight(
      [&](std::size_t slot) {
        if (reruns == 0 && plan == 0) return false;
        rerun_in[slot] = reruns > 0;
        --(rerun_in[slot] ? reruns : plan);
        log += {'s', char('0' + slot), rerun_in[slot] ? 'r' : 'p', ' '};
        return true;
      },
      [&](std::size_t slot) {
        log += {'f', char('0' + slot), ' '};
        if (!rerun_in[slot]) ++reruns;
      },
      [] { return false; });
  return log;
}

}  // namespace

TEST_CASE("chunks that a finish leaves start after it, also once the plan has run out", "[engine]") {
  CHECK(calls_with_reruns(1) == "s0p f0 s1r f1 ");
  CHECK(calls_with_reruns(2) == "s0p s1p f0 s0r f1 s1r f0 f1 ");
}
