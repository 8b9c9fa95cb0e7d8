// Reads the members of a result file or shard (README "Output file") back into MemberResults:
// every field the writer stores, so that writing them again gives the same datasets.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ensemble/member_plan.hpp"
#include "ensemble/member_result.hpp"
#include "ensemble/scene.hpp"
#include "io/hdf5_file.hpp"

namespace rotorsweep::io {

/// "<version> (revision <revision>)" of the program that wrote `file`.
std::string written_by(const Hdf5Location& file);

struct StoredMembers {
  std::vector<std::size_t> plan_index;          ///< the plan member of each result
  std::vector<ensemble::MemberResult> results;  ///< results[i].index == plan_index[i]
};

/// The members in `file`'s /members group: all of the plan in order for a whole result, the
/// members listed in /members/plan_index for a shard. `plan` is plan_members(scene) of the
/// file's own scene. Throws std::runtime_error naming the file for a column that is missing or
/// holds a value the writer never writes.
StoredMembers read_member_results(const Hdf5Location& file, const ensemble::Scene& scene,
                                  const std::vector<ensemble::Member>& plan);

}  // namespace rotorsweep::io
