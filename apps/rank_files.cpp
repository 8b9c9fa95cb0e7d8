// Finding the rank files of a run under mpirun and joining what they hold into its partial file.
#include "rank_files.hpp"

#include <algorithm>

#include "ensemble/rows/member_plan.hpp"
#include "io/result_reader.hpp"

namespace rotorsweep::apps {

std::vector<std::string> rank_files(const std::string& partial) {
  namespace fs = std::filesystem;
  const fs::path at(partial);
  const fs::path directory = at.has_parent_path() ? at.parent_path() : fs::path(".");
  const std::string stem = at.filename().string() + ".rank-";
  std::vector<std::pair<long, std::string>> found;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= stem.size() || name.compare(0, stem.size(), stem) != 0) continue;
    const std::string rank = name.substr(stem.size());
    if (rank.find_first_not_of("0123456789") != std::string::npos || rank.size() > 9) continue;
    found.emplace_back(std::stol(rank), rank_file(partial, int(std::stol(rank))));
  }
  std::sort(found.begin(), found.end());
  std::vector<std::string> paths;
  for (auto& [rank, path] : found) paths.push_back(std::move(path));
  return paths;
}

std::size_t join_rank_file(const io::ResultFile& out, const ensemble::Scene& scene, const std::string& path) {
  constexpr std::size_t block = 4096;
  const ensemble::MemberPlan plan(scene);
  std::size_t joined = 0;
  {
    const auto file = io::Hdf5Location::open_file(path);
    const auto done = io::read_done(file);
    for (std::size_t first = 0; first < done.size(); first += block) {
      const std::size_t count = std::min(block, done.size() - first);
      auto results = io::read_member_rows(file, scene, plan, first, count, done.data() + first);
      joined += results.size();
      out.write_results(plan, std::move(results));
    }
  }
  std::filesystem::remove(path);
  return joined;
}

std::size_t join_rank_file(const io::SliderResultFile& out, const ensemble::SliderScene&,
                           const std::string& path) {
  const std::size_t joined = out.copy_done_rows(io::Hdf5Location::open_file(path));
  std::filesystem::remove(path);
  return joined;
}

namespace {
std::size_t members_marked_done(const io::MemberTableFile& file) {
  const auto done = file.done();
  return std::size_t(std::count(done.begin(), done.end(), 1));
}
}  // namespace

void keep_joined(const io::ResultFile& out) { out.keep_partial(members_marked_done(out), {}); }
void keep_joined(const io::SliderResultFile& out) { out.keep_partial(members_marked_done(out), 0.0, 0); }

}  // namespace rotorsweep::apps
