// Test support: runs the rotorsweep executable with arguments and returns its exit code, everything
// it printed (stdout and stderr together) and its wall time, also when it is sent a signal mid-run.
#pragma once

#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

namespace rotorsweep::testing {

struct CliResult {
  int exit_code = -1;
  std::string output;
  double seconds = 0;  ///< wall time
};

namespace detail {

/// Runs a shell command that writes to `log` and returns its exit code, the log's text and its wall time.
inline CliResult run_logged(const std::string& command, const std::filesystem::path& log) {
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  CliResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  result.output.assign(std::istreambuf_iterator<char>(in), {});
  return result;
}

}  // namespace detail

/// `shell_prefix` runs first in the same shell (e.g. "ulimit -f 64; " to limit the file size).
inline CliResult run_cli(const std::string& arguments, const std::filesystem::path& scratch,
                         const std::string& shell_prefix = "") {
  const auto log = scratch / "cli-output.txt";
  return detail::run_logged("(" + shell_prefix + std::string(ROTORSWEEP_EXECUTABLE) + " " + arguments +
                                ") > '" + log.string() + "' 2>&1",
                            log);
}

/// A delay for sleep(1) after which a run is signalled part of the way through: a random fraction, 10 to
/// 20 %, of the wall time `whole_seconds` of the same run uninterrupted on as many threads or more (so the
/// same on a fast machine as on a slow one), different in every test run (report it).
inline std::string random_delay(double whole_seconds) {
  static std::mt19937 engine{std::random_device{}()};
  return std::to_string(std::uniform_real_distribution<double>(0.1, 0.2)(engine) * whole_seconds);
}

/// Runs the executable in the background and sends it `signal` ("INT", "TERM") after `delay`
/// (a sleep(1) argument, e.g. "0.5"); the exit code is the process's own.
inline CliResult run_cli_signalled(const std::string& arguments, const std::filesystem::path& scratch,
                                   const std::string& signal, const std::string& delay) {
  const auto log = scratch / "cli-output.txt";
  return detail::run_logged(std::string(ROTORSWEEP_EXECUTABLE) + " " + arguments + " > '" + log.string() +
                                "' 2>&1 & pid=$!; sleep " + delay + "; kill -" + signal + " $pid; wait $pid",
                            log);
}

}  // namespace rotorsweep::testing
