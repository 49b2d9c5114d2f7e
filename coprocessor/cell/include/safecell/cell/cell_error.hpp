#pragma once
// The one exception type of cell descriptions. Its message is a single line that names the file,
// the line, the field and the value, and says what was expected; the CLI prints it as it is.

#include <stdexcept>
#include <string>

#include "safecell/cell/cell_config.hpp"

namespace safecell {

class CellError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Builds "source:line: field: problem".
[[noreturn]] void throw_cell_error(const SourceLine& where, const std::string& field,
                                   const std::string& problem);

}  // namespace safecell
