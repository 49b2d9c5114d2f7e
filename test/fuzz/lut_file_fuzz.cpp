// Any bytes as a LUT file, read as `safecell luts info` reads one (the header and checksum) and
// as the service loads one (every section, against a small grid). A refusal is an InputError
// (LutFileError, FileError: the CLI's exit 2); anything else (a bad_alloc from a count, a read
// outside the mapping) is a finding.
// Mode byte 1: the rest gets a right file size field and checksum, so the checks behind the
// checksum (counts, the section table, every section's bounds) are explored too; any other
// mode: the bytes as they are.

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fuzz_targets.hpp"
#include "safecell/base/crc32.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/lut_files/lut_file.hpp"

namespace safecell::fuzz {
namespace {

std::vector<std::uint8_t> sealed(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint8_t> file(data, data + size);
  if (file.size() < kLutHeaderBytes) return file;
  const std::uint64_t bytes = file.size();
  for (std::size_t k = 0; k < 8; ++k) {
    file[kLutFileBytesOffset + k] = static_cast<std::uint8_t>(bytes >> (8 * k));
  }
  std::fill_n(file.begin() + kLutChecksumOffset, 4, std::uint8_t{0});
  const std::uint32_t checksum = crc32(file.data(), file.size());
  for (std::size_t k = 0; k < 4; ++k) {
    file[kLutChecksumOffset + k] = static_cast<std::uint8_t>(checksum >> (8 * k));
  }
  return file;
}

const CspaceGrid& small_grid() {
  static const CspaceGrid grid = [] {
    GridSpec spec;
    spec.m_max_m = 0.2;
    spec.joint_count = 2;
    for (std::uint32_t j = 0; j < 2; ++j) spec.joints[j] = {-1.0, 1.0, 0.5, true};
    return CspaceGrid::create(spec).value();
  }();
  return grid;
}

}  // namespace

int lut_file(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("safecell-fuzz-lut-" + std::to_string(::getpid()) + ".sclut");
  const std::vector<std::uint8_t> bytes = size > 0 && data[0] == 1
                                              ? sealed(data + 1, size - 1)
                                              : std::vector<std::uint8_t>(data, data + size);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
  }
  try {
    static_cast<void>(read_lut_file_summary(file));
  } catch (const InputError&) {
  }
  try {
    static_cast<void>(load_lut_file(file, small_grid(), std::nullopt));
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace safecell::fuzz

SAFECELL_FUZZ_ENTRY_POINT(lut_file)
