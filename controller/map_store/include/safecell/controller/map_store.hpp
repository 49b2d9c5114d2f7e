#pragma once
// The controller's forbidden map, and how map updates reach it.
//
// The grid is cut into blocks of 512 cells (map_view.hpp), the unit of the map hash (map_hash.hpp:
// one hash per block, the map hash their XOR) and of every change. The store is a double buffer:
// an update is written into the working side (blocks it changes; unchanged ones stay as the held
// map has them), and the sides swap only when the update is whole and its hash matches. A reader
// of view() never sees half an update.
//
// Two forms, chosen by the layout:
// - dense (the default): both sides hold every word of the grid. Real maps mix nearly every block
//   (measured: 97 % of the default cell's blocks with the demo's maps, up to 99 % of the 6 cm
//   grid's 32,156 with its own fused maps), so nothing smaller holds two of them exactly.
// - compressed: a block is free, forbidden, or mixed; only mixed blocks take memory, 64 bytes each
//   from a pool whose size is fixed at init, and two slot tables point into it (blocks an update
//   does not change are shared with the held map). For a controller whose memory is smaller than
//   a dense double buffer, or maps that are mostly whole free or forbidden blocks. When the pool
//   has no room for a mixed block, the block is stored as forbidden ("degraded"): the map only
//   gains forbidden cells, and the count says so. The hash still checks the exact content, so a
//   keyframe always verifies; a delta that changes part of a degraded block has no exact base
//   there and is refused (MapRefusal::kBaseInexact), so the link asks for a keyframe.
//
// Updates arrive as chunks (map_chunk.hpp) in grid order, so the store rebuilds each block's
// exact words in a scratch buffer as the chunks stream past and hashes them before storing.
//
// Work in slices. An update costs O(runs + blocks it changes) for a delta and O(blocks) for a
// keyframe, more than a control cycle can spare on a fine grid. So the store does it in slices of
// a bounded amount of work: accept() takes a chunk in O(1), and work(budget) goes on with it until
// the budget is spent, across as many calls (control cycles) as it needs. The swap itself is O(1);
// bringing the other side level with the new map afterwards (or undoing a refused update) is more
// work for later slices. The map a reader sees changes only at the swap, so slicing the work
// delays a map but never tears one; the map's measured age includes the delay.
//
// Memory: the caller's (MapStoreStorage), sized by MapStoreLayout from the grid and the form;
// nothing is allocated.
// Thread context: one thread, the controller's cycle (which also polls the link); not
// synchronised. No allocation, no recursion, bounded loops; reset() is O(blocks) (a new session,
// while the robot is held anyway).

#include <cstddef>
#include <cstdint>

#include "safecell/controller/map_view.hpp"
#include "safecell/cspace/map_hash.hpp"
#include "safecell/cspace/map_update_sequence.hpp"
#include "safecell/cspace/run_coding.hpp"

namespace safecell {

struct MapStoreLayout {
  CellIndex cell_count = 0;
  std::uint32_t blocks = 0;       // blocks of 512 cells (also the map hash's blocks)
  std::uint32_t pool_blocks = 0;  // compressed: mixed blocks the pool holds (both sides')
  bool dense = false;

  // The default form for a grid: dense (see above; a compressed pool with room for two maps of
  // mixed blocks takes 164 bytes per block against the dense form's 128).
  static constexpr MapStoreLayout of(CellIndex cell_count) noexcept {
    return {cell_count, store_blocks_for(cell_count), 0, true};
  }
  // The compressed form with a pool of `pool_blocks` mixed blocks.
  static constexpr MapStoreLayout compressed(CellIndex cell_count,
                                             std::uint32_t pool_blocks) noexcept {
    return {cell_count, store_blocks_for(cell_count), pool_blocks, false};
  }
  // The words of each side of the dense form: whole blocks.
  constexpr std::size_t dense_words() const noexcept {
    return dense ? std::size_t{blocks} * kStoreBlockWords : 0;
  }
  // The words of the dense form's bitset of changed blocks.
  constexpr std::size_t changed_bits_words() const noexcept {
    return dense ? (std::size_t{blocks} + 63) / 64 : 0;
  }
  // The blocks of each per-block array of the compressed form.
  constexpr std::size_t table_blocks() const noexcept { return dense ? 0 : blocks; }
  // The bytes of all the arrays of MapStoreStorage.
  constexpr std::size_t bytes() const noexcept {
    return 2 * dense_words() * 8 + changed_bits_words() * 8 + table_blocks() * (4 * 3 + 8 * 2) +
           std::size_t{pool_blocks} * (kStoreBlockWords * 8 + 4);
  }
};

// The arrays a MapStore works in, each of the size its comment names (layout functions); the
// arrays of the other form are null.
struct MapStoreStorage {
  // Dense.
  std::uint64_t* sides[2];      // dense_words() each
  std::uint64_t* changed_bits;  // changed_bits_words(): the blocks the update changed
  // Compressed.
  std::uint32_t* slots[2];        // table_blocks() each
  std::uint64_t* pool;            // pool_blocks * kStoreBlockWords
  std::uint32_t* free_blocks;     // pool_blocks
  std::uint32_t* changed_blocks;  // table_blocks(): the blocks the update being collected changed
  std::uint64_t* changed_hashes;  // table_blocks(): their new block hashes
  std::uint64_t* block_hashes;    // table_blocks(): the held map's block hashes
};

// The arrays of a MapStore as static storage sized at compile time, for targets without a heap:
// `static StaticMapStoreMemory<kLayout> memory;` (zero-initialised, in bss) then
// `MapStore store(kLayout, memory.storage());`. The other form's arrays take one element each.
template <const MapStoreLayout& kLayout>
struct StaticMapStoreMemory {
  static constexpr std::size_t at_least_one(std::size_t count) { return count == 0 ? 1 : count; }
  static constexpr std::size_t kSideWords = at_least_one(kLayout.dense_words());
  static constexpr std::size_t kTable = at_least_one(kLayout.table_blocks());
  static constexpr std::size_t kPool = at_least_one(kLayout.pool_blocks);

  std::uint64_t sides[2][kSideWords];
  std::uint64_t changed_bits[at_least_one(kLayout.changed_bits_words())];
  std::uint32_t slots[2][kTable];
  std::uint64_t pool[kPool * kStoreBlockWords];
  std::uint32_t free_blocks[kPool];
  std::uint32_t changed_blocks[kTable];
  std::uint64_t changed_hashes[kTable];
  std::uint64_t block_hashes[kTable];

  MapStoreStorage storage() noexcept {
    if (kLayout.dense) return {{sides[0], sides[1]}, changed_bits, {}, {}, {}, {}, {}, {}};
    return {
        {},          {}, {slots[0], slots[1]}, pool, free_blocks, changed_blocks, changed_hashes,
        block_hashes};
  }
};

// The units of MapStore::work()'s budget; each takes roughly the same time on a host core
// (safecell-controller-bench reports the nanoseconds per unit it measured).
inline constexpr std::uint32_t kWorkPerRun = 2;    // one run record read and applied
inline constexpr std::uint32_t kWorkPerBlock = 4;  // one block's words hashed and stored
inline constexpr std::uint32_t kWorkPerLevel = 1;  // one block of the other table made level

class MapStore {
 public:
  static constexpr std::uint32_t kUnlimited = 0xFFFFFFFFu;

  // Starts with no map (version 0, every cell forbidden). Precondition (checked): every array of
  // `storage` the layout's form uses is there and layout.cell_count > 0.
  MapStore(const MapStoreLayout& layout, const MapStoreStorage& storage) noexcept;
  MapStore(const MapStore&) = delete;
  MapStore& operator=(const MapStore&) = delete;

  // Takes one chunk of a keyframe or delta; capture_ns is the capture time of the frame that
  // carried it (the controller's clock). The held map's capture time is the oldest of its
  // update's chunks. Returns kIgnored or kRefused when the chunk is done with at once, else
  // kWorking: then `runs` must stay valid until work() gives the chunk's outcome. A chunk still in
  // work when the next is accepted is first finished without a budget (callers wait instead).
  MapOffer accept(const MapChunkHeader& header, const std::uint8_t* runs, std::size_t runs_size,
                  std::uint64_t capture_ns) noexcept;
  // Goes on with the accepted chunk and the store's upkeep while `budget` lasts (it is lowered by
  // the units spent; the last step may overdraw it by less than kWorkPerRun + kWorkPerBlock).
  // Returns the chunk's outcome once it has one (kPending: the chunk is in, the update needs more;
  // kApplied: the update is verified and swapped in; kRefused), else kWorking.
  MapOffer work(std::uint32_t& budget) noexcept;
  // accept() and work() without a budget: the chunk's outcome, and the upkeep done.
  MapOffer offer(const MapChunkHeader& header, const std::uint8_t* runs, std::size_t runs_size,
                 std::uint64_t capture_ns) noexcept;

  // A chunk was accepted and has no outcome yet (its runs must stay valid).
  bool chunk_in_work() const noexcept {
    return chunk_waiting_ || phase_ == Phase::kRuns || phase_ == Phase::kFinish;
  }
  // Work is left: a chunk, or the upkeep after a swap or a refusal.
  bool busy() const noexcept { return chunk_waiting_ || phase_ != Phase::kIdle; }
  // The units of work done so far (all calls).
  std::uint64_t work_done() const noexcept { return work_done_; }

  // Forgets the held map (a new session): version 0, every cell forbidden.
  void reset() noexcept;

  // The held map; it changes only in the work() call that returns kApplied.
  MapView view() const noexcept {
    if (layout_.dense) return {storage_.sides[held_], layout_.cell_count};
    return {storage_.slots[held_], storage_.pool, layout_.cell_count};
  }
  std::uint64_t version() const noexcept { return version_; }  // 0: no map
  std::uint64_t hash() const noexcept { return hash_; }
  std::uint64_t capture_ns() const noexcept { return capture_ns_; }
  CellIndex cell_count() const noexcept { return layout_.cell_count; }
  const MapStoreLayout& layout() const noexcept { return layout_; }

  // The compressed form: the pool blocks in use (the held map's mixed blocks, and the old map's
  // too until the upkeep after a swap is done), the held map's degraded blocks, and how often a
  // mixed block found the pool full (all updates). All 0 in the dense form.
  std::uint32_t pool_blocks_used() const noexcept { return layout_.pool_blocks - free_count_; }
  std::uint32_t degraded_blocks() const noexcept { return degraded_blocks_; }
  std::uint64_t pool_overflows() const noexcept { return pool_overflows_; }

 private:
  enum class Phase : std::uint8_t {
    kIdle,
    kLevel,   // the working table is made equal to the held one again, block by block
    kRuns,    // the accepted chunk's runs are applied
    kFinish,  // the last chunk is in: the blocks after its runs, then the hash and the swap
  };
  // One step of each phase; each returns the chunk's outcome when it has one, else kWorking.
  MapOffer level_step() noexcept;
  bool level_dense() noexcept;
  MapOffer runs_step() noexcept;
  MapOffer finish_step() noexcept;
  void start_chunk() noexcept;
  MapOffer chunk_done() noexcept;
  MapOffer drop(const MapChunkHeader& header, MapRefusal refusal) noexcept;
  void begin_stream(MapChunkKind kind, std::uint64_t capture_ns) noexcept;
  void abandon() noexcept;
  void make_idle() noexcept;
  void swap_in(std::uint64_t version, std::uint64_t hash) noexcept;
  void load_block(std::uint32_t block, bool whole) noexcept;
  void finish_loaded() noexcept;
  void held_words(std::uint32_t block, std::uint64_t* out) noexcept;
  void store(std::uint32_t block, const std::uint64_t* words) noexcept;
  void store_dense(std::uint32_t block, const std::uint64_t* words) noexcept;
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

  std::uint64_t work_done_ = 0;
  Phase phase_ = Phase::kIdle;

  // The accepted chunk.
  bool chunk_waiting_ = false;  // accepted, to start once the working table is level
  bool chunk_begins_ = false;   // it is the first chunk of an update
  MapChunkHeader chunk_{};
  const std::uint8_t* chunk_runs_ = nullptr;
  std::size_t chunk_runs_size_ = 0;
  std::uint64_t chunk_capture_ns_ = 0;
  RunReader reader_{nullptr, 0, 0, 0};
  bool have_run_ = false;
  CellRun run_{};  // the run being applied; run_.begin advances block by block

  // Making the working side level: of the changed_count_ blocks, level_next_ are done (compressed:
  // changed_blocks [level_next_ .. changed_count_) are left; dense: the set bits of changed_bits
  // from word level_word_ on).
  std::uint32_t level_next_ = 0;
  std::uint32_t level_word_ = 0;
  bool swapped_ = false;  // after a swap (the hashes move in), not a refusal

  // The update being collected.
  MapUpdateSequence sequence_;
  bool keyframe_ = false;
  bool inexact_ = false;  // it needed the words of a degraded block
  std::uint64_t update_capture_ns_ = 0;
  std::uint32_t update_degraded_ = 0;  // the working table's degraded blocks
  std::uint32_t changed_count_ = 0;    // changed_blocks / changed_hashes [0 .. changed_count_)
  std::uint64_t update_combined_ = 0;  // combined_ with the changed blocks' hashes swapped in
  std::uint32_t next_block_ = 0;       // blocks below this are final in the working table
  bool loaded_ = false;                // scratch_ holds block next_block_, being written
  std::uint64_t scratch_[kStoreBlockWords]{};
};

}  // namespace safecell
