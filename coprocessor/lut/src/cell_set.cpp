#include "safecell/lut/cell_set.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "safecell/lut/cpu_clones.hpp"

namespace safecell {
namespace {

constexpr std::uint64_t kAll = ~std::uint64_t{0};

// Bits from `first` (0..63) up to the word's end.
std::uint64_t from_bit(std::uint32_t first) { return kAll << first; }
// Bits below `end` (1..64).
std::uint64_t below_bit(std::uint32_t end) {
  return end == 64 ? kAll : (std::uint64_t{1} << end) - 1;
}

// Calls apply(word index, mask) for the words the range begin..end-1 touches.
template <typename Apply>
void for_range(CellIndex begin, CellIndex end, Apply apply) {
  if (begin >= end) return;
  const std::uint32_t first_word = begin >> 6;
  const std::uint32_t last_word = (end - 1) >> 6;
  if (first_word == last_word) {
    apply(first_word, from_bit(begin & 63) & below_bit(((end - 1) & 63) + 1));
    return;
  }
  apply(first_word, from_bit(begin & 63));
  for (std::uint32_t word = first_word + 1; word < last_word; ++word) apply(word, kAll);
  apply(last_word, below_bit(((end - 1) & 63) + 1));
}

}  // namespace

CellSet::CellSet(std::uint32_t cell_count)
    : cell_count_(cell_count), words_((static_cast<std::size_t>(cell_count) + 63) / 64, 0) {}

void CellSet::set_range(CellIndex begin, CellIndex end) {
  for_range(begin, end, [this](std::uint32_t word, std::uint64_t mask) { words_[word] |= mask; });
}

void CellSet::reset_range(CellIndex begin, CellIndex end) {
  for_range(begin, end, [this](std::uint32_t word, std::uint64_t mask) { words_[word] &= ~mask; });
}

bool CellSet::all_in_range(CellIndex begin, CellIndex end) const {
  bool all = true;
  for_range(begin, end, [&](std::uint32_t word, std::uint64_t mask) {
    all = all && (words_[word] & mask) == mask;
  });
  return all;
}

void CellSet::clear() { std::fill(words_.begin(), words_.end(), 0); }

void CellSet::fill() {
  clear();
  set_range(0, cell_count_);
}

SAFECELL_CPU_CLONES std::size_t CellSet::count() const {
  std::size_t total = 0;
  for (const std::uint64_t word : words_) total += static_cast<std::size_t>(std::popcount(word));
  return total;
}

bool CellSet::any() const {
  return std::any_of(words_.begin(), words_.end(), [](std::uint64_t word) { return word != 0; });
}

CellIndex CellSet::next_set(CellIndex from) const {
  if (from >= cell_count_) return cell_count_;
  std::size_t word = from >> 6;
  std::uint64_t bits = words_[word] & from_bit(from & 63);
  while (bits == 0) {
    if (++word == words_.size()) return cell_count_;
    bits = words_[word];
  }
  const auto found =
      static_cast<CellIndex>(word * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
  return std::min(found, cell_count_);
}

CellIndex CellSet::next_clear(CellIndex from, CellIndex limit) const {
  limit = std::min(limit, cell_count_);
  if (from >= limit) return limit;
  std::size_t word = from >> 6;
  const std::size_t last_word = (static_cast<std::size_t>(limit) - 1) >> 6;
  std::uint64_t bits = ~words_[word] & from_bit(from & 63);
  while (bits == 0) {
    if (++word > last_word) return limit;
    bits = ~words_[word];
  }
  const auto found =
      static_cast<CellIndex>(word * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
  return std::min(found, limit);
}

CellSet& CellSet::operator|=(const CellSet& other) {
  if (other.cell_count_ != cell_count_) throw std::invalid_argument("cell sets of different grids");
  for (std::size_t i = 0; i < words_.size(); ++i) words_[i] |= other.words_[i];
  return *this;
}

CellSet& CellSet::operator&=(const CellSet& other) {
  if (other.cell_count_ != cell_count_) throw std::invalid_argument("cell sets of different grids");
  for (std::size_t i = 0; i < words_.size(); ++i) words_[i] &= other.words_[i];
  return *this;
}

}  // namespace safecell
