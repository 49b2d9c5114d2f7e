#pragma once
// Sets of C-space cells as bits over caller storage: cell c is bit c % 64 of word c / 64, in the
// grid's linear order (joint 0 fastest). Both sides use these: the coprocessor's CellSet (fusion)
// and the controller's map store. Bits past the last cell are kept zero by every function here,
// so counts and map hashes are canonical.
// Preconditions (the callers own the storage): begin <= end <= limit <= the cells the words hold.
// Real-time safe: no allocation, O(words touched), inline so hot loops compile to word operations.

#include <bit>
#include <cstdint>

#include "safecell/cspace/cspace_grid.hpp"

namespace safecell::cell_bits {

inline constexpr std::uint64_t kAllBits = ~std::uint64_t{0};

constexpr std::uint32_t words_for(std::uint32_t cell_count) noexcept {
  return static_cast<std::uint32_t>((std::uint64_t{cell_count} + 63) / 64);
}

inline bool test(const std::uint64_t* words, CellIndex cell) noexcept {
  return ((words[cell >> 6] >> (cell & 63)) & 1U) != 0;
}
inline void set(std::uint64_t* words, CellIndex cell) noexcept {
  words[cell >> 6] |= std::uint64_t{1} << (cell & 63);
}
inline void clear(std::uint64_t* words, CellIndex cell) noexcept {
  words[cell >> 6] &= ~(std::uint64_t{1} << (cell & 63));
}

// Calls apply(word index, mask) for each word the cells begin..end-1 touch, with the mask of those
// cells in that word.
template <typename Apply>
void for_each_word(CellIndex begin, CellIndex end, Apply apply) noexcept {
  if (begin >= end) return;
  const std::uint32_t first_word = begin >> 6;
  const std::uint32_t last_word = (end - 1) >> 6;
  const std::uint64_t first_mask = kAllBits << (begin & 63);
  const std::uint32_t last_bits = ((end - 1) & 63) + 1;
  const std::uint64_t last_mask = last_bits == 64 ? kAllBits : (std::uint64_t{1} << last_bits) - 1;
  if (first_word == last_word) {
    apply(first_word, first_mask & last_mask);
    return;
  }
  apply(first_word, first_mask);
  for (std::uint32_t word = first_word + 1; word < last_word; ++word) apply(word, kAllBits);
  apply(last_word, last_mask);
}

inline void set_range(std::uint64_t* words, CellIndex begin, CellIndex end) noexcept {
  for_each_word(begin, end, [words](std::uint32_t w, std::uint64_t mask) { words[w] |= mask; });
}
inline void clear_range(std::uint64_t* words, CellIndex begin, CellIndex end) noexcept {
  for_each_word(begin, end, [words](std::uint32_t w, std::uint64_t mask) { words[w] &= ~mask; });
}
inline bool all_set(const std::uint64_t* words, CellIndex begin, CellIndex end) noexcept {
  bool all = true;
  for_each_word(begin, end, [&](std::uint32_t w, std::uint64_t mask) {
    all = all && (words[w] & mask) == mask;
  });
  return all;
}
inline std::uint64_t count(const std::uint64_t* words, CellIndex begin, CellIndex end) noexcept {
  std::uint64_t total = 0;
  for_each_word(begin, end, [&](std::uint32_t w, std::uint64_t mask) {
    total += static_cast<std::uint64_t>(std::popcount(words[w] & mask));
  });
  return total;
}

// The first cell at or after `from`, before `limit`, whose bit in word_of(w) is set; `limit` when
// none. word_of lets callers search derived sets (a ^ b, b & ~a) without a temporary.
template <typename WordOf>
CellIndex next_set_in(WordOf word_of, CellIndex from, CellIndex limit) noexcept {
  if (from >= limit) return limit;
  std::uint32_t word = from >> 6;
  const std::uint32_t last_word = (limit - 1) >> 6;
  std::uint64_t bits = word_of(word) & (kAllBits << (from & 63));
  while (bits == 0) {
    if (++word > last_word) return limit;
    bits = word_of(word);
  }
  const CellIndex found = word * 64 + static_cast<CellIndex>(std::countr_zero(bits));
  return found < limit ? found : limit;
}

// The last cell in [from, limit) whose bit in word_of(w) is set; `limit` when none.
template <typename WordOf>
CellIndex last_set_in(WordOf word_of, CellIndex from, CellIndex limit) noexcept {
  if (from >= limit) return limit;
  const std::uint32_t first_word = from >> 6;
  std::uint32_t word = (limit - 1) >> 6;
  const std::uint32_t top_bits = ((limit - 1) & 63) + 1;
  std::uint64_t bits = word_of(word);
  if (top_bits < 64) bits &= (std::uint64_t{1} << top_bits) - 1;
  while (bits == 0) {
    if (word == first_word) return limit;
    bits = word_of(--word);
  }
  const CellIndex found = word * 64 + 63 - static_cast<CellIndex>(std::countl_zero(bits));
  return found >= from ? found : limit;
}

inline CellIndex next_set(const std::uint64_t* words, CellIndex from, CellIndex limit) noexcept {
  return next_set_in([words](std::uint32_t w) { return words[w]; }, from, limit);
}
inline CellIndex next_clear(const std::uint64_t* words, CellIndex from, CellIndex limit) noexcept {
  return next_set_in([words](std::uint32_t w) { return ~words[w]; }, from, limit);
}

}  // namespace safecell::cell_bits
