#include "safecell/cell/cell_error.hpp"

namespace safecell {

void throw_cell_error(const SourceLine& where, const std::string& field,
                      const std::string& problem) {
  std::string message = where.source;
  if (where.line > 0) message += ":" + std::to_string(where.line);
  message += ": " + field + ": " + problem;
  throw CellError(message);
}

}  // namespace safecell
