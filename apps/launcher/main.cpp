// The `rotorsweep` command of a portable build: runs rotorsweep-<isa> for the widest instruction
// set this CPU executes, or the one a leading --isa or ROTORSWEEP_ISA names (exit 2 if it cannot).
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "apps/launcher/cpu_isas.hpp"
#include "apps/launcher/isa_choice.hpp"

int main(int argc, char** argv) {
  using namespace rotorsweep::launcher;
  std::string request = "auto", source = "ROTORSWEEP_ISA";
  if (const char* variable = std::getenv("ROTORSWEEP_ISA"); variable != nullptr && *variable != '\0')
    request = variable;
  std::vector<char*> arguments(argv, argv + argc);
  if (argc >= 2 && std::strcmp(argv[1], "--isa") == 0) {
    if (argc < 3) {
      std::fprintf(stderr, "rotorsweep: --isa needs a value; allowed: %s\n",
                   joined(allowed_requests()).c_str());
      return 2;
    }
    request = argv[2], source = "--isa";
    arguments.erase(arguments.begin() + 1, arguments.begin() + 3);
  } else if (argc >= 2 && std::strncmp(argv[1], "--isa=", 6) == 0) {
    request = argv[1] + 6, source = "--isa";
    arguments.erase(arguments.begin() + 1);
  }
  const auto directory = executable_directory(argv[0]);
  const auto choice = choose_isa(request, source, runnable_isas(), built_isas(directory));
  if (!choice.error.empty()) {
    std::fprintf(stderr, "rotorsweep: %s\n", choice.error.c_str());
    return 2;
  }
  const std::string binary = isa_binary(directory, choice.isa).string();
  arguments[0] = const_cast<char*>(binary.c_str());
  arguments.push_back(nullptr);
  ::execv(binary.c_str(), arguments.data());
  std::fprintf(stderr, "rotorsweep: cannot run %s: %s\n", binary.c_str(), std::strerror(errno));
  return 1;
}
