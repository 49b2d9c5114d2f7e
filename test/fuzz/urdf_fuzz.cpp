// Any text as a URDF, through the project's loader (the tinyxml2 gate, urdfdom, the chain
// builder). Meshes are looked for in a folder that does not exist. A refusal is a RobotError;
// anything else is a finding.

#include <string>

#include "fuzz_targets.hpp"
#include "safecell/robot/robot_error.hpp"
#include "safecell/robot/urdf_loader.hpp"

namespace safecell::fuzz {

int urdf(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    static_cast<void>(parse_urdf(text, "fuzz.urdf", "/nonexistent"));
  } catch (const RobotError&) {
  }
  return 0;
}

}  // namespace safecell::fuzz

SAFECELL_FUZZ_ENTRY_POINT(urdf)
