// Reads the members of a result file, shard or partial file (docs/output.md "Output file")
// back into MemberResults, a block of rows at a time: every field the writer stores.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/scene.hpp"
#include "io/hdf5_file.hpp"

namespace rotorsweep::io {

/// What every file rotorsweep writes has, for the message that refuses another HDF5 file.
inline constexpr const char* rotorsweep_file_shape =
    "its files have the attributes version and complete, and a kind, or a scene and /members";
/// Whether `file` has what every file rotorsweep writes has (rotorsweep_file_shape).
bool is_rotorsweep_file(const Hdf5Location& file);

/// "<version> (revision <revision>)" of the program that wrote `file`.
std::string written_by(const Hdf5Location& file);

/// Rows [first, first + count) of `file`'s /members as results; MemberResult::index is the plan
/// index (the row itself, or /members/plan_index of a shard). `plan` is the file's own scene's.
/// With `keep` (count flags), only the rows it marks are read back (the others may hold anything).
/// Throws std::runtime_error naming the column for one that is missing or holds a value the
/// writer never writes.
std::vector<ensemble::MemberResult> read_member_rows(const Hdf5Location& file, const ensemble::Scene& scene,
                                                     const ensemble::MemberPlan& plan, std::size_t first,
                                                     std::size_t count, const char* keep = nullptr);

/// /members/done: 1 for the rows that hold a finished member.
std::vector<char> read_done(const Hdf5Location& file);

/// The number of rows of /members.
std::size_t member_rows(const Hdf5Location& file);

}  // namespace rotorsweep::io
