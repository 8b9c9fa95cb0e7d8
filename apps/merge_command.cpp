// `rotorsweep merge SHARD.h5... -o OUT.h5`: checks that the shards (of `run` or `slider`) come from one scene
// and one version and cover its plan exactly once, and writes the result file the unsharded run writes.
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "apps/launcher/isa_choice.hpp"
#include "build_info.hpp"
#include "commands.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/member_columns.hpp"
#include "io/output_target.hpp"
#include "io/result_file.hpp"
#include "io/result_reader.hpp"
#include "io/scene_parser.hpp"
#include "io/slider_result_file.hpp"
#include "io/slider_scene_parser.hpp"
#include "remove_on_signal.hpp"
#include "run_support.hpp"
#include "usable_memory.hpp"

namespace rotorsweep::apps {

namespace {

/// A shard's identity as its attributes state it.
struct ShardFile {
  std::string path, scene_text, scene_path, version, device, isa;
  std::size_t index = 0, count = 0;
  bool slider = false;  ///< a slider scan's shard (`rotorsweep slider --shard`)
  double wall_seconds = 0, threads = 1, lane_width = 1, lane_occupancy = 0;
};

ShardFile describe(const std::string& path, const io::Hdf5Location& file) {
  if (!file.has_attribute("shard_index") || !file.has("members"))
    throw std::runtime_error("'" + path + "' is not a shard file (written by run or slider --shard I/N)");
  if (!file.attribute_flag("complete")) {  // a shard's partial file: its run resumes, then its file merges
    const auto label = io::MemberTableFile::shard_label(file);
    const bool slider = file.has_attribute("kind") && file.attribute_string("kind") == "slider";
    const std::string shard = label ? std::to_string(label->index) + "/" + std::to_string(label->count) : "I/N";
    throw std::runtime_error("'" + path + "' is incomplete: its run stopped early; finish it with rotorsweep " +
                             (slider ? "slider" : "run") + " '" + file.attribute_string("scene_path") +
                             "' --shard " + shard + " -o OUT.h5 --resume (OUT.h5.partial being this file), " +
                             "then merge OUT.h5");
  }
  ShardFile shard;
  shard.path = path;
  shard.scene_text = file.attribute_string("scene");
  shard.scene_path = file.attribute_string("scene_path");
  shard.device = file.has_attribute("device") ? file.attribute_string("device") : "cpu";
  shard.isa = file.has_attribute("isa") ? file.attribute_string("isa") : "unknown";
  shard.version = io::written_by(file);
  const auto label = io::MemberTableFile::shard_label(file).value();
  shard.index = label.index;
  shard.count = label.count;
  shard.slider = file.has_attribute("kind") && file.attribute_string("kind") == "slider";
  shard.wall_seconds = file.attribute_double("wall_seconds");
  shard.threads = file.attribute_double("threads");
  if (!shard.slider && file.has_attribute("lane_width")) {  // the slider's lanes are not counted
    shard.lane_width = file.attribute_double("lane_width");
    shard.lane_occupancy = file.attribute_double("lane_occupancy");
  }
  return shard;
}

void check_same_plan(const ShardFile& first, const ShardFile& other) {
  const auto differ = [&](const std::string& what) {
    throw std::runtime_error("'" + other.path + "' and '" + first.path + "' differ in their " + what +
                             ": they are not shards of one run");
  };
  if (other.scene_text != first.scene_text) differ("scene");
  if (other.version != first.version) differ("program (version and revision) that wrote them");
  if (other.count != first.count) differ("shard count");
}

}  // namespace

/// Members copied at a time.
constexpr std::size_t block_members = 4096;

int run_merge(const MergeOptions& options) {
  // first pass: the shards' attributes and plan indices, checked to make one plan exactly once
  ensemble::Scene scene;
  ensemble::SliderScene slider;
  std::optional<ShardFile> first;
  std::set<std::string> isas;  // shards run by different binaries give the same bits; all are named
  ensemble::SweepStatistics stats;
  double row_bytes = 0;  // of the output's /members
  try {
    std::map<std::size_t, std::string> seen;  // shard index → file
    std::vector<char> covered;
    double busy = 0;
    for (const auto& path : options.shards) {
      const auto file = io::Hdf5Location::open_file(path);
      const ShardFile shard = describe(path, file);
      if (!first) {
        first = shard;
        if (shard.slider)
          slider = io::parse_slider_scene_text(shard.scene_text, shard.scene_path);
        else
          scene = io::parse_scene_text(shard.scene_text, shard.scene_path);
        const std::size_t plan_members = shard.slider ? slider.member_count() : scene.member_count();
        if (shard.version != program_identity())
          throw std::runtime_error("'" + path + "' was written by rotorsweep " + shard.version +
                                   ", this is " + program_identity() +
                                   ": merge with the program that ran the shards");
        row_bytes =
            shard.slider
                ? 1 + io::table_row_bytes(io::slider_columns(slider, ensemble::slider_timeline(slider)))
                : io::member_row_bytes(io::member_columns(scene));
        // the plan's coverage mask, and a block of rows read and one written
        if (!fits_in_memory(double(plan_members) + 2 * double(block_members) * row_bytes, "merge",
                            " for a plan of " + std::to_string(plan_members) + " members",
                            "merge on a larger machine"))
          return 2;
        covered.assign(plan_members, 0);
      }
      check_same_plan(*first, shard);
      // its kind, plan size and every dataset's shape and type, against the scene
      if (first->slider)
        io::SliderResultFile::check_file(file, slider);
      else
        io::ResultFile::check_file(file, scene);
      isas.insert(shard.isa);
      if (const auto [at, fresh] = seen.emplace(shard.index, path); !fresh)
        throw std::runtime_error("'" + path + "' and '" + at->second + "' are both shard " +
                                 std::to_string(shard.index) + "/" + std::to_string(shard.count));
      const auto members = file.open_group("members");
      const std::size_t rows = io::member_rows(file);
      if (members.has("done")) {  // a complete shard has every row done; an edited one may not
        const auto done = members.read_flags("done");
        for (std::size_t row = 0; row < done.size(); ++row)
          if (!done[row])
            throw std::runtime_error("'" + path + "': /members row " + std::to_string(row) +
                                     " is not marked done, though the file says complete: it is not a "
                                     "whole shard");
      }
      for (std::size_t row = 0; row < rows; row += block_members)
        for (const auto i :
             members.read_rows_integers("plan_index", row, std::min(block_members, rows - row))) {
          if (i < 0 || std::size_t(i) >= covered.size())
            throw std::runtime_error("'" + path + "': /members/plan_index is outside the plan");
          if (covered[std::size_t(i)])
            throw std::runtime_error("member " + std::to_string(i) + " is in two shards ('" + path + "')");
          covered[std::size_t(i)] = 1;
        }
      stats.wall_seconds += shard.wall_seconds;
      stats.threads = std::max(stats.threads, int(shard.threads));
      stats.lane_width = std::size_t(shard.lane_width);
      busy += shard.lane_occupancy * double(rows);
    }
    std::string missing;
    for (std::size_t i = 1; i <= first->count; ++i)
      if (!seen.count(i)) missing += (missing.empty() ? "" : ", ") + std::to_string(i);
    if (!missing.empty())
      throw std::runtime_error("shard" + std::string(missing.find(',') == std::string::npos ? " " : "s ") +
                               missing + " of " + std::to_string(first->count) + " missing");
    for (std::size_t m = 0; m < covered.size(); ++m)
      if (!covered[m]) throw std::runtime_error("member " + std::to_string(m) + " is in no shard");
    stats.lane_steps_busy = busy;
    stats.lane_steps_total = double(covered.size());
  } catch (const std::exception& e) {  // shards that do not make one plan, or unreadable ones
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }

  std::optional<io::OutputTarget> target;
  try {
    target.emplace(options.output, options.shards, io::Replaceable::hdf5, options.force);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << " (-o)\n";
    return 2;
  }
  const std::size_t plan_members = first->slider ? slider.member_count() : scene.member_count();
  if (!fits_on_disk(double(plan_members) * row_bytes +
                        (first->slider ? io::SliderResultFile::finishing_bytes(slider, false)
                                       : io::ResultFile::finishing_bytes(scene, false)),
                    "the merged file's " + std::to_string(plan_members) + " members and its curves",
                    target->temporary(), "Free some space there, or merge elsewhere"))
    return 2;
  // second pass: the shards' rows, a block at a time, into their plan rows of the output
  std::size_t members = 0;
  try {
    std::optional<RemoveOnSignal> on_signal(std::in_place, *target);
    const io::Provenance provenance{first->scene_path, version, revision, first->device,
                                    launcher::joined({isas.begin(), isas.end()})};
    if (first->slider) {
      io::SliderResultFile out(target->temporary(), slider, provenance);
      target->claim_temporary();
      for (const auto& path : options.shards) out.copy_done_rows(io::Hdf5Location::open_file(path));
      out.finish(stats.wall_seconds, stats.threads);
      out.close();
      members = slider.member_count();
    } else {
      const ensemble::MemberPlan plan(scene);
      io::ResultFile out(target->temporary(), scene, provenance);
      target->claim_temporary();
      for (const auto& path : options.shards) {
        const auto file = io::Hdf5Location::open_file(path);
        const std::size_t rows = io::member_rows(file);
        for (std::size_t row = 0; row < rows; row += block_members)
          out.write_results(
              plan, io::read_member_rows(file, scene, plan, row, std::min(block_members, rows - row)));
      }
      out.finish(stats);
      out.close();
      members = scene.member_count();
    }
    on_signal.reset();
    target->commit();
  } catch (const std::exception& e) {
    std::cerr << "error: writing " << options.output << " failed: " << e.what() << "; "
              << (target->replaced() ? "the previous file is unchanged" : "no file was written") << "\n";
    return 1;
  }
  if (!options.quiet)
    std::fprintf(stderr, "wrote %s: %zu members from %zu shards\n", options.output.c_str(), members,
                 options.shards.size());
  return 0;
}

}  // namespace rotorsweep::apps
