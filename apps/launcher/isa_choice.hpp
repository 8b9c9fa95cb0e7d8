// Which rotorsweep-<isa> binary the launcher runs: the one requested (ROTORSWEEP_ISA or --isa),
// or with "auto" the widest that is both built and runnable; an impossible request is an error.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rotorsweep::launcher {

struct IsaChoice {
  std::string isa;    ///< the set to run ("" when error is set)
  std::string error;  ///< why none can run, naming the request and the allowed values
};

/// `request`: "auto" or a set's name; `source`: where it came from ("ROTORSWEEP_ISA", "--isa");
/// `runnable`: what the CPU executes; `built`: the binaries present.
IsaChoice choose_isa(std::string_view request, std::string_view source,
                     const std::vector<std::string>& runnable, const std::vector<std::string>& built);

/// The binary of a set beside the launcher: <directory>/rotorsweep-<isa>.
std::filesystem::path isa_binary(const std::filesystem::path& directory, std::string_view isa);

/// The known sets whose binary is present (and executable) in `directory`, narrowest first.
std::vector<std::string> built_isas(const std::filesystem::path& directory);

/// The directory of the running executable.
std::filesystem::path executable_directory(const char* argv0);

/// "a, b, c" (or "none").
std::string joined(const std::vector<std::string>& names);

/// What a request may name: "auto" and the known sets, narrowest first.
std::vector<std::string> allowed_requests();

}  // namespace rotorsweep::launcher
