// The columns of /members (docs/output.md "Output file"): name, type, shape, description and how a
// member's row is filled, so that creating the file and writing rows share one list.
#pragma once

#include <string>
#include <vector>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/scene.hpp"
#include "io/hdf5_file.hpp"
#include "io/table_columns.hpp"

namespace rotorsweep::io {

/// One column of /members, filled from a member and its result.
using MemberColumn = TableColumn<ensemble::Member, ensemble::MemberResult>;

/// Every column the scene's observables and options call for, in the order they are created.
std::vector<MemberColumn> member_columns(const ensemble::Scene& scene);

/// Periods in a row of /members/periods: the longest schedule the scene allows.
std::size_t period_series_width(const ensemble::Scene& scene);

/// Bytes one member's row takes in the file, over all columns.
double member_row_bytes(const std::vector<MemberColumn>& columns);

/// Creates the columns in /members (and /members/periods) with `rows` rows each.
void create_member_columns(const Hdf5Location& members, const std::vector<MemberColumn>& columns,
                           hsize_t rows);

}  // namespace rotorsweep::io
