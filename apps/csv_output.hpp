// The CSV file a command writes beside what it prints (`couplings -o`, `table -o`): checked before any
// work, replaced without --force only where it is the command's own table, removed on a signal.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "io/output_target.hpp"
#include "remove_on_signal.hpp"

namespace rotorsweep::apps {

/// Takes `output` (nothing when it is empty): an io::OutputTarget that replaces an existing file
/// without `force` only when it starts with `first_line` (the table's own first line), and a
/// RemoveOnSignal for it. False when the path is refused: the message is said, the command exits 2.
bool take_csv_output(const std::string& output, std::string_view first_line, bool force,
                     std::optional<io::OutputTarget>& target, std::optional<RemoveOnSignal>& on_signal);

}  // namespace rotorsweep::apps
