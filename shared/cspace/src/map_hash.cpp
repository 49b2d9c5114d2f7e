#include "safecell/cspace/map_hash.hpp"

#include "safecell/cspace/cell_bits.hpp"

namespace safecell {

std::uint64_t map_block_hash(const std::uint64_t* words, CellIndex cell_count,
                             std::uint32_t block) noexcept {
  const std::uint32_t word_count = cell_bits::words_for(cell_count);
  std::uint64_t hash = map_block_hash_seed(block);
  const std::uint32_t first = block * kMapHashBlockWords;
  for (std::uint32_t w = first; w < first + kMapHashBlockWords; ++w) {
    hash = map_hash_mix(hash ^ (w < word_count ? words[w] : 0));
  }
  return hash;
}

std::uint64_t map_hash_of_blocks(const std::uint64_t* block_hashes, CellIndex cell_count) noexcept {
  std::uint64_t combined = 0;
  const std::uint32_t blocks = map_hash_blocks(cell_count);
  for (std::uint32_t b = 0; b < blocks; ++b) combined ^= block_hashes[b];
  return map_hash_from_combined(combined, cell_count);
}

std::uint64_t map_hash(const std::uint64_t* words, CellIndex cell_count) noexcept {
  std::uint64_t combined = 0;
  const std::uint32_t blocks = map_hash_blocks(cell_count);
  for (std::uint32_t b = 0; b < blocks; ++b) combined ^= map_block_hash(words, cell_count, b);
  return map_hash_from_combined(combined, cell_count);
}

void MapBlockHashes::refresh_all(const std::uint64_t* words) noexcept {
  refresh(words, 0, cell_count_);
}

void MapBlockHashes::refresh(const std::uint64_t* words, CellIndex begin, CellIndex end) noexcept {
  if (begin >= end) return;
  const std::uint32_t last = (end - 1) / kMapHashBlockCells;
  for (std::uint32_t b = begin / kMapHashBlockCells; b <= last; ++b) {
    hashes_[b] = map_block_hash(words, cell_count_, b);
  }
}

}  // namespace safecell
