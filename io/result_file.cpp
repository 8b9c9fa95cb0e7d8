// Writing a sweep's results: pre-sized /members columns filled row by row with the done mask
// written after the rows it marks, /curves from the file at the end, the completion flag last.
#include "io/result_file.hpp"

#include <algorithm>

#include "io/curve_table.hpp"
#include "io/output_target.hpp"

namespace rotorsweep::io {

ResultFile::ResultFile(const std::string& path, const ensemble::Scene& scene, const Provenance& provenance,
                       const std::optional<ShardLabel>& shard)
    : ResultFile(Hdf5Location::create_file(creating_path(path)), scene, shard) {
  settle_on_disk(path, [&] { create(provenance); });
}

ResultFile ResultFile::in_memory(const ensemble::Scene& scene, const Provenance& provenance) {
  ResultFile file(Hdf5Location::create_in_memory(provenance.scene_path + ".h5"), scene, std::nullopt);
  file.create(provenance);
  return file;
}

ResultFile ResultFile::reopen(const std::string& path, const ensemble::Scene& scene) {
  auto location = Hdf5Location::open_file_for_writing(path);
  check_file(location, scene);
  auto shard = shard_label(location);
  ResultFile file(std::move(location), scene, shard);
  file.adopt_reopened();
  return file;
}

void ResultFile::check_file(const Hdf5Location& file, const ensemble::Scene& scene) {
  const hsize_t rows = check_table(file, "", scene.member_count());
  check_table_columns(file.open_group("members"), member_columns(scene), rows, file.path(), "/members/");
}

double ResultFile::finishing_bytes(const ensemble::Scene& scene, bool shard) {
  return shard ? 0.0
               : reserved_bytes(curves_data_bytes(scene, assumed_attractor_labels, assumed_label_length));
}

ResultFile::ResultFile(Hdf5Location file, const ensemble::Scene& scene, std::optional<ShardLabel> shard)
    : MemberTableFile(std::move(file), scene.member_count(), shard),
      scene_(scene),
      columns_(member_columns(scene)) {}

void ResultFile::create(const Provenance& provenance) const {
  const auto members = create_table(scene_.text, provenance);
  // the row model is dimensionless: its datasets say units "1" (angles "rad") in these scales
  file_.set_attribute("scaled_units", std::string("energies in ε = μ0 m0² N / (4π P³), time in 1/ṽ (a drive "
                                                  "period is 2π), angles in rad (docs/model.md)"));
  write_statistics({});
  create_member_columns(members, columns_, rows_);
}

PackedRow ResultFile::pack(const ensemble::Member& member, const ensemble::MemberResult& result) const {
  return {result.index, pack_table_row(columns_, member, result)};
}

void ResultFile::write_packed(std::vector<PackedRow> packed) const {
  if (packed.empty()) return;
  std::sort(packed.begin(), packed.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  std::vector<hsize_t> rows;
  std::vector<const PackedRow*> order;
  for (const auto& p : packed) {
    rows.push_back(row_of(p.index));
    order.push_back(&p);
  }
  write_packed_rows(file_.open_group("members"), columns_, rows, order);
  mark_done(rows);
}

void ResultFile::write_results(const ensemble::MemberPlan& plan,
                               const std::vector<ensemble::MemberResult>& results) const {
  std::vector<PackedRow> packed;
  for (const auto& r : results) packed.push_back(pack(plan[r.index], r));
  write_packed(std::move(packed));
}

void ResultFile::write_statistics(const ensemble::SweepStatistics& statistics) const {
  file_.set_attribute("wall_seconds", statistics.wall_seconds);
  file_.set_attribute("threads", std::int64_t(statistics.threads));
  file_.set_attribute("lane_width", std::int64_t(statistics.lane_width));
  file_.set_attribute("lane_occupancy", statistics.occupancy());
}

ensemble::SweepStatistics ResultFile::recorded_statistics(int threads, std::size_t lane_width) const {
  ensemble::SweepStatistics recorded;
  recorded.wall_seconds = file_.attribute_double("wall_seconds");
  recorded.threads = recorded.wall_seconds > 0 ? int(file_.attribute_double("threads")) : threads;
  recorded.lane_width =
      recorded.wall_seconds > 0 ? std::size_t(file_.attribute_double("lane_width")) : lane_width;
  recorded.lane_steps_busy = file_.attribute_double("lane_occupancy");  // a ratio: busy over one total
  recorded.lane_steps_total = 1;
  return recorded;
}

void ResultFile::keep_partial(std::size_t members_done, const ensemble::SweepStatistics& statistics) const {
  set_members_done(members_done);
  write_statistics(statistics);
  file_.flush();
}

void ResultFile::finish(const ensemble::SweepStatistics& statistics) const {
  if (!shard_) write_curves_from_members(file_, scene_, [this](double bytes) { reserve(bytes, "/curves"); });
  set_members_done(rows_);
  write_statistics(statistics);
  set_complete();
}

}  // namespace rotorsweep::io
