// Writing a sweep's results: pre-sized /members columns filled row by row with the done mask
// written after the rows it marks, /curves from the file at the end, the completion flag last.
#include "io/result_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <numeric>

#include "io/curve_table.hpp"

namespace rotorsweep::io {

ResultFile::ResultFile(const std::string& path, const ensemble::Scene& scene, const Provenance& provenance,
                       const std::optional<ShardLabel>& shard)
    : ResultFile(Hdf5Location::create_file(path), scene, shard) {
  create(provenance);
  // closing sets the file's length to all it allocated: from here on nothing is allocated until finish()
  file_.close();
  file_ = Hdf5Location::open_file_for_writing(path);
  on_disk_ = true;
}

ResultFile ResultFile::in_memory(const ensemble::Scene& scene, const Provenance& provenance) {
  ResultFile file(Hdf5Location::create_in_memory(provenance.scene_path + ".h5"), scene, std::nullopt);
  file.create(provenance);
  return file;
}

ResultFile ResultFile::reopen(const std::string& path, const ensemble::Scene& scene) {
  auto location = Hdf5Location::open_file_for_writing(path);
  std::optional<ShardLabel> shard;
  if (location.has_attribute("shard_index"))
    shard = ShardLabel{std::size_t(location.attribute_double("shard_index")),
                       std::size_t(location.attribute_double("shard_count")),
                       std::size_t(location.attribute_double("plan_members"))};
  ResultFile file(std::move(location), scene, shard);
  file.on_disk_ = true;
  if (file.file_.open_group("members").shape("done").first != file.rows_)
    throw std::runtime_error("'" + path + "' does not have a row for every member of its scene's plan");
  return file;
}

ResultFile::ResultFile(Hdf5Location file, const ensemble::Scene& scene, std::optional<ShardLabel> shard)
    : file_(std::move(file)), scene_(scene), columns_(member_columns(scene)), shard_(shard) {
  const std::size_t plan = scene.member_count();
  rows_ = shard ? (plan + shard->count - shard->index) / shard->count : plan;
}

hsize_t ResultFile::row_of(std::size_t plan_index) const {
  return shard_ ? (plan_index - (shard_->index - 1)) / shard_->count : plan_index;
}

void write_provenance(const Hdf5Location& file, const std::string& scene_text, const Provenance& provenance) {
  file.set_attribute("scene", scene_text);
  file.set_attribute("scene_path", provenance.scene_path);
  file.set_attribute("version", provenance.version);
  file.set_attribute("revision", provenance.revision);
  file.set_attribute("device", provenance.device);
  file.set_attribute("isa", provenance.isa);
}

void ResultFile::create(const Provenance& provenance) const {
  file_.set_flag("complete", false);
  write_provenance(file_, scene_.text, provenance);
  file_.set_attribute("plan_members", std::int64_t(scene_.member_count()));
  // every attribute written later exists from the start, so that writing it changes bytes in place
  file_.set_attribute("members_done", std::int64_t(0));
  write_statistics({});
  const auto members = file_.create_group("members");
  create_member_columns(members, columns_, rows_);
  std::vector<hsize_t> all(rows_);
  std::iota(all.begin(), all.end(), hsize_t(0));
  members.create_column("done", ColumnType::flag, {rows_, 0, 0},
                        "TRUE when the row holds its finished member (all TRUE in a complete file)");
  members.write_rows("done", all, std::vector<signed char>(rows_, 0).data());
  if (shard_) {
    file_.set_attribute("shard_index", std::int64_t(shard_->index));
    file_.set_attribute("shard_count", std::int64_t(shard_->count));
    members.create_column("plan_index", ColumnType::int64, {rows_, 0, 0},
                          "the member's index in the whole plan (shard files only)");
    std::vector<std::int64_t> index(rows_);
    for (std::size_t k = 0; k < rows_; ++k) index[k] = std::int64_t(shard_->index - 1 + k * shard_->count);
    members.write_rows("plan_index", all, index.data());
  }
  file_.flush();
}

void ResultFile::write_rows(std::vector<hsize_t> rows, const std::vector<ensemble::Member>& members,
                            const std::vector<ensemble::MemberResult>& results) const {
  const auto group = file_.open_group("members");
  write_member_rows(group, columns_, rows, members, results);
  file_.flush();
  group.write_rows("done", rows, std::vector<signed char>(rows.size(), 1).data());
  file_.flush();
}

void ResultFile::write_results(const ensemble::MemberPlan& plan,
                               std::vector<ensemble::MemberResult> results) const {
  if (results.empty()) return;
  std::sort(results.begin(), results.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  std::vector<hsize_t> rows;
  std::vector<ensemble::Member> members;
  for (const auto& r : results) {
    rows.push_back(row_of(r.index));
    members.push_back(plan[r.index]);
  }
  write_rows(std::move(rows), members, results);
}

std::vector<char> ResultFile::done() const {
  const auto flags = file_.open_group("members").read_flags("done");
  return std::vector<char>(flags.begin(), flags.end());
}

void ResultFile::write_sweep(const std::vector<ensemble::Member>& members,
                             const ensemble::SweepOutcome& outcome) const {
  std::vector<hsize_t> rows;
  for (const auto& m : members) rows.push_back(row_of(m.index));
  write_rows(std::move(rows), members, outcome.results);
  finish(outcome.statistics);
}

void ResultFile::write_statistics(const ensemble::SweepStatistics& statistics) const {
  file_.set_attribute("wall_seconds", statistics.wall_seconds);
  file_.set_attribute("threads", std::int64_t(statistics.threads));
  file_.set_attribute("lane_width", std::int64_t(statistics.lane_width));
  file_.set_attribute("lane_occupancy", statistics.occupancy());
}

void ResultFile::keep_partial(std::size_t members_done, const ensemble::SweepStatistics& statistics) const {
  file_.set_attribute("members_done", std::int64_t(members_done));
  write_statistics(statistics);
  file_.flush();
}

void ResultFile::reserve(double bytes) const {
  if (!on_disk_) return;
  const int fd = ::open(file_.path().c_str(), O_WRONLY);
  if (fd < 0) return;
  struct stat status {};
  ::fstat(fd, &status);
  // twice the data and 1 MiB for the groups' metadata, beyond the file's end, the length unchanged
  const int failed =
      ::fallocate(fd, FALLOC_FL_KEEP_SIZE, status.st_size, off_t(2 * bytes) + (off_t(1) << 20));
  const int error = errno;
  ::close(fd);
  if (failed != 0 && error != EOPNOTSUPP)
    throw std::runtime_error("cannot reserve " + std::to_string(long(bytes / 1e6) + 1) +
                             " MB for /curves in " + file_.path() + ": " + std::strerror(error));
}

void ResultFile::finish(const ensemble::SweepStatistics& statistics) const {
  if (!shard_) write_curves_from_members(file_, scene_, [this](double bytes) { reserve(bytes); });
  file_.set_attribute("members_done", std::int64_t(rows_));
  write_statistics(statistics);
  file_.flush();
  file_.set_flag("complete", true);
  file_.flush();
}

}  // namespace rotorsweep::io
