// Any text as a cell file: read, and when it reads, made into a cell model. A refusal is an
// InputError (exit 2); any other exception, a crash or a sanitizer report is a finding.

#include <string>

#include "fuzz_targets.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/errors/input_error.hpp"

namespace safecell::fuzz {

int cell_file(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    CellConfig config = parse_cell_yaml(text, "fuzz.yaml", "/nonexistent");
    // A URDF path would be read from this machine's disk: only the built-in arm is modelled.
    if (config.robot && config.robot->urdf.rfind(kBuiltinRobotPrefix, 0) != 0) return 0;
    static_cast<void>(load_cell_model(std::move(config)));
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace safecell::fuzz

SAFECELL_FUZZ_ENTRY_POINT(cell_file)
