// Test support: the dataset paths of a result file (/members, /members/periods, /curves,
// /curves/attractors; a slider's /curve and /series), and two files compared dataset by dataset.
#pragma once

#include <catch2/catch.hpp>
#include <filesystem>
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

/// Every dataset of `actual` holds the bytes of `expected`'s, and `actual` is complete.
inline void check_same_datasets(const std::filesystem::path& expected, const std::filesystem::path& actual) {
  const auto a = io::Hdf5Location::open_file(expected.string());
  const auto b = io::Hdf5Location::open_file(actual.string());
  const auto paths = dataset_paths(a);
  CHECK(paths == dataset_paths(b));
  for (const auto& path : paths) {
    INFO(path);
    CHECK(a.read_bytes(path) == b.read_bytes(path));
  }
  CHECK(b.attribute_flag("complete"));
}

}  // namespace rotorsweep::testing
