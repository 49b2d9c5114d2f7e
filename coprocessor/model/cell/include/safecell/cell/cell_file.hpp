#pragma once
// Reading a cell description from YAML. Unknown fields are refused (a misspelt field would
// otherwise be silently ignored), and so are missing fields and values of the wrong type.

#include <filesystem>
#include <string>
#include <string_view>

#include "safecell/cell/cell_config.hpp"

namespace safecell {

// Throws CellError for malformed YAML and for missing, unknown or mistyped fields. Relative
// paths in the file are taken from base_directory. Values are checked for sense when the cell
// model and its grid are built: see load_cell_model() and make_grid().
CellConfig parse_cell_yaml(std::string_view text, const std::string& source,
                           const std::filesystem::path& base_directory = {});

// As parse_cell_yaml(), reading the file first; a file that cannot be read is a CellError too.
CellConfig load_cell_file(const std::filesystem::path& path);

// The cell file at `path`, or the built-in default cell when `path` is empty (the commands'
// --cell option).
CellConfig load_cell_file_or_default(const std::string& path);

}  // namespace safecell
