#include "safecell/controller/map_store.hpp"

#include "safecell/base/assert.hpp"
#include "safecell/cspace/run_coding.hpp"

namespace safecell {
static_assert(kMapHashBlockCells == kStoreBlockCells, "the store hashes the blocks it stores");

MapStore::MapStore(const MapStoreLayout& layout, const MapStoreStorage& storage) noexcept
    : layout_(layout), storage_(storage) {
  SAFECELL_ASSERT(layout.cell_count > 0 && layout.blocks == store_blocks_for(layout.cell_count));
  SAFECELL_ASSERT(storage.slots[0] != nullptr && storage.slots[1] != nullptr &&
                  storage.changed_blocks != nullptr && storage.changed_hashes != nullptr &&
                  storage.block_hashes != nullptr);
  SAFECELL_ASSERT(layout.pool_blocks == 0 ||
                  (storage.pool != nullptr && storage.free_blocks != nullptr));
  reset();
}

void MapStore::reset() noexcept {
  // No map: every cell forbidden, a consistent map with its block hashes.
  combined_ = 0;
  std::uint64_t words[kStoreBlockWords];
  for (std::uint32_t b = 0; b < layout_.blocks; ++b) {
    storage_.slots[0][b] = kForbiddenSlot;
    storage_.slots[1][b] = kForbiddenSlot;
    for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) words[w] = valid_bits(b, w);
    storage_.block_hashes[b] = block_hash(b, words);
    combined_ ^= storage_.block_hashes[b];
  }
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
  abandon();
}

MapOffer MapStore::offer(const MapChunkHeader& header, const std::uint8_t* runs,
                         std::size_t runs_size, std::uint64_t capture_ns) noexcept {
  const MapUpdateSequence::Verdict verdict = sequence_.check(header, version_);
  if (verdict.step == MapUpdateSequence::Step::kIgnore) {
    return {MapOutcome::kIgnored, MapRefusal::kNone};
  }
  if (verdict.step == MapUpdateSequence::Step::kRefuse) return drop(header, verdict.refusal);
  if (verdict.step == MapUpdateSequence::Step::kBegin) {
    abandon();  // the rest of an update being collected was lost
    begin_stream(header.kind, capture_ns);
  } else if (capture_ns < update_capture_ns_) {
    update_capture_ns_ = capture_ns;
  }
  // One pass: the runs are checked as they are applied (a malformed chunk leaves only the
  // working table touched, and drop() undoes that).
  const MapChunkView chunk{header.kind, header.first_cell, header.end_cell, runs, runs_size};
  if (header.first_cell > header.end_cell || header.end_cell > layout_.cell_count ||
      (runs == nullptr && runs_size != 0) || !apply_runs(chunk)) {
    return drop(header, MapRefusal::kBadChunk);
  }
  if (inexact_) return drop(header, MapRefusal::kBaseInexact);
  const MapUpdateSequence::Progress progress = sequence_.advanced(header, layout_.cell_count);
  if (progress == MapUpdateSequence::Progress::kBadChunk) {
    return drop(header, MapRefusal::kBadChunk);
  }
  if (progress == MapUpdateSequence::Progress::kPending) {
    return {MapOutcome::kPending, MapRefusal::kNone};
  }
  // The last chunk: finish the stream (the blocks after the last run), then check the hash.
  if (loaded_) finish_loaded();
  pass_until(layout_.blocks);
  if (inexact_) return drop(header, MapRefusal::kBaseInexact);
  const std::uint64_t hash = map_hash_from_combined(update_combined_, layout_.cell_count);
  if (hash != sequence_.update().map_hash) return drop(header, MapRefusal::kHashMismatch);
  commit(sequence_.update().map_version, hash);
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
}

void MapStore::abandon() noexcept {
  // Undo the working table's changes: it equals the held table again, and the pool blocks the
  // update took are free.
  std::uint32_t* work = storage_.slots[1 - held_];
  const std::uint32_t* held = storage_.slots[held_];
  for (std::uint32_t i = 0; i < changed_count_; ++i) {
    const std::uint32_t block = storage_.changed_blocks[i];
    if (is_pool_slot(work[block])) storage_.free_blocks[free_count_++] = work[block];
    work[block] = held[block];
  }
  changed_count_ = 0;
  update_combined_ = combined_;
  next_block_ = 0;
  loaded_ = false;
  inexact_ = false;
}

void MapStore::commit(std::uint64_t version, std::uint64_t hash) noexcept {
  const std::uint32_t* work = storage_.slots[1 - held_];
  const std::uint32_t* held = storage_.slots[held_];
  for (std::uint32_t i = 0; i < changed_count_; ++i) {
    const std::uint32_t block = storage_.changed_blocks[i];
    if (is_pool_slot(held[block])) storage_.free_blocks[free_count_++] = held[block];
    if (held[block] == kDegradedSlot) --degraded_blocks_;
    if (work[block] == kDegradedSlot) ++degraded_blocks_;
  }
  held_ = 1 - held_;  // the swap: from here on view() shows the new map
  std::uint32_t* stale = storage_.slots[1 - held_];
  for (std::uint32_t i = 0; i < changed_count_; ++i) {
    const std::uint32_t block = storage_.changed_blocks[i];
    stale[block] = storage_.slots[held_][block];
  }
  for (std::uint32_t i = 0; i < changed_count_; ++i) {
    storage_.block_hashes[storage_.changed_blocks[i]] = storage_.changed_hashes[i];
  }
  combined_ = update_combined_;
  version_ = version;
  hash_ = hash;
  capture_ns_ = update_capture_ns_;
  changed_count_ = 0;  // nothing to undo: the working table equals the held one
  abandon();
}

bool MapStore::apply_runs(const MapChunkView& chunk) noexcept {
  RunReader reader(chunk.runs, chunk.runs_size, chunk.first_cell, chunk.end_cell);
  for (;;) {
    const Result<CellRun> next = reader.next();
    if (!next.ok()) return next.error() == Status::kEmpty;  // the end, or a malformed record
    const CellRun& run = next.value();
    if (keyframe_ && !run.value) return false;  // a keyframe only sets cells
    CellIndex cell = run.begin;
    while (cell < run.end) {
      const std::uint32_t block = cell / kStoreBlockCells;
      // Runs come in grid order (check_map_chunk and the update sequence saw to it).
      if (block < next_block_) return false;
      const CellIndex block_first = block * kStoreBlockCells;
      const CellIndex block_end = block_first + kStoreBlockCells < layout_.cell_count
                                      ? block_first + kStoreBlockCells
                                      : layout_.cell_count;
      const CellIndex segment_end = run.end < block_end ? run.end : block_end;
      const bool whole = cell == block_first && segment_end == block_end;
      seek(block, whole);
      if (whole) {
        for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) {
          scratch_[w] = run.value ? valid_bits(block, w) : 0;
        }
      } else if (run.value) {
        cell_bits::set_range(scratch_, cell - block_first, segment_end - block_first);
      } else {
        cell_bits::clear_range(scratch_, cell - block_first, segment_end - block_first);
      }
      cell = segment_end;
    }
  }
}

void MapStore::seek(std::uint32_t block, bool whole) noexcept {
  if (loaded_ && block == next_block_) return;
  if (loaded_) finish_loaded();
  pass_until(block);
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

void MapStore::pass_until(std::uint32_t block) noexcept {
  // The blocks no run touched: a keyframe clears them; a delta keeps them as they are.
  if (!keyframe_) {
    if (next_block_ < block) next_block_ = block;
    return;
  }
  const std::uint64_t zeros[kStoreBlockWords] = {};
  for (; next_block_ < block; ++next_block_) store(next_block_, zeros);
}

void MapStore::held_words(std::uint32_t block, std::uint64_t* out) noexcept {
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

std::uint64_t MapStore::block_hash(std::uint32_t block, const std::uint64_t* words) const noexcept {
  std::uint64_t hash = map_block_hash_seed(block);
  for (std::uint32_t w = 0; w < kStoreBlockWords; ++w) hash = map_hash_mix(hash ^ words[w]);
  return hash;
}

void MapStore::store(std::uint32_t block, const std::uint64_t* words) noexcept {
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
  work[block] = slot;
  storage_.changed_blocks[changed_count_] = block;
  storage_.changed_hashes[changed_count_] = hash;
  ++changed_count_;
  update_combined_ ^= storage_.block_hashes[block] ^ hash;
}

std::uint64_t MapStore::valid_bits(std::uint32_t block, std::uint32_t word) const noexcept {
  const std::uint64_t first_cell = (std::uint64_t{block} * kStoreBlockWords + word) * 64;
  if (first_cell + 64 <= layout_.cell_count) return cell_bits::kAllBits;
  if (first_cell >= layout_.cell_count) return 0;
  return (std::uint64_t{1} << (layout_.cell_count - first_cell)) - 1;
}

}  // namespace safecell
