// Test support: the dataset paths of a result file (/members, /members/periods, /curves,
// /curves/attractors; a slider's /curve and /series), two files compared dataset by dataset, and a
// dataset replaced by one of another shape (an edited file).
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

/// Replaces dataset `name` of the file at `path` by one of doubles (zeros) with dimensions `dims`: a file
/// edited, or written for another scene.
inline void replace_dataset(const std::filesystem::path& path, const std::string& name,
                            const std::vector<hsize_t>& dims) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(file >= 0);
  REQUIRE(H5Ldelete(file, name.c_str(), H5P_DEFAULT) >= 0);
  const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
  const hid_t set =
      H5Dcreate2(file, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  hsize_t values = 1;
  for (const hsize_t d : dims) values *= d;
  const std::vector<double> zeros(values, 0.0);
  CHECK(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, zeros.data()) >= 0);
  H5Dclose(set);
  H5Sclose(space);
  H5Fclose(file);
}

}  // namespace rotorsweep::testing
