// `rotorsweep --version`: the program identity, the instruction set of the running binary and,
// in a portable build, the sets this CPU runs and the binaries beside this one.
#include "apps/launcher/cpu_isas.hpp"
#include "apps/launcher/isa_choice.hpp"
#include "build_info.hpp"
#include "commands.hpp"
#include "ensemble/engine/instruction_set.hpp"

namespace rotorsweep::apps {

std::string version_text(const char* argv0) {
  const auto isa = ensemble::instruction_set();
  std::string text = "rotorsweep " + program_identity() + "\ninstruction set: " + isa.name + " (" + isa.simd +
                     ", " + std::to_string(isa.lanes) + " doubles per SIMD lane)";
  if (isa.name != "native") {
    const auto directory = launcher::executable_directory(argv0);
    text += "\nthis CPU runs: " + launcher::joined(launcher::runnable_isas()) +
            "; built: " + launcher::joined(launcher::built_isas(directory)) +
            " (the rotorsweep launcher runs the widest; ROTORSWEEP_ISA or --isa forces one)";
  }
  return text;
}

}  // namespace rotorsweep::apps
