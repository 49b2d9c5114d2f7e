#pragma once
// A read-only view of the controller's forbidden map (map_store.hpp), held in one of two forms:
// dense (every word of the grid), or compressed: the grid in blocks of 512 cells, each free,
// forbidden, or mixed with its 8 words in a pool. A block the compressed store could not hold
// exactly (its pool was full) reads as forbidden. Look-up is O(1) in both.
// Thread context: the controller's cycle; valid until the next MapStore::offer() that applies an
// update or reset().

#include <cstdint>

#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

inline constexpr std::uint32_t kStoreBlockCells = 512;
inline constexpr std::uint32_t kStoreBlockWords = kStoreBlockCells / 64;

// A block's entry in the slot table: a pool index (below kDegradedSlot) or one of these.
inline constexpr std::uint32_t kFreeSlot = 0xFFFFFFFFu;
inline constexpr std::uint32_t kForbiddenSlot = 0xFFFFFFFEu;
// Forbidden because the pool had no room for the block's exact content: safe, and counted.
inline constexpr std::uint32_t kDegradedSlot = 0xFFFFFFFDu;

constexpr bool is_pool_slot(std::uint32_t slot) noexcept { return slot < kDegradedSlot; }

constexpr std::uint32_t store_blocks_for(CellIndex cell_count) noexcept {
  return static_cast<std::uint32_t>((std::uint64_t{cell_count} + kStoreBlockCells - 1) /
                                    kStoreBlockCells);
}

class MapView {
 public:
  // A compressed map: a slot per block, and the pool the slots point into.
  MapView(const std::uint32_t* slots, const std::uint64_t* pool, CellIndex cell_count) noexcept
      : slots_(slots), pool_(pool), dense_(nullptr), is_dense_(false), cell_count_(cell_count) {}
  // A dense map: words_for(cell_count) words.
  MapView(const std::uint64_t* dense, CellIndex cell_count) noexcept
      : slots_(nullptr), pool_(nullptr), dense_(dense), is_dense_(true), cell_count_(cell_count) {}

  CellIndex cell_count() const noexcept { return cell_count_; }

  // Word w of the map (cells 64 w .. 64 w + 63); a compressed forbidden block's words are all
  // ones, also past the last cell, which the searches below never look at.
  std::uint64_t word(std::uint32_t w) const noexcept {
    if (is_dense_) return dense_[w];
    const std::uint32_t slot = slots_[w / kStoreBlockWords];
    if (is_pool_slot(slot))
      return pool_[std::uint64_t{slot} * kStoreBlockWords + w % kStoreBlockWords];
    return slot == kFreeSlot ? 0 : cell_bits::kAllBits;
  }

  // The map as a dense bitmap (cell_bits.hpp) into words[0 .. words_for(cell_count())): for
  // snapshots and checks, O(cells / 64), not for the cycle.
  void copy_dense(std::uint64_t* words) const noexcept {
    const std::uint32_t count = cell_bits::words_for(cell_count_);
    for (std::uint32_t w = 0; w < count; ++w) words[w] = word(w);
    const std::uint32_t tail = cell_count_ & 63;
    if (tail != 0) words[count - 1] &= (std::uint64_t{1} << tail) - 1;
  }

  // Precondition for all three: cells < cell_count(), begin <= end <= cell_count().
  bool forbidden(CellIndex cell) const noexcept {
    return ((word(cell >> 6) >> (cell & 63)) & 1U) != 0;
  }
  // The first forbidden cell in [begin, end); end when none.
  CellIndex first_forbidden(CellIndex begin, CellIndex end) const noexcept {
    return cell_bits::next_set_in([this](std::uint32_t w) { return word(w); }, begin, end);
  }
  // The last forbidden cell in [begin, end); end when none.
  CellIndex last_forbidden(CellIndex begin, CellIndex end) const noexcept {
    return cell_bits::last_set_in([this](std::uint32_t w) { return word(w); }, begin, end);
  }

 private:
  const std::uint32_t* slots_;
  const std::uint64_t* pool_;
  const std::uint64_t* dense_;
  // Which form, said outright rather than read off a null pointer: the static analyser cannot
  // follow "slots_ null means dense_ set" and reports a null dereference.
  bool is_dense_;
  CellIndex cell_count_;
};

}  // namespace safecell
