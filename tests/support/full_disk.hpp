// Test support: a command whose disk fills up mid-run (a private tmpfs of 4 MiB, filled by another
// writer once the run has created its partial file) exits 1 naming the full disk, and resumes to the whole run.
#pragma once

#include <catch2/catch.hpp>
#include <cstddef>
#include <filesystem>
#include <string>

#include "io/hdf5_file.hpp"
#include "support/cli.hpp"
#include "support/result_datasets.hpp"

namespace rotorsweep::testing {

/// `rotorsweep COMMAND SCENE -q ARGUMENTS -o OUT.h5` (a run or slider scan of `members` members) with
/// OUT.h5 on a 4 MiB file system of its own, filled by another writer while the run is held stopped the
/// moment it has created its partial file (run_cli_filling_disk, without -q): exit 1 naming the full disk and --resume, no
/// complete file there, a partial file with members not done, and --resume of it ending in the whole
/// run's datasets. Skipped with a warning where no private tmpfs can be mounted.
inline void check_full_disk_resumes(const std::string& command, const std::filesystem::path& scene,
                                    const std::string& arguments, std::size_t members,
                                    const std::filesystem::path& dir) {
  const auto small = dir / "small";
  const std::string mount = private_tmpfs(small, "4m");
  if (mount.empty()) {
    WARN("skipped: no private tmpfs mount here (unshare -rm and mount -t tmpfs must work)");
    return;
  }
  const std::string base = command + " '" + scene.string() + "' -q ";
  const auto whole = run_cli(base + "-o '" + (dir / "whole.h5").string() + "'", dir);
  REQUIRE(whole.exit_code == 0);
  const auto full = run_cli_filling_disk(
      mount, command + " '" + scene.string() + "' " + arguments + " -o '" + (small / "out.h5").string() + "'",
      small, "out.h5.partial", dir);
  INFO(full.output);
  CHECK(full.exit_code == 1);
  CHECK_THAT(full.output, Catch::Contains("No space left on device") && Catch::Contains("--resume"));
  CHECK_THAT(full.output, !Catch::Contains("out.h5\n"));  // no complete file in the small file system
  const auto partial = dir / "out.h5.partial";
  REQUIRE(std::filesystem::exists(partial));
  {
    const auto file = io::Hdf5Location::open_file(partial.string());
    CHECK_FALSE(file.attribute_flag("complete"));
    std::size_t done = 0;
    for (const auto flag : file.open_group("members").read_flags("done")) done += flag != 0;
    CHECK(done < members);
  }
  const auto resumed = run_cli(base + "-o '" + (dir / "out.h5").string() + "' --resume", dir);
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  check_same_datasets(dir / "whole.h5", dir / "out.h5");
}

}  // namespace rotorsweep::testing
