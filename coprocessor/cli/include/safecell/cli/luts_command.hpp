#pragma once
// `safecell luts build` and `safecell luts info`: the look-up tables of a cell (model mode), built
// into a folder (a file per fingerprint, as the cache keeps them), and what a LUT file holds.

#include <ostream>
#include <string>

namespace safecell {

struct LutsBuildOptions {
  std::string cell_path;       // empty: the built-in default cell
  std::string out_dir;         // empty: the cache folder
  double ball_radius_m = 0.0;  // size of the balls covering the robot; 0: the cell's
  double padding_m = 0.02;
  unsigned threads = 0;
  bool force = false;  // build even when the folder holds the tables already
  bool json = false;
  // Cells whose LUT-2 entries are compared with their silhouettes computed directly after the
  // build (pixel_table_check.hpp); 0: none.
  std::uint32_t verify_cells = 0;
  std::uint64_t seed = 1;  // of the cells sampled
};

struct LutsInfoOptions {
  std::string path;  // a LUT file, or a folder of them
  bool json = false;
};

// Returns 1 when the verification found a mismatch, 0 otherwise.
int run_luts_build(const LutsBuildOptions& options, std::ostream& out, std::ostream& err);
// A file: throws LutFileError when it is not a usable LUT file. A folder (such as the cache, which
// keeps the files of earlier versions and settings): reports every usable file, names each
// refused one and why on `err`, and returns kExitBadInput when there was one (0 otherwise);
// throws std::invalid_argument when it holds no usable file at all.
int run_luts_info(const LutsInfoOptions& options, std::ostream& out, std::ostream& err);

}  // namespace safecell
