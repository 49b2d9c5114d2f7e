#include "safecell/cellsets/cell_slices.hpp"

#include <stdexcept>
#include <string>

namespace safecell {
namespace {

// The 64 bits of `words` from bit `first` on (bits past the last word read as 0).
std::uint64_t bits_from(const std::vector<std::uint64_t>& words, std::size_t first) {
  const std::size_t word = first / 64;
  const std::size_t shift = first % 64;
  std::uint64_t bits = words[word] >> shift;
  if (shift != 0 && word + 1 < words.size()) bits |= words[word + 1] << (64 - shift);
  return bits;
}

}  // namespace

CellSet cells_in_every_slice(const CellSet& cells, std::uint32_t slice_cells,
                             std::uint32_t slices) {
  if (static_cast<std::uint64_t>(slice_cells) * slices != cells.cell_count()) {
    throw std::invalid_argument(std::to_string(slices) + " slices of " +
                                std::to_string(slice_cells) + " cells in a set of " +
                                std::to_string(cells.cell_count()));
  }
  CellSet common(slice_cells);
  std::vector<std::uint64_t>& out = common.words();
  for (std::size_t word = 0; word < out.size(); ++word) {
    std::uint64_t all = ~std::uint64_t{0};
    // Most words of a pixel's set are empty: stop at the first slice that clears them all.
    for (std::uint32_t slice = 0; slice < slices && all != 0; ++slice) {
      all &= bits_from(cells.words(), std::size_t{slice} * slice_cells + word * 64);
    }
    out[word] = all;
  }
  // The last word also read the start of the next slice: keep only this slice's cells.
  if (slice_cells % 64 != 0 && !out.empty()) {
    out.back() &= (std::uint64_t{1} << (slice_cells % 64)) - 1;
  }
  return common;
}

CellSet repeat_slice(const CellSet& slice, std::uint32_t slices) {
  const std::uint64_t cells = std::uint64_t{slice.cell_count()} * slices;
  if (cells > UINT32_MAX) throw std::invalid_argument("repeated slice past 2^32 cells");
  CellSet repeated(static_cast<std::uint32_t>(cells));
  std::vector<std::uint64_t>& out = repeated.words();
  const std::vector<std::uint64_t>& in = slice.words();
  for (std::uint32_t k = 0; k < slices; ++k) {
    for (std::size_t word = 0; word < in.size(); ++word) {
      // Bits past the slice's last cell are 0, so nothing spills into the next copy.
      const std::size_t first = std::size_t{k} * slice.cell_count() + word * 64;
      const std::size_t shift = first % 64;
      out[first / 64] |= in[word] << shift;
      if (shift != 0 && first / 64 + 1 < out.size())
        out[first / 64 + 1] |= in[word] >> (64 - shift);
    }
  }
  return repeated;
}

}  // namespace safecell
