#pragma once
// The controller's forbidden map, compressed, and how map updates reach it.
//
// The grid is cut into blocks of 512 cells (map_view.hpp). A block is free, forbidden, or mixed;
// only mixed blocks take memory: 64 bytes each from a pool whose size is fixed at init. Two slot
// tables make the double buffer: an update is written into the working table (blocks it changes
// get fresh pool blocks; unchanged ones are shared with the held map), and the tables swap only
// when the update is whole and its hash matches. A reader of view() never sees half an update.
//
// Updates arrive as chunks (map_chunk.hpp) in grid order, so the store rebuilds each block's
// exact words in a scratch buffer as the chunks stream past, hashes them (map_hash.hpp: one hash
// per 512-cell block, the map hash their XOR) before storing, and then keeps them mixed, or all
// free / all forbidden. When the pool has no room for a mixed block, the block is stored as
// forbidden ("degraded"): the map only gains forbidden cells, and the count says so. The hash
// still checks the exact content, so a keyframe always verifies; a delta that changes part of a
// degraded block has no exact base there and is refused (MapRefusal::kBaseInexact), so the link
// asks for a keyframe.
//
// Memory: the caller's (MapStoreStorage), sized by MapStoreLayout from the grid and the pool size;
// nothing is allocated. Cost per update: O(runs + blocks it changes) for a delta, O(blocks) for a
// keyframe.
// Thread context: one thread, the controller's cycle (which also polls the link); not
// synchronised. No allocation, no recursion, bounded loops.

#include <cstddef>
#include <cstdint>

#include "safecell/controller/map_view.hpp"
#include "safecell/cspace/map_hash.hpp"
#include "safecell/cspace/map_update_sequence.hpp"

namespace safecell {

struct MapStoreLayout {
  CellIndex cell_count = 0;
  std::uint32_t blocks = 0;       // blocks of 512 cells (also the map hash's blocks)
  std::uint32_t pool_blocks = 0;  // mixed blocks the pool holds (the held map's and an update's)

  static constexpr MapStoreLayout of(CellIndex cell_count, std::uint32_t pool_blocks) noexcept {
    return {cell_count, store_blocks_for(cell_count), pool_blocks};
  }
  // The bytes of all the arrays of MapStoreStorage.
  constexpr std::size_t bytes() const noexcept {
    return std::size_t{blocks} * (4 * 3 + 8 * 2) +
           std::size_t{pool_blocks} * (kStoreBlockWords * 8 + 4);
  }
};

// The default pool. A small grid (up to 4096 blocks, 2 M cells) gets room for two whole maps of
// mixed blocks: its blocks are nearly all mixed (97 % on the default cell's grid with the demo's
// maps), so compression does not pay there and exactness does. A larger grid gets one and a half
// blocks per grid block: the demo's maps upsampled to the 6 cm grid mix up to three quarters of
// its blocks (safecell-controller-bench), which leaves room for an update's changes. A map with
// more mixed blocks than fit is held with some blocks degraded (forbidden, counted); a smaller
// pool is an integrator's trade of memory against those.
constexpr std::uint32_t default_pool_blocks(CellIndex cell_count) noexcept {
  const std::uint32_t blocks = store_blocks_for(cell_count);
  const std::uint32_t pool = blocks <= 4096 ? 2 * blocks : blocks + blocks / 2;
  return pool < 16 ? 16 : pool;
}

// The arrays a MapStore works in, each of the size its comment names (layout fields).
struct MapStoreStorage {
  std::uint32_t* slots[2];        // blocks each
  std::uint64_t* pool;            // pool_blocks * kStoreBlockWords
  std::uint32_t* free_blocks;     // pool_blocks
  std::uint32_t* changed_blocks;  // blocks: the blocks the update being collected changed
  std::uint64_t* changed_hashes;  // blocks: their new block hashes
  std::uint64_t* block_hashes;    // blocks: the held map's block hashes
};

// The arrays of a MapStore as static storage sized at compile time, for targets without a heap:
// `static StaticMapStoreMemory<kLayout> memory;` (zero-initialised, in bss) then
// `MapStore store(kLayout, memory.storage());`.
template <const MapStoreLayout& kLayout>
struct StaticMapStoreMemory {
  std::uint32_t slots[2][kLayout.blocks];
  std::uint64_t pool[std::size_t{kLayout.pool_blocks} * kStoreBlockWords];
  std::uint32_t free_blocks[kLayout.pool_blocks];
  std::uint32_t changed_blocks[kLayout.blocks];
  std::uint64_t changed_hashes[kLayout.blocks];
  std::uint64_t block_hashes[kLayout.blocks];

  MapStoreStorage storage() noexcept {
    return {{slots[0], slots[1]}, pool, free_blocks, changed_blocks, changed_hashes, block_hashes};
  }
};

class MapStore {
 public:
  // Starts with no map (version 0, every cell forbidden). Precondition (checked): every array of
  // `storage` is there and layout.cell_count > 0.
  MapStore(const MapStoreLayout& layout, const MapStoreStorage& storage) noexcept;
  MapStore(const MapStore&) = delete;
  MapStore& operator=(const MapStore&) = delete;

  // One chunk of a keyframe or delta; capture_ns is the capture time of the frame that carried it
  // (the controller's clock). The held map's capture time is the oldest of its update's chunks.
  MapOffer offer(const MapChunkHeader& header, const std::uint8_t* runs, std::size_t runs_size,
                 std::uint64_t capture_ns) noexcept;

  // Forgets the held map (a new session): version 0, every cell forbidden.
  void reset() noexcept;

  MapView view() const noexcept {
    return {storage_.slots[held_], storage_.pool, layout_.cell_count};
  }
  std::uint64_t version() const noexcept { return version_; }  // 0: no map
  std::uint64_t hash() const noexcept { return hash_; }
  std::uint64_t capture_ns() const noexcept { return capture_ns_; }
  CellIndex cell_count() const noexcept { return layout_.cell_count; }
  const MapStoreLayout& layout() const noexcept { return layout_; }

  // The held map's blocks by kind, and how often a mixed block found the pool full (all updates).
  std::uint32_t mixed_blocks() const noexcept { return layout_.pool_blocks - free_count_; }
  std::uint32_t degraded_blocks() const noexcept { return degraded_blocks_; }
  std::uint64_t pool_overflows() const noexcept { return pool_overflows_; }

 private:
  MapOffer drop(const MapChunkHeader& header, MapRefusal refusal) noexcept;
  void begin_stream(MapChunkKind kind, std::uint64_t capture_ns) noexcept;
  void abandon() noexcept;
  void commit(std::uint64_t version, std::uint64_t hash) noexcept;
  bool apply_runs(const MapChunkView& chunk) noexcept;
  void seek(std::uint32_t block, bool whole) noexcept;
  void pass_until(std::uint32_t block) noexcept;
  void finish_loaded() noexcept;
  void held_words(std::uint32_t block, std::uint64_t* out) noexcept;
  std::uint64_t block_hash(std::uint32_t block, const std::uint64_t* words) const noexcept;
  void store(std::uint32_t block, const std::uint64_t* words) noexcept;
  std::uint64_t valid_bits(std::uint32_t block, std::uint32_t word) const noexcept;

  MapStoreLayout layout_;
  MapStoreStorage storage_;
  int held_ = 0;
  std::uint32_t free_count_ = 0;  // storage_.free_blocks[0 .. free_count_) are unused
  std::uint32_t degraded_blocks_ = 0;
  std::uint64_t pool_overflows_ = 0;
  std::uint64_t version_ = 0;
  std::uint64_t hash_ = 0;
  std::uint64_t capture_ns_ = 0;
  std::uint64_t combined_ = 0;  // the XOR of the held map's block hashes

  // The update being collected.
  MapUpdateSequence sequence_;
  bool keyframe_ = false;
  bool inexact_ = false;  // it needed the words of a degraded block
  std::uint64_t update_capture_ns_ = 0;
  std::uint32_t changed_count_ = 0;    // changed_blocks / changed_hashes [0 .. changed_count_)
  std::uint64_t update_combined_ = 0;  // combined_ with the changed blocks' hashes swapped in
  std::uint32_t next_block_ = 0;       // blocks below this are final in the working table
  bool loaded_ = false;                // scratch_ holds block next_block_, being written
  std::uint64_t scratch_[kStoreBlockWords]{};
};

}  // namespace safecell
