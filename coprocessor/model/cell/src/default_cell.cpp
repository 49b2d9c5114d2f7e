#include "safecell/cell/default_cell.hpp"

#include "safecell/cell/cell_file.hpp"

namespace safecell {

extern const char* const kDefaultCellYaml;  // generated from default_cell.yaml

std::string_view default_cell_yaml() { return kDefaultCellYaml; }

CellConfig default_cell() { return parse_cell_yaml(default_cell_yaml(), kDefaultCellSource); }

}  // namespace safecell
