// RerunQueue, the one queue of reruns for lanes and chunks: reruns first in first out, a primary held
// until its last rerun has finished, each rerun's result taken into it.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "ensemble/engine/rerun_queue.hpp"

using rotorsweep::ensemble::RerunQueue;

namespace {

/// A rerun of member `index`, and a result that records what completed it.
struct Rerun {
  std::size_t index;
  char kind;
};

}  // namespace

TEST_CASE("a rerun queue holds a primary until its last rerun, reruns first in first out", "[engine]") {
  RerunQueue<Rerun, std::string> queue;
  CHECK_FALSE(queue.take());
  queue.hold(7, "p7", {{7, 's'}, {7, 'g'}});
  queue.hold(3, "p3", {{3, 's'}});
  CHECK(queue.queued() == 3);
  CHECK(queue.held() == 2);

  const auto first = queue.take(), second = queue.take(), third = queue.take();
  REQUIRE((first && second && third));
  CHECK(first->index == 7);
  CHECK(first->kind == 's');
  CHECK(second->kind == 'g');
  CHECK(third->index == 3);
  CHECK_FALSE(queue.take());
  CHECK(queue.queued() == 0);

  // member 3's only rerun completes it; member 7 waits for both of its reruns, taking each
  const auto add = [](char kind) { return [kind](std::string& primary) { primary += kind; }; };
  CHECK(queue.finish(3, add('s')) == std::string("p3s"));
  CHECK_FALSE(queue.finish(7, add('g')));
  CHECK(queue.held() == 1);
  CHECK(queue.finish(7, add('s')) == std::string("p7gs"));
  CHECK(queue.held() == 0);
}
