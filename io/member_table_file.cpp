// The kind-independent rows of a streamed result file: creation with the done mask and a shard's plan
// indices, rows marked done only after they are on disk, reserved space for the finishing writes.
#include "io/member_table_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <numeric>
#include <stdexcept>

#include "io/output_target.hpp"
#include "io/table_columns.hpp"

namespace rotorsweep::io {

namespace {

/// Bytes reserved for the metadata of the finishing writes' groups and datasets (object headers,
/// attributes, B-tree nodes).
constexpr double metadata_reserve = 1 << 20;

}  // namespace

void write_provenance(const Hdf5Location& file, const std::string& scene_text, const Provenance& provenance) {
  file.set_attribute("scene", scene_text);
  file.set_attribute("scene_path", provenance.scene_path);
  file.set_attribute("version", provenance.version);
  file.set_attribute("revision", provenance.revision);
  file.set_attribute("device", provenance.device);
  file.set_attribute("isa", provenance.isa);
}

double reserved_bytes(double data_bytes) { return 2 * data_bytes + metadata_reserve; }

MemberTableFile::MemberTableFile(Hdf5Location file, std::size_t plan_members, std::optional<ShardLabel> shard)
    : file_(std::move(file)), shard_(shard) {
  rows_ = shard ? (plan_members + shard->count - shard->index) / shard->count : plan_members;
}

std::optional<ShardLabel> MemberTableFile::shard_label(const Hdf5Location& file) {
  if (!file.has_attribute("shard_index")) return std::nullopt;
  const double index = file.attribute_double("shard_index"),
               count = file.has_attribute("shard_count") ? file.attribute_double("shard_count") : 0;
  if (!(index >= 1 && index <= count && count <= 1e9) || index != std::floor(index) ||
      count != std::floor(count)) {
    char stated[96];
    std::snprintf(stated, sizeof stated, "shard_index %g and shard_count %g", index, count);
    throw std::runtime_error("'" + file.path() + "': its " + stated +
                             " do not name a shard I/N with 1 <= I <= N <= 1e9");
  }
  return ShardLabel{
      std::size_t(index), std::size_t(count),
      file.has_attribute("plan_members") ? std::size_t(file.attribute_double("plan_members")) : 0};
}

hsize_t MemberTableFile::check_table(const Hdf5Location& file, const std::string& kind,
                                     std::size_t plan_members) {
  const std::string path = "'" + file.path() + "'";
  const std::string stated = file.has_attribute("kind") ? file.attribute_string("kind") : std::string();
  if (stated != kind)
    throw std::runtime_error(path + " says kind = '" + stated + "', not " +
                             (kind.empty() ? "a row sweep's file (no kind)" : "'" + kind + "'"));
  if (!file.has_attribute("plan_members") || file.attribute_double("plan_members") != double(plan_members))
    throw std::runtime_error(path + ": its attribute plan_members is not its scene's " +
                             std::to_string(plan_members) + " members");
  const auto shard = shard_label(file);
  const hsize_t rows = shard ? (plan_members + shard->count - shard->index) / shard->count : plan_members;
  const auto column = [](std::string name, ColumnType type) {
    TableColumn<> c;
    c.name = std::move(name);
    c.type = type;
    return c;
  };
  std::vector<TableColumn<>> table{column("done", ColumnType::flag)};
  if (shard) table.push_back(column("plan_index", ColumnType::int64));
  check_table_columns(file.open_group("members"), table, rows, file.path(), "/members/");
  return rows;
}

hsize_t MemberTableFile::row_of(std::size_t plan_index) const {
  return shard_ ? (plan_index - (shard_->index - 1)) / shard_->count : plan_index;
}

std::size_t MemberTableFile::plan_index_of(std::size_t row) const {
  return shard_ ? shard_->index - 1 + row * shard_->count : row;
}

std::vector<char> MemberTableFile::done() const {
  const auto flags = file_.open_group("members").read_flags("done");
  return std::vector<char>(flags.begin(), flags.end());
}

void MemberTableFile::add_writer_isa(const std::string& isa) const {
  std::string list = file_.has_attribute("isa") ? file_.attribute_string("isa") : std::string();
  for (std::size_t begin = 0; begin <= list.size();) {
    const std::size_t end = std::min(list.find(", ", begin), list.size());
    if (list.substr(begin, end - begin) == isa) return;
    begin = end + 2;
  }
  file_.set_attribute("isa", list.empty() ? isa : list + ", " + isa);
  file_.flush();
}

Hdf5Location MemberTableFile::create_table(const std::string& scene_text,
                                           const Provenance& provenance) const {
  file_.set_flag("complete", false);
  write_provenance(file_, scene_text, provenance);
  file_.set_attribute("plan_members", std::int64_t(shard_ ? shard_->plan_members : rows_));
  // every attribute written later exists from the start, so that writing it changes bytes in place
  file_.set_attribute("members_done", std::int64_t(0));
  auto members = file_.create_group("members");
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
    for (std::size_t k = 0; k < rows_; ++k) index[k] = std::int64_t(plan_index_of(k));
    members.write_rows("plan_index", all, index.data());
  }
  return members;
}

void MemberTableFile::settle_on_disk(const std::string& path, const std::function<void()>& write_new) {
  // created whole under a hidden name (creating_path), then in place at once; a failure leaves nothing
  std::error_code error;
  try {
    write_new();
    file_.flush();
    file_.close();
  } catch (...) {
    try {
      file_.close();
    } catch (const std::exception&) {  // the write's failure is the one to report
    }
    std::filesystem::remove(creating_path(path), error);
    throw;
  }
  std::filesystem::rename(creating_path(path), path, error);
  if (error)
    throw std::runtime_error("cannot move the new file into place as '" + path + "': " + error.message());
  file_ = Hdf5Location::open_file_for_writing(path);
  on_disk_ = true;
}

void MemberTableFile::adopt_reopened() {
  on_disk_ = true;
  const auto marked = done();
  rows_done_ = std::size_t(std::count(marked.begin(), marked.end(), 1));
}

void MemberTableFile::mark_done(const std::vector<hsize_t>& rows) const {
  file_.flush();
  file_.open_group("members").write_rows("done", rows, std::vector<signed char>(rows.size(), 1).data());
  rows_done_ += rows.size();
  set_members_done(rows_done_);  // in place: a killed run's file says what it holds
  file_.flush();
}

void MemberTableFile::set_members_done(std::size_t count) const {
  file_.set_attribute("members_done", std::int64_t(count));
}

void MemberTableFile::set_complete() const {
  file_.flush();
  file_.set_flag("complete", true);
  file_.flush();
}

void MemberTableFile::reserve(double bytes, const std::string& what) const {
  if (!on_disk_) return;
  const int fd = ::open(file_.path().c_str(), O_WRONLY);
  if (fd < 0) return;
  struct stat status {};
  ::fstat(fd, &status);
  // beyond the file's end, the length unchanged
  const int failed = ::fallocate(fd, FALLOC_FL_KEEP_SIZE, status.st_size, off_t(reserved_bytes(bytes)));
  const int error = errno;
  ::close(fd);
  if (failed != 0 && error != EOPNOTSUPP)
    throw std::runtime_error("cannot reserve " + std::to_string(long(reserved_bytes(bytes) / 1e3) + 1) +
                             " kB for " + what + " in " + file_.path() + ": " + std::strerror(error));
}

}  // namespace rotorsweep::io
