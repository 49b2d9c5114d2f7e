#pragma once
// The built-in default cell of the paper (default_cell.yaml, compiled in).

#include <string_view>

#include "safecell/cell/cell_config.hpp"

namespace safecell {

inline constexpr const char* kDefaultCellSource = "built-in default cell";

std::string_view default_cell_yaml();
CellConfig default_cell();

}  // namespace safecell
