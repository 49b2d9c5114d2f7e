#pragma once
// A sequence of forbidden maps with their grid, as `safecell bench` hands the demo's maps to the
// controller's benchmark program (the two never link each other's code: the coprocessor writes
// this format in coprocessor/verification/bench/src/map_sequence_writer.cpp, this side reads it).
// Little-endian:
//
//   "SCMAPS1\0"                      8 bytes
//   m_max_m                          f64
//   joint_count                      u32
//   per joint: lo_rad, hi_rad, l_m   f64 x 3, then discretised u8
//   map_count, cell_count            u32 x 2
//   per map: words_for(cell_count) words, u64 each (cell_bits.hpp order)
// Hosted code; throws std::runtime_error naming the file for anything malformed.

#include <cstdint>
#include <string>
#include <vector>

#include "safecell/cspace/grid_spec.hpp"

namespace safecell {

struct MapSequence {
  GridSpec grid;
  std::uint32_t cell_count = 0;
  std::vector<std::vector<std::uint64_t>> maps;
};

MapSequence read_map_sequence(const std::string& path);

}  // namespace safecell
