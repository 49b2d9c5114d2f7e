#include "safecell/cellsets/cell_set.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "safecell/compute/cpu_clones.hpp"
#include "safecell/cspace/cell_bits.hpp"

namespace safecell {

CellSet::CellSet(std::uint32_t cell_count)
    : cell_count_(cell_count), words_(cell_bits::words_for(cell_count), 0) {}

void CellSet::set_range(CellIndex begin, CellIndex end) {
  cell_bits::set_range(words_.data(), begin, end);
}

void CellSet::reset_range(CellIndex begin, CellIndex end) {
  cell_bits::clear_range(words_.data(), begin, end);
}

bool CellSet::all_in_range(CellIndex begin, CellIndex end) const {
  return cell_bits::all_set(words_.data(), begin, end);
}

void CellSet::clear() { std::fill(words_.begin(), words_.end(), 0); }

void CellSet::fill() {
  clear();
  set_range(0, cell_count_);
}

// The loop is written out here, not taken from cell_bits::count: the compiler did not inline
// that into the CPU clones, and every word went through the library's software popcount (a
// quarter of a 6 cm grid's fusion). The last word is masked: words() lets callers write it.
SAFECELL_CPU_CLONES std::size_t CellSet::count() const {
  if (words_.empty()) return 0;
  std::size_t total = 0;
  for (std::size_t w = 0; w + 1 < words_.size(); ++w) {
    total += static_cast<std::size_t>(std::popcount(words_[w]));
  }
  const std::uint32_t tail = cell_count_ % 64;
  const std::uint64_t last_mask = tail == 0 ? ~std::uint64_t{0} : (std::uint64_t{1} << tail) - 1;
  return total + static_cast<std::size_t>(std::popcount(words_.back() & last_mask));
}

bool CellSet::any() const {
  return std::any_of(words_.begin(), words_.end(), [](std::uint64_t word) { return word != 0; });
}

CellIndex CellSet::next_set(CellIndex from) const {
  return cell_bits::next_set(words_.data(), from, cell_count_);
}

CellIndex CellSet::next_clear(CellIndex from, CellIndex limit) const {
  return cell_bits::next_clear(words_.data(), from, std::min(limit, cell_count_));
}

CellSet& CellSet::operator|=(const CellSet& other) {
  if (other.cell_count_ != cell_count_) throw std::invalid_argument("cell sets of different grids");
  for (std::size_t i = 0; i < words_.size(); ++i) words_[i] |= other.words_[i];
  return *this;
}

SAFECELL_CPU_CLONES std::size_t CellSet::assign_union(const CellSet& a, const CellSet& b) {
  if (a.cell_count_ != cell_count_ || b.cell_count_ != cell_count_) {
    throw std::invalid_argument("cell sets of different grids");
  }
  if (words_.empty()) return 0;
  std::uint64_t* const to = words_.data();
  const std::uint64_t* const from_a = a.words_.data();
  const std::uint64_t* const from_b = b.words_.data();
  std::size_t total = 0;
  const std::size_t last = words_.size() - 1;
  for (std::size_t w = 0; w < last; ++w) {
    to[w] = from_a[w] | from_b[w];
    total += static_cast<std::size_t>(std::popcount(to[w]));
  }
  to[last] = from_a[last] | from_b[last];
  const std::uint32_t tail = cell_count_ % 64;
  const std::uint64_t last_mask = tail == 0 ? ~std::uint64_t{0} : (std::uint64_t{1} << tail) - 1;
  return total + static_cast<std::size_t>(std::popcount(to[last] & last_mask));
}

CellSet& CellSet::operator&=(const CellSet& other) {
  if (other.cell_count_ != cell_count_) throw std::invalid_argument("cell sets of different grids");
  for (std::size_t i = 0; i < words_.size(); ++i) words_[i] &= other.words_[i];
  return *this;
}

}  // namespace safecell
