#pragma once
// One file per camera set holding a LutSet, loaded by mmap (DESIGN.md §3, "LUTs").
//
// Layout (little-endian; every section starts on an 8-byte boundary; offsets are 64-bit):
//   header (80 bytes): magic "SCLUT\r\n\x1a", format version, header size, the set's fingerprint
//     and grid fingerprint, source (model/recorded), feature grid columns and rows, camera count,
//     cell count, section count, section table offset, file size, CRC-32 of the whole file
//     computed with this field zero.
//   section table: per section its kind, camera (or 0xFFFF), pyramid level, robot part, offset
//     and size in bytes.
//   sections: once, the robot parts' bodies (first and end body per part, 64-bit each) and per
//     part its name; per camera its name and (recorded sets) LUT-1 offsets and rectangles; per
//     camera and part its statistics, LUT-2 offsets and strips for the pixels and for each block
//     level, the same for their differences to the left and the upper neighbour; once, the
//     static-obstacle cells as 64-bit words.
// A file of another version, another fingerprint or grid, a bad checksum, or sections that do not
// fit is refused with LutFileError naming the file and what was wrong; nothing is guessed.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/tables/lut_set.hpp"

namespace safecell {

// 5: LUT-2 per robot part.
inline constexpr std::uint32_t kLutFileVersion = 5;

// Where the header keeps the file's size (64-bit) and its CRC-32, in bytes from the start: a
// tool that writes a file by hand (the fuzz target's sealing mode) fills these.
inline constexpr std::size_t kLutHeaderBytes = 80;
inline constexpr std::size_t kLutFileBytesOffset = 64;
inline constexpr std::size_t kLutChecksumOffset = 72;

class LutFileError : public InputError {
 public:
  LutFileError(const std::filesystem::path& path, const std::string& problem)
      : InputError(path.string() + ": " + problem) {}
};

// What a file says about itself, read without the tables (for `luts info`).
struct LutFileSummary {
  std::uint32_t version = 0;
  std::uint64_t fingerprint = 0;
  std::uint64_t grid_fingerprint = 0;
  LutSource source = LutSource::kModel;
  int columns = 0;
  int rows = 0;
  std::uint32_t camera_count = 0;
  std::uint32_t cell_count = 0;
  std::uint64_t file_bytes = 0;
  std::vector<RobotPart> parts;

  // Each camera's figures are summed over the parts.
  struct Camera {
    std::string name;
    std::uint64_t cell_table_bytes = 0;   // LUT-1 (0 in a model-mode set)
    std::uint64_t pixel_table_bytes = 0;  // LUT-2 with its block levels
    std::uint64_t block_table_bytes = 0;  // of which the block levels
    int block_levels = 0;
    std::uint64_t strips = 0;  // of the pixels' LUT-2
    std::uint64_t covered_pairs = 0;
  };
  std::vector<Camera> cameras;
};

// Writes the set atomically (temporary file, then rename). Throws FileError when it cannot.
void write_lut_file(const std::filesystem::path& path, const LutSet& set);

// Maps the file and checks it whole (checksum included) against the grid; with
// expected_fingerprint, the set's fingerprint must equal it. The tables are views into the
// mapping, which lives as long as any of them.
[[nodiscard]] LutSet load_lut_file(const std::filesystem::path& path, const CspaceGrid& grid,
                                   std::optional<std::uint64_t> expected_fingerprint);

// Reads and checks the header and checksum only.
[[nodiscard]] LutFileSummary read_lut_file_summary(const std::filesystem::path& path);

}  // namespace safecell
