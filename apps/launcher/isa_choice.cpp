// The launcher's choice of binary (isa_choice.hpp): validation of the request against the known,
// runnable and built instruction sets, and where the per-set binaries live.
#include "apps/launcher/isa_choice.hpp"

#include <unistd.h>

#include <algorithm>

#include "apps/launcher/cpu_isas.hpp"

namespace rotorsweep::launcher {

namespace {

bool contains(const std::vector<std::string>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::string joined(const std::vector<std::string>& names) {
  if (names.empty()) return "none";
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

std::vector<std::string> allowed_requests() {
  std::vector<std::string> allowed{"auto"};
  allowed.insert(allowed.end(), known_isas.begin(), known_isas.end());
  return allowed;
}

IsaChoice choose_isa(std::string_view request, std::string_view source,
                     const std::vector<std::string>& runnable, const std::vector<std::string>& built) {
  const std::string said = std::string(source) + " = '" + std::string(request) + "'";
  if (request == "auto") {
    for (auto isa = known_isas.rbegin(); isa != known_isas.rend(); ++isa)
      if (contains(runnable, *isa) && contains(built, *isa)) return {std::string(*isa), ""};
    return {"", "none of the built instruction sets (" + joined(built) +
                    ") runs on this CPU (it runs: " + joined(runnable) + ")"};
  }
  if (std::find(known_isas.begin(), known_isas.end(), request) == known_isas.end())
    return {"", said + " is not an instruction set; allowed: " + joined(allowed_requests())};
  if (!contains(runnable, request))
    return {"", said + ": this CPU cannot execute it (it runs: " + joined(runnable) + ")"};
  if (!contains(built, request))
    return {"", said + ": this installation has no rotorsweep-" + std::string(request) +
                    " (built: " + joined(built) + ")"};
  return {std::string(request), ""};
}

std::filesystem::path isa_binary(const std::filesystem::path& directory, std::string_view isa) {
  return directory / ("rotorsweep-" + std::string(isa));
}

std::vector<std::string> built_isas(const std::filesystem::path& directory) {
  std::vector<std::string> built;
  for (const auto isa : known_isas)
    if (::access(isa_binary(directory, isa).c_str(), X_OK) == 0) built.emplace_back(isa);
  return built;
}

std::filesystem::path executable_directory(const char* argv0) {
  std::error_code error;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) return self.parent_path();
  return std::filesystem::absolute(argv0, error).parent_path();
}

}  // namespace rotorsweep::launcher
