// `rotorsweep bench host`: the host's share of a GPU sweep per member, measured without a GPU: a chunk's
// fill, the members' summaries, the summaries with the result file's writes (as `rotorsweep run`), the rows
// packed for the file, and the packed rows' writes in order and scattered as a GPU sweep delivers them.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ensemble/engine/thread_count.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "io/member_stream.hpp"
#include "io/result_file.hpp"
#include "io/scene_parser.hpp"
#include "remove_on_signal.hpp"

namespace rotorsweep::apps {

namespace {

/// The curve's scene (examples/friction_curve_gpu.toml) with N rows and no output.
std::string curve_scene(int rows) {
  return "[model]\nrows = " + std::to_string(rows) +
         "\n[drive]\ng = [0.01]\n[sweep]\nA = { from = 0.25, to = 16.0, count = 1000 }\n[initial]\n"
         "kinds = [\"random\"]\nreplicas = 1000\nseed = 1\n"
         "[schedule]\nrelax_periods = 2\naverage_periods = 2\n[numerics]\nrtol = 1e-6\natol = 1e-9\n";
}

/// The outputs a kernel leaves in the chunk's slots, made up: every member finished its 2 + 2 periods,
/// each period's channels and end state derived from its starting angles, so that the summaries compute
/// on distinct values.
void leave_finished_members(ensemble::SlotChunk& chunk) {
  const auto& s = chunk.schedule();
  const ensemble::SlotViews v = chunk.views();
  const std::size_t n = s.rows;
  for (std::size_t k = 0; k < chunk.count(); ++k) {
    v.status[k] = 0;
    v.settled[k] = 1;
    v.periods[k] = 4;
    v.steps[2 * k] = 300;
    v.steps[2 * k + 1] = 10;
    std::copy(v.y0 + k * n, v.y0 + (k + 1) * n, v.theta + k * n);
    for (std::size_t r = 0; r < s.record_capacity; ++r)
      for (std::size_t c = 0; c < ensemble::channel_count; ++c)
        v.records[(k * s.record_capacity + r) * ensemble::channel_count + c] =
            0.5 + 0.01 * v.y0[k * n + c % n];
    for (std::size_t r = 0; r < s.end_capacity; ++r)
      std::copy(v.y0 + k * n, v.y0 + (k + 1) * n, v.end_states + (k * s.end_capacity + r) * n);
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x[x.size() / 2];
}

/// The median seconds of each step for chunks of `members` of the curve's scene at N rows.
struct HostSteps {
  double fill, summaries, writes, packing, ordered_writes, scattered_writes;
};

/// The seconds one thread takes to write the packed rows `packed` into a new result file at `path`, rows
/// in order or, `scattered`, as a GPU sweep delivers them: every fourth member first (its averaged periods
/// did not slip), the other three after their shadow runs.
double time_writes(const ensemble::Scene& scene, const ensemble::MemberPlan& plan,
                   std::vector<io::PackedRow> packed, bool scattered, const std::filesystem::path& path) {
  std::filesystem::remove(path);
  const io::ResultFile file(path.string(), scene, io::Provenance{"bench host", "", "", "cpu", ""});
  io::MemberStream stream(file, plan, {}, [] {});
  io::ResultStream<io::PackedRow>& rows = stream;  // rows already packed, as the workers leave them
  const auto start = std::chrono::steady_clock::now();
  for (const int pass : {0, 1})
    for (auto& r : packed)
      if (!scattered ? pass == 0 : (r.index % 4 == 0) == (pass == 0)) rows.add(std::move(r));
  stream.flush();
  const double seconds = seconds_since(start);
  std::filesystem::remove(path);
  return seconds;
}

HostSteps time_host_steps(int rows, std::size_t members, int threads, int repeats,
                          const std::filesystem::path& path) {
  const auto scene = io::parse_scene_text(curve_scene(rows), "bench host");
  const ensemble::MemberPlan plan(scene);
  ensemble::SlotChunk chunk(ensemble::slot_schedule(scene, plan[0], 1.0), members);
  std::vector<double> fill, summaries, writes, packing, ordered, scattered;
  for (int repeat = 0; repeat < repeats; ++repeat) {
    auto start = std::chrono::steady_clock::now();
    std::vector<ensemble::Member> chunk_members;  // decoded from the plan, as the GPU's loop does
    for (std::size_t k = 0; k < members; ++k) chunk_members.push_back(plan[k]);
    chunk.fill(scene, chunk_members);
    fill.push_back(seconds_since(start));
    leave_finished_members(chunk);

    start = std::chrono::steady_clock::now();
    chunk.deliver(scene, threads, [](const ensemble::Member&, ensemble::MemberResult&&) {});
    summaries.push_back(seconds_since(start));

    std::filesystem::remove(path);
    {
      const io::ResultFile file(path.string(), scene, io::Provenance{"bench host", "", "", "cpu", ""});
      io::MemberStream stream(file, plan, {}, [] {});
      start = std::chrono::steady_clock::now();
      chunk.deliver(scene, threads,
                    [&](const ensemble::Member&, ensemble::MemberResult&& r) { stream.add(std::move(r)); });
      stream.flush();
      writes.push_back(seconds_since(start));
    }

    std::vector<ensemble::MemberResult> results;
    std::mutex lock;
    chunk.deliver(scene, threads, [&](const ensemble::Member&, ensemble::MemberResult&& r) {
      const std::lock_guard guard(lock);
      results.push_back(std::move(r));
    });
    std::sort(results.begin(), results.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
    const auto columns = io::member_columns(scene);  // what ResultFile::pack packs
    std::vector<io::PackedRow> packed;
    start = std::chrono::steady_clock::now();
    for (const auto& r : results) packed.push_back({r.index, io::pack_table_row(columns, plan[r.index], r)});
    packing.push_back(seconds_since(start));
    ordered.push_back(time_writes(scene, plan, packed, false, path));
    scattered.push_back(time_writes(scene, plan, std::move(packed), true, path));
  }
  return {median(fill),    median(summaries), median(writes),
          median(packing), median(ordered),   median(scattered)};
}

}  // namespace

int run_bench_host(const BenchHostOptions& options) {
  const int threads = ensemble::thread_count(options.threads);
  const std::size_t members = std::size_t(options.members);
  // the scratch file is written and removed at every repeat: a directory it cannot be written to is
  // refused before any work, as a bad option
  if (::access(options.scratch.c_str(), W_OK | X_OK) != 0) {
    std::fprintf(stderr, "error: --scratch %s: the result file cannot be written there (%s)\n",
                 options.scratch.c_str(), std::strerror(errno));
    return 2;
  }
  const std::filesystem::path path = std::filesystem::path(options.scratch) /
                                     ("rotorsweep-bench-host-" + std::to_string(::getpid()) + ".h5");
  const RemoveOnSignal on_signal(path);  // SIGINT or SIGTERM removes the scratch file and ends at once
  std::printf("rotorsweep bench host: %zu members per chunk, %d host threads, medians of %d\n", members,
              threads, options.repeats);
  std::printf(
      "| N | step | s per chunk | µs per member | members/s | s per 10⁶ members |\n"
      "|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  for (const int rows : options.rows) {
    HostSteps steps{};
    try {
      steps = time_host_steps(rows, members, threads, options.repeats, path);
    } catch (const std::exception& e) {  // a full disk, a scratch directory removed under the run
      std::error_code ignored;
      std::filesystem::remove(path, ignored);
      std::fprintf(stderr, "error: --scratch %s: %s\n", options.scratch.c_str(), e.what());
      return 1;
    }
    const auto row = [&](const char* step, double seconds) {
      const double per_member = seconds / double(members);
      std::printf("| %d | %s | %.3f | %.2f | %.3g | %.2f |\n", rows, step, seconds, 1e6 * per_member,
                  1.0 / per_member, 1e6 * per_member);
    };
    row("fill (one thread)", steps.fill);
    row("summaries", steps.summaries);
    row("summaries and file writes", steps.writes);
    row("rows packed for the file (one thread)", steps.packing);
    row("file writes alone (one thread)", steps.ordered_writes);
    row("file writes alone, rows scattered (one thread)", steps.scattered_writes);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace rotorsweep::apps
