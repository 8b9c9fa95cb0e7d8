// Test support: the dataset paths of a result file (/members, /members/periods, /curves,
// /curves/attractors), for comparing two files dataset by dataset.
#pragma once

#include <string>
#include <vector>

#include "io/hdf5_file.hpp"

namespace rotorsweep::testing {

inline std::vector<std::string> dataset_paths(const io::Hdf5Location& file) {
  std::vector<std::string> paths;
  for (const std::string group :
       {"members", "members/periods", "curves", "curves/attractors", "curve", "series"}) {
    if (!file.has(group)) continue;
    const auto location = file.open_group(group);
    for (const auto& name : location.members())
      if (name != "periods" && name != "attractors") paths.push_back(group + "/" + name);
  }
  return paths;
}

}  // namespace rotorsweep::testing
