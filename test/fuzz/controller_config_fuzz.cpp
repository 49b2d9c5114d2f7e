// Any text as safecell-controller's configuration file. A refusal is a ControllerConfigError;
// anything else (a yaml-cpp exception that escaped, a crash) is a finding.

#include <string>

#include "fuzz_targets.hpp"
#include "safecell/controller/host/controller_config.hpp"

namespace safecell::fuzz {

int controller_config(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    static_cast<void>(parse_controller_config(text, "fuzz.yaml"));
  } catch (const ControllerConfigError&) {
  }
  return 0;
}

}  // namespace safecell::fuzz

SAFECELL_FUZZ_ENTRY_POINT(controller_config)
