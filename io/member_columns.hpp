// The columns of /members (README "Output file"): name, type, shape, description and how a
// member's row is filled, so that creating the file and writing rows share one list.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ensemble/engine/member_result.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/scene.hpp"
#include "io/hdf5_file.hpp"

namespace rotorsweep::io {

/// One column of /members (`name` is a path below it, e.g. "periods/dissipation"). Exactly one
/// of real (writes max(1, width) values), integer and text fills a row, matching `type`.
struct MemberColumn {
  std::string name;
  ColumnType type = ColumnType::float64;
  hsize_t width = 0;  ///< 0: one value per member
  std::size_t text_length = 0;
  std::string description;
  std::function<void(const ensemble::Member&, const ensemble::MemberResult&, double*)> real;
  std::function<std::int64_t(const ensemble::Member&, const ensemble::MemberResult&)> integer;
  std::function<std::string(const ensemble::Member&, const ensemble::MemberResult&)> text;
};

/// Every column the scene's observables and options call for, in the order they are created.
std::vector<MemberColumn> member_columns(const ensemble::Scene& scene);

/// Periods in a row of /members/periods: the longest schedule the scene allows.
std::size_t period_series_width(const ensemble::Scene& scene);

/// Bytes one member's row takes in the file, over all columns.
double member_row_bytes(const std::vector<MemberColumn>& columns);

/// Creates the columns in /members (and /members/periods) with `rows` rows each.
void create_member_columns(const Hdf5Location& members, const std::vector<MemberColumn>& columns,
                           hsize_t rows);

/// Writes results[i] of members[i] into row rows[i] of every column (rows ascending).
void write_member_rows(const Hdf5Location& members, const std::vector<MemberColumn>& columns,
                       const std::vector<hsize_t>& rows, const std::vector<ensemble::Member>& plan_members,
                       const std::vector<ensemble::MemberResult>& results);

}  // namespace rotorsweep::io
