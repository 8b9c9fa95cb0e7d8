// Test support: scene texts for the sweeper tests (the paper's reference members, small
// friction curves) and a scratch directory to write scenes and result files into.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace rotorsweep::testing {

/// The paper's table setting (N = 20, g = 0.0011, 2 + 2 periods) at the given A list, kinds and
/// tolerance; `extra` is appended (more sections).
inline std::string paper_scene(const std::string& A_list, const std::string& kinds, double rtol,
                               const std::string& extra = "") {
  char tolerances[96];
  std::snprintf(tolerances, sizeof tolerances, "rtol = %.17g\natol = %.17g\n", rtol, rtol * 1e-3);
  return "[model]\nrows = 20\n[drive]\ng = [0.0011]\n[sweep]\nA = " + A_list +
         "\n[initial]\nkinds = " + kinds + "\n[numerics]\n" + tolerances + extra;
}

/// A fresh directory under the system's temporary directory, named for the test.
inline std::filesystem::path scratch_directory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("rotorsweep-test-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::filesystem::path write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

}  // namespace rotorsweep::testing
