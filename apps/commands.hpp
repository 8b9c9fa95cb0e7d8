// The subcommands of the rotorsweep command line and their options.
// Each returns the process exit code.
#pragma once

#include <string>

namespace rotorsweep::apps {

struct TableOptions {
  std::string stepper = "rodas4";
  double rtol = 1e-9;
  std::string output;  ///< CSV path; empty: stdout only
};
int run_table(const TableOptions& options);

struct BenchKernelOptions {
  int rows = 20;
  int repeats = 5;
};
int run_bench_kernels(const BenchKernelOptions& options);

}  // namespace rotorsweep::apps
