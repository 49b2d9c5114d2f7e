#pragma once
// The one exception type of cell descriptions. Its message is a single line that names the file,
// the line, the field and the value, and says what was expected; the CLI prints it as it is.

#include <stdexcept>
#include <string>

#include "safecell/cell/cell_config.hpp"
#include "safecell/errors/input_error.hpp"

namespace safecell {

class CellError : public InputError {
 public:
  using InputError::InputError;
};

// Builds "source:line: field: problem".
[[noreturn]] void throw_cell_error(const SourceLine& where, const std::string& field,
                                   const std::string& problem);

}  // namespace safecell
