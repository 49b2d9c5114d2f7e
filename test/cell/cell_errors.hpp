#pragma once
// What the cell tests check: the one-line message a cell file earns at each stage.

#include <string>

#include "safecell/cell/cell_error.hpp"

namespace safecell::test {

// The message of the CellError that `stage` throws, or "(no error)".
template <typename Stage>
std::string cell_error_of(Stage&& stage) {
  try {
    stage();
  } catch (const CellError& error) {
    return error.what();
  }
  return "(no error)";
}

// `text` with the first `from` replaced by `to` (the test's own text: `from` is there).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

}  // namespace safecell::test
