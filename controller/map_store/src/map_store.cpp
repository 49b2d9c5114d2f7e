#include "safecell/controller/map_store.hpp"

#include <bit>

#include "safecell/base/assert.hpp"
#include "safecell/cspace/run_coding.hpp"

namespace safecell {
static_assert(kMapHashBlockCells == kStoreBlockCells, "the store hashes the blocks it stores");
namespace {

// The map hash's hashes of block `block` (map_hash.hpp) holding each of N sets of its words, in
// one loop: N independent chains of multiplies that the core overlaps (the dense store hashes the
// held and the new words of a block; two calls one after the other took 48 ns a block, against
// 41-43 ns).
template <std::size_t N>
void block_hashes(std::uint32_t block, const std::uint64_t* const (&words)[N],
                  std::uint64_t (&hashes)[N]) noexcept {
  for (std::uint64_t& hash : hashes) hash = map_block_hash_seed(block);
  for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) {
    for (std::size_t k = 0; k < N; ++k) hashes[k] = map_hash_mix(hashes[k] ^ words[k][w]);
  }
}

std::uint64_t block_hash(std::uint32_t block, const std::uint64_t* words) noexcept {
  std::uint64_t hash[1];
  block_hashes<1>(block, {words}, hash);
  return hash[0];
}

}  // namespace

MapStore::MapStore(const MapStoreLayout& layout, const MapStoreStorage& storage) noexcept
    : layout_(layout), storage_(storage) {
  SAFECELL_ASSERT(layout.cell_count > 0 && layout.blocks == store_blocks_for(layout.cell_count));
  if (layout.dense) {
    SAFECELL_ASSERT(layout.pool_blocks == 0 && storage.sides[0] != nullptr &&
                    storage.sides[1] != nullptr && storage.changed_bits != nullptr);
  } else {
    SAFECELL_ASSERT(storage.slots[0] != nullptr && storage.slots[1] != nullptr &&
                    storage.changed_blocks != nullptr && storage.changed_hashes != nullptr &&
                    storage.block_hashes != nullptr);
    SAFECELL_ASSERT(layout.pool_blocks == 0 ||
                    (storage.pool != nullptr && storage.free_blocks != nullptr));
  }
  reset();
}

void MapStore::reset() noexcept {
  // No map: every cell forbidden, a consistent map with its block hashes.
  combined_ = 0;
  std::uint64_t words[kStoreBlockWords];
  for (std::uint32_t b = 0; b < layout_.blocks; ++b) {
    for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) words[w] = valid_bits(b, w);
    const std::uint64_t hash = block_hash(b, words);
    combined_ ^= hash;
    if (layout_.dense) {
      for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) {
        storage_.sides[0][b * kStoreBlockWords + w] = words[w];
        storage_.sides[1][b * kStoreBlockWords + w] = words[w];
      }
      continue;
    }
    storage_.slots[0][b] = kForbiddenSlot;
    storage_.slots[1][b] = kForbiddenSlot;
    storage_.block_hashes[b] = hash;
  }
  for (std::size_t w = 0; w < layout_.changed_bits_words(); ++w) storage_.changed_bits[w] = 0;
  free_count_ = 0;
  for (std::uint32_t p = layout_.pool_blocks; p > 0; --p)
    storage_.free_blocks[free_count_++] = p - 1;
  held_ = 0;
  degraded_blocks_ = 0;
  version_ = 0;
  hash_ = 0;
  capture_ns_ = 0;
  sequence_ = MapUpdateSequence{};
  changed_count_ = 0;
  chunk_waiting_ = false;
  have_run_ = false;
  make_idle();
}

MapOffer MapStore::offer(const MapChunkHeader& header, const std::uint8_t* runs,
                         std::size_t runs_size, std::uint64_t capture_ns) noexcept {
  MapOffer offer = accept(header, runs, runs_size, capture_ns);
  std::uint32_t budget = kUnlimited;
  while (busy()) {
    const MapOffer outcome = work(budget);
    if (outcome.outcome != MapOutcome::kWorking) offer = outcome;
  }
  return offer;
}

MapOffer MapStore::accept(const MapChunkHeader& header, const std::uint8_t* runs,
                          std::size_t runs_size, std::uint64_t capture_ns) noexcept {
  std::uint32_t unlimited = kUnlimited;
  while (chunk_in_work()) (void)work(unlimited);  // a caller that did not wait
  const MapUpdateSequence::Verdict verdict = sequence_.check(header, version_);
  if (verdict.step == MapUpdateSequence::Step::kIgnore) {
    return {MapOutcome::kIgnored, MapRefusal::kNone};
  }
  if (verdict.step == MapUpdateSequence::Step::kRefuse) return drop(header, verdict.refusal);
  const bool begins = verdict.step == MapUpdateSequence::Step::kBegin;
  if (begins) {
    abandon();  // the rest of an update being collected was lost
  } else if (capture_ns < update_capture_ns_) {
    update_capture_ns_ = capture_ns;
  }
  if (header.first_cell > header.end_cell || header.end_cell > layout_.cell_count ||
      (runs == nullptr && runs_size != 0)) {
    return drop(header, MapRefusal::kBadChunk);
  }
  chunk_waiting_ = true;
  chunk_begins_ = begins;
  chunk_ = header;
  chunk_runs_ = runs;
  chunk_runs_size_ = runs_size;
  chunk_capture_ns_ = capture_ns;
  return {MapOutcome::kWorking, MapRefusal::kNone};
}

MapOffer MapStore::work(std::uint32_t& budget) noexcept {
  while (budget > 0) {
    if (phase_ == Phase::kIdle) {
      if (!chunk_waiting_) break;
      start_chunk();
    }
    const std::uint64_t before = work_done_;
    MapOffer outcome{MapOutcome::kWorking, MapRefusal::kNone};
    switch (phase_) {
      case Phase::kLevel:
        outcome = level_step();
        break;
      case Phase::kRuns:
        outcome = runs_step();
        break;
      case Phase::kFinish:
        outcome = finish_step();
        break;
      case Phase::kIdle:
        break;
    }
    const std::uint64_t spent = work_done_ - before;
    budget = spent >= budget ? 0 : budget - static_cast<std::uint32_t>(spent);
    if (outcome.outcome != MapOutcome::kWorking) return outcome;
  }
  return {MapOutcome::kWorking, MapRefusal::kNone};
}

void MapStore::start_chunk() noexcept {
  // The working table is level with the held one here (phase kIdle).
  chunk_waiting_ = false;
  if (chunk_begins_) begin_stream(chunk_.kind, chunk_capture_ns_);
  reader_ = RunReader(chunk_runs_, chunk_runs_size_, chunk_.first_cell, chunk_.end_cell);
  have_run_ = false;
  phase_ = Phase::kRuns;
}

MapOffer MapStore::level_step() noexcept {
  if (layout_.dense) {
    if (!level_dense()) make_idle();
    return {MapOutcome::kWorking, MapRefusal::kNone};
  }
  // One changed block: the working table takes the held table's slot again, and the pool block
  // the working table had there is free (after a swap: the old map's; after a refusal: the
  // update's).
  if (level_next_ < changed_count_) {
    std::uint32_t* work = storage_.slots[1 - held_];
    const std::uint32_t block = storage_.changed_blocks[level_next_];
    if (is_pool_slot(work[block])) storage_.free_blocks[free_count_++] = work[block];
    work[block] = storage_.slots[held_][block];
    if (swapped_) storage_.block_hashes[block] = storage_.changed_hashes[level_next_];
    ++level_next_;
    work_done_ += kWorkPerLevel;
    return {MapOutcome::kWorking, MapRefusal::kNone};
  }
  make_idle();
  return {MapOutcome::kWorking, MapRefusal::kNone};
}

bool MapStore::level_dense() noexcept {
  // One word of the changed blocks' bitset passed, or one changed block copied from the held side
  // to the working side (after a swap: the new map's words; after a refusal: the held map's
  // again). False when every changed block is level (and the bitset all zeros again).
  // (The bitset holds changed_count_ - level_next_ set bits, so the scan ends within it.)
  if (level_next_ == changed_count_ || level_word_ >= layout_.changed_bits_words()) return false;
  std::uint64_t& bits = storage_.changed_bits[level_word_];
  work_done_ += kWorkPerLevel;
  if (bits == 0) {
    ++level_word_;
    return true;
  }
  const std::uint32_t block = level_word_ * 64 + static_cast<std::uint32_t>(std::countr_zero(bits));
  bits &= bits - 1;
  const std::uint64_t* from = storage_.sides[held_] + std::size_t{block} * kStoreBlockWords;
  std::uint64_t* to = storage_.sides[1 - held_] + std::size_t{block} * kStoreBlockWords;
  for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) to[w] = from[w];
  ++level_next_;
  return true;
}

void MapStore::make_idle() noexcept {
  // The working table equals the held one: no update in it.
  changed_count_ = 0;
  level_next_ = 0;
  level_word_ = 0;
  swapped_ = false;
  update_combined_ = combined_;
  update_degraded_ = degraded_blocks_;
  next_block_ = 0;
  loaded_ = false;
  inexact_ = false;
  phase_ = Phase::kIdle;
}

MapOffer MapStore::runs_step() noexcept {
  // One costed action (a run read, or a block stored) and the free ones around it: the segments
  // of a run within the block in scratch_.
  for (;;) {
    if (!have_run_) {
      work_done_ += kWorkPerRun;
      const Result<CellRun> next = reader_.next();
      if (!next.ok()) {
        // The end, or a malformed record.
        if (next.error() != Status::kEmpty) return drop(chunk_, MapRefusal::kBadChunk);
        return chunk_done();
      }
      run_ = next.value();
      if (keyframe_ && !run_.value) return drop(chunk_, MapRefusal::kBadChunk);  // only sets
      have_run_ = true;
    }
    if (run_.begin >= run_.end) {
      have_run_ = false;
      return {MapOutcome::kWorking, MapRefusal::kNone};
    }
    const std::uint32_t block = run_.begin / kStoreBlockCells;
    // Runs come in grid order (check_map_chunk and the update sequence saw to it).
    if (block < next_block_) return drop(chunk_, MapRefusal::kBadChunk);
    if (loaded_ && block != next_block_) {
      finish_loaded();
      return {MapOutcome::kWorking, MapRefusal::kNone};
    }
    if (!loaded_ && next_block_ < block) {
      // The blocks no run touched: a keyframe clears them; a delta keeps them as they are.
      if (keyframe_) {
        const std::uint64_t zeros[kStoreBlockWords] = {};
        store(next_block_++, zeros);
        return {MapOutcome::kWorking, MapRefusal::kNone};
      }
      next_block_ = block;
    }
    const CellIndex block_first = block * kStoreBlockCells;
    const CellIndex block_end = block_first + kStoreBlockCells < layout_.cell_count
                                    ? block_first + kStoreBlockCells
                                    : layout_.cell_count;
    const CellIndex segment_end = run_.end < block_end ? run_.end : block_end;
    const bool whole = run_.begin == block_first && segment_end == block_end;
    if (!loaded_) load_block(block, whole);
    if (whole) {
      for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) {
        scratch_[w] = run_.value ? valid_bits(block, w) : 0;
      }
    } else if (run_.value) {
      cell_bits::set_range(scratch_, run_.begin - block_first, segment_end - block_first);
    } else {
      cell_bits::clear_range(scratch_, run_.begin - block_first, segment_end - block_first);
    }
    run_.begin = segment_end;
  }
}

MapOffer MapStore::chunk_done() noexcept {
  if (inexact_) return drop(chunk_, MapRefusal::kBaseInexact);
  const MapUpdateSequence::Progress progress = sequence_.advanced(chunk_, layout_.cell_count);
  if (progress == MapUpdateSequence::Progress::kBadChunk) {
    return drop(chunk_, MapRefusal::kBadChunk);
  }
  if (progress == MapUpdateSequence::Progress::kPending) {
    phase_ = Phase::kIdle;
    return {MapOutcome::kPending, MapRefusal::kNone};
  }
  phase_ = Phase::kFinish;
  return {MapOutcome::kWorking, MapRefusal::kNone};
}

MapOffer MapStore::finish_step() noexcept {
  // The blocks after the last run (a keyframe clears them, a delta keeps them), then the check.
  if (loaded_) {
    finish_loaded();
    return {MapOutcome::kWorking, MapRefusal::kNone};
  }
  if (keyframe_ && next_block_ < layout_.blocks) {
    const std::uint64_t zeros[kStoreBlockWords] = {};
    store(next_block_++, zeros);
    return {MapOutcome::kWorking, MapRefusal::kNone};
  }
  work_done_ += kWorkPerRun;
  if (inexact_) return drop(chunk_, MapRefusal::kBaseInexact);
  const std::uint64_t hash = map_hash_from_combined(update_combined_, layout_.cell_count);
  if (hash != sequence_.update().map_hash) return drop(chunk_, MapRefusal::kHashMismatch);
  swap_in(sequence_.update().map_version, hash);
  sequence_.finished();
  return {MapOutcome::kApplied, MapRefusal::kNone};
}

MapOffer MapStore::drop(const MapChunkHeader& header, MapRefusal refusal) noexcept {
  abandon();
  sequence_.dropped(header);
  return {MapOutcome::kRefused, refusal};
}

void MapStore::begin_stream(MapChunkKind kind, std::uint64_t capture_ns) noexcept {
  keyframe_ = kind == MapChunkKind::kKeyframe;
  update_capture_ns_ = capture_ns;
  update_combined_ = combined_;
  update_degraded_ = degraded_blocks_;
}

void MapStore::abandon() noexcept {
  // The update's changes to the working table are undone in the slices that follow. While the
  // table is being made level already (after a swap or a refusal), no update has touched it since.
  chunk_waiting_ = false;
  have_run_ = false;
  if (phase_ == Phase::kLevel) return;
  loaded_ = false;
  swapped_ = false;
  level_next_ = 0;
  level_word_ = 0;
  phase_ = Phase::kLevel;
}

void MapStore::swap_in(std::uint64_t version, std::uint64_t hash) noexcept {
  held_ = 1 - held_;  // from here on view() shows the new map
  combined_ = update_combined_;
  degraded_blocks_ = update_degraded_;
  version_ = version;
  hash_ = hash;
  capture_ns_ = update_capture_ns_;
  // The other table (the old map) is made level with the new one in the slices that follow.
  swapped_ = true;
  level_next_ = 0;
  level_word_ = 0;
  loaded_ = false;
  phase_ = Phase::kLevel;
}

void MapStore::load_block(std::uint32_t block, bool whole) noexcept {
  loaded_ = true;
  if (whole) return;  // the caller writes every word
  if (keyframe_) {
    for (std::uint64_t& word : scratch_) word = 0;
  } else {
    held_words(block, scratch_);
  }
}

void MapStore::finish_loaded() noexcept {
  store(next_block_, scratch_);
  ++next_block_;
  loaded_ = false;
}

void MapStore::held_words(std::uint32_t block, std::uint64_t* out) noexcept {
  if (layout_.dense) {
    const std::uint64_t* held = storage_.sides[held_] + std::size_t{block} * kStoreBlockWords;
    for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) out[w] = held[w];
    return;
  }
  const std::uint32_t slot = storage_.slots[held_][block];
  if (slot == kDegradedSlot) inexact_ = true;  // the exact words are gone
  for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) {
    if (is_pool_slot(slot)) {
      out[w] = storage_.pool[std::uint64_t{slot} * kStoreBlockWords + w];
    } else {
      out[w] = slot == kFreeSlot ? 0 : valid_bits(block, w);
    }
  }
}

void MapStore::store(std::uint32_t block, const std::uint64_t* words) noexcept {
  work_done_ += kWorkPerBlock;
  if (layout_.dense) {
    store_dense(block, words);
    return;
  }
  bool none = true;
  bool all = true;
  for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) {
    none = none && words[w] == 0;
    all = all && words[w] == valid_bits(block, w);
  }
  const std::uint64_t hash = block_hash(block, words);  // of the exact words, whatever is kept
  std::uint32_t* work = storage_.slots[1 - held_];
  const std::uint32_t old = work[block];  // the held map's: each block is stored once per update
  std::uint32_t slot = none ? kFreeSlot : kForbiddenSlot;
  if (!none && !all) {
    if (is_pool_slot(old)) {
      const std::uint64_t* held_copy = storage_.pool + std::uint64_t{old} * kStoreBlockWords;
      bool same = true;
      for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) same = same && held_copy[w] == words[w];
      if (same) return;
    }
    if (free_count_ == 0) {
      slot = kDegradedSlot;
      ++pool_overflows_;
    } else {
      slot = storage_.free_blocks[--free_count_];
      std::uint64_t* copy = storage_.pool + std::uint64_t{slot} * kStoreBlockWords;
      for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) copy[w] = words[w];
    }
  }
  // A degraded block that stays degraded may hold other (unknown) words: its hash tells.
  if (slot == old && hash == storage_.block_hashes[block]) return;
  if (old == kDegradedSlot) --update_degraded_;
  if (slot == kDegradedSlot) ++update_degraded_;
  work[block] = slot;
  storage_.changed_blocks[changed_count_] = block;
  storage_.changed_hashes[changed_count_] = hash;
  ++changed_count_;
  update_combined_ ^= storage_.block_hashes[block] ^ hash;
}

void MapStore::store_dense(std::uint32_t block, const std::uint64_t* words) noexcept {
  // The working side's block is the held map's until this update stores it (once).
  std::uint64_t* work = storage_.sides[1 - held_] + std::size_t{block} * kStoreBlockWords;
  bool same = true;
  for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) same = same && work[w] == words[w];
  if (same) return;
  // No stored hash of the held block (the dense form keeps no hashes): its words are hashed again
  // here, beside the new ones.
  std::uint64_t hashes[2];
  block_hashes<2>(block, {work, words}, hashes);
  update_combined_ ^= hashes[0] ^ hashes[1];
  for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) work[w] = words[w];
  storage_.changed_bits[block / 64] |= std::uint64_t{1} << (block % 64);
  ++changed_count_;
}

std::uint64_t MapStore::valid_bits(std::uint32_t block, std::uint32_t word) const noexcept {
  const std::uint64_t first_cell = (std::uint64_t{block} * kStoreBlockWords + word) * 64;
  if (first_cell + 64 <= layout_.cell_count) return cell_bits::kAllBits;
  if (first_cell >= layout_.cell_count) return 0;
  return (std::uint64_t{1} << (layout_.cell_count - first_cell)) - 1;
}

}  // namespace safecell
