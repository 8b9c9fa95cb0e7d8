// Test support: runs the rotorsweep executable with arguments and returns its exit code and
// everything it printed (stdout and stderr together).
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace rotorsweep::testing {

struct CliResult {
  int exit_code = -1;
  std::string output;
};

/// `shell_prefix` runs first in the same shell (e.g. "ulimit -f 64; " to limit the file size).
inline CliResult run_cli(const std::string& arguments, const std::filesystem::path& scratch,
                         const std::string& shell_prefix = "") {
  const auto log = scratch / "cli-output.txt";
  const std::string command = "(" + shell_prefix + std::string(ROTORSWEEP_EXECUTABLE) + " " + arguments +
                              ") > '" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  CliResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  result.output.assign(std::istreambuf_iterator<char>(in), {});
  return result;
}

}  // namespace rotorsweep::testing
