#pragma once
// `safecell cell info`: the C-space grid a cell file defines, per joint and in total.

#include <ostream>
#include <string>

namespace safecell {

struct CellInfoOptions {
  std::string cell_path;  // empty: the built-in default cell
  bool json = false;
};

// Prints the report; throws CellError for a cell file that cannot be used.
void run_cell_info(const CellInfoOptions& options, std::ostream& out);

}  // namespace safecell
