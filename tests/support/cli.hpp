// Test support: runs the rotorsweep executable with arguments and returns its exit code, everything
// it printed (stdout and stderr together) and its wall time, also when it is sent a signal mid-run or
// its disk fills up.
#pragma once

#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "test_paths.hpp"

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

/// The start of a command that mounts a private tmpfs of `size` at `at` (unshare -rm sh -c "mount … && ",
/// the commands that follow close the quote), or "" where this machine cannot mount one.
inline std::string private_tmpfs(const std::filesystem::path& at, const std::string& size) {
  std::filesystem::create_directories(at);
  const std::string mount =
      "unshare -rm sh -c \"mount -t tmpfs -o size=" + size + " tmpfs '" + at.string() + "' && ";
  return std::system((mount + "true\" 2>/dev/null").c_str()) == 0 ? mount : "";
}

/// Runs the executable with `arguments` (without -q) in the mount namespace of `mount` (private_tmpfs's, at
/// `disk`) and fills that disk once the run has printed its first line (its header, printed once its
/// partial file is created): the run is stopped (SIGSTOP) the moment the line is there, another writer
/// fills the disk (16 MiB at most, whatever disk it lands on), and the run continues (SIGCONT) into the full disk. Events, not a clock, order the
/// three, so the run meets the full disk with members still to write on any machine. Then copies the
/// file `kept` from the disk into `scratch` (where it exists) and appends the disk's listing to the output.
inline CliResult run_cli_filling_disk(const std::string& mount, const std::string& arguments,
                                      const std::filesystem::path& disk, const std::string& kept,
                                      const std::filesystem::path& scratch) {
  const auto log = scratch / "cli-output.txt";
  // the braces keep the mount in the foreground: `mount && run &` would background the mount too
  const std::string command =
      mount + "{ rm -f '" + log.string() + "'; " + std::string(ROTORSWEEP_EXECUTABLE) + " " + arguments +
      " > '" + log.string() + "' 2>&1 & pid=\\$!; while [ ! -s '" + log.string() +
      "' ] && kill -0 \\$pid 2>/dev/null; do :; done; kill -STOP \\$pid 2>/dev/null; head -c 16777216 /dev/zero > '" +
      (disk / "filler").string() + "' 2>/dev/null; kill -CONT \\$pid 2>/dev/null; wait \\$pid; rc=\\$?; cp '" +
      (disk / kept).string() + "' '" + (scratch / kept).string() + "'; ls '" + disk.string() + "' >> '" +
      log.string() + "'; exit \\$rc; }\"";
  return detail::run_logged(command, log);
}

}  // namespace rotorsweep::testing
