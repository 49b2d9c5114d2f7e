#pragma once
// A set of C-space cells as a bitset in cell index order (joint 0 fastest): the per-camera
// suspicious sets, the critical and forbidden maps. A row of cells along joint 0 is a run of
// consecutive bits, so a box of cells is set with a few word operations per row. The storage is
// owned here; the word algorithms are shared/cspace/cell_bits.hpp, the same the controller uses.

#include <cstdint>
#include <vector>

#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

class CellSet {
 public:
  CellSet() = default;
  explicit CellSet(std::uint32_t cell_count);

  [[nodiscard]] std::uint32_t cell_count() const { return cell_count_; }

  [[nodiscard]] bool test(CellIndex cell) const { return cell_bits::test(words_.data(), cell); }
  void set(CellIndex cell) { cell_bits::set(words_.data(), cell); }
  void reset(CellIndex cell) { cell_bits::clear(words_.data(), cell); }
  // Sets cells begin..end-1 (precondition: begin <= end <= cell_count()).
  void set_range(CellIndex begin, CellIndex end);
  // Whether every cell begin..end-1 is set.
  [[nodiscard]] bool all_in_range(CellIndex begin, CellIndex end) const;
  // Clears cells begin..end-1.
  void reset_range(CellIndex begin, CellIndex end);
  void clear();
  void fill();

  [[nodiscard]] std::size_t count() const;
  [[nodiscard]] bool any() const;
  // The first set cell at or after `from`; cell_count() when none.
  [[nodiscard]] CellIndex next_set(CellIndex from) const;
  // The first cell not set at or after `from`; cell_count() when none.
  [[nodiscard]] CellIndex next_clear(CellIndex from) const { return next_clear(from, cell_count_); }
  // The same, looking only before `limit`: min(limit, next_clear(from)), without reading past it.
  [[nodiscard]] CellIndex next_clear(CellIndex from, CellIndex limit) const;

  CellSet& operator|=(const CellSet& other);
  CellSet& operator&=(const CellSet& other);
  // This set becomes a | b in one pass (what fusion does each cycle: forbidden = critical |
  // static); returns count() of the result. Throws std::invalid_argument for another grid.
  std::size_t assign_union(const CellSet& a, const CellSet& b);

  [[nodiscard]] const std::vector<std::uint64_t>& words() const { return words_; }
  [[nodiscard]] std::vector<std::uint64_t>& words() { return words_; }

  friend bool operator==(const CellSet&, const CellSet&) = default;

 private:
  std::uint32_t cell_count_ = 0;
  std::vector<std::uint64_t> words_;
};

}  // namespace safecell
