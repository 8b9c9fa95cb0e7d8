// take_csv_output: the OutputTarget of a CSV table, with the table's own first line as what it may
// replace without --force (docs/cli.md "Other commands"), and the signal handler that removes it.
#include "csv_output.hpp"

#include <iostream>
#include <vector>

namespace rotorsweep::apps {

bool take_csv_output(const std::string& output, std::string_view first_line, bool force,
                     std::optional<io::OutputTarget>& target, std::optional<RemoveOnSignal>& on_signal) {
  if (output.empty()) return true;
  try {
    target.emplace(output, std::vector<std::string>{},
                   io::Replaceable::text_starting_with(std::string(first_line)), force);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << " (-o)\n";
    return false;
  }
  on_signal.emplace(*target);
  return true;
}

}  // namespace rotorsweep::apps
