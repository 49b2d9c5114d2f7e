#include "safecell/cspace/map_assembler.hpp"

#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/map_hash.hpp"

namespace safecell {

const char* to_string(MapRefusal refusal) noexcept {
  switch (refusal) {
    case MapRefusal::kNone:
      return "none";
    case MapRefusal::kBaseMismatch:
      return "delta base is not the held map";
    case MapRefusal::kStaleVersion:
      return "version not above the held map";
    case MapRefusal::kTorn:
      return "chunk missing or out of order";
    case MapRefusal::kBadChunk:
      return "malformed chunk";
    case MapRefusal::kHashMismatch:
      return "map hash mismatch";
  }
  return "unknown map refusal";
}

MapAssembler::MapAssembler(const MapAssemblyStorage& storage, CellIndex cell_count) noexcept
    : words_{storage.words[0], storage.words[1]},
      block_hashes_{storage.block_hashes[0], storage.block_hashes[1]},
      cell_count_(cell_count) {
  reset();
}

void MapAssembler::reset() noexcept {
  // No map: every cell forbidden, so a reader that ignores version() still stops.
  const std::uint32_t words = cell_bits::words_for(cell_count_);
  for (int b = 0; b < 2; ++b) {
    for (std::uint32_t w = 0; w < words; ++w) words_[b][w] = 0;
    cell_bits::set_range(words_[b], 0, cell_count_);
  }
  held_ = 0;
  version_ = 0;
  hash_ = 0;
  collecting_ = false;
  dropped_version_ = 0;
}

MapAssembler::Offer MapAssembler::drop(const MapChunkHeader& header, MapRefusal refusal) noexcept {
  collecting_ = false;
  dropped_version_ = header.map_version;
  return {Outcome::kRefused, refusal};
}

bool MapAssembler::begin_update(const MapChunkHeader& header, MapRefusal& refusal) noexcept {
  if (header.chunk_count == 0 || header.first_cell != 0) {
    refusal = MapRefusal::kBadChunk;
    return false;
  }
  if (header.map_version <= version_) {
    refusal = MapRefusal::kStaleVersion;
    return false;
  }
  const int work = 1 - held_;
  const std::uint32_t words = cell_bits::words_for(cell_count_);
  const std::uint32_t blocks = map_hash_blocks(cell_count_);
  if (header.kind == MapChunkKind::kDelta) {
    if (version_ == 0 || header.base_version != version_) {
      refusal = MapRefusal::kBaseMismatch;
      return false;
    }
    for (std::uint32_t w = 0; w < words; ++w) words_[work][w] = words_[held_][w];
    for (std::uint32_t b = 0; b < blocks; ++b) block_hashes_[work][b] = block_hashes_[held_][b];
  }
  collecting_ = true;
  update_ = header;
  next_chunk_ = 0;
  next_cell_ = 0;
  return true;
}

MapAssembler::Offer MapAssembler::offer(const MapChunkHeader& header, const std::uint8_t* runs,
                                        std::size_t runs_size) noexcept {
  if (header.chunk_index == 0) {
    // A new update; one still being collected is torn (its rest was lost) and dropped silently:
    // the refusal that matters is this one's, if any.
    collecting_ = false;
    MapRefusal refusal = MapRefusal::kNone;
    if (!begin_update(header, refusal)) return drop(header, refusal);
  } else if (!collecting_ && header.map_version == dropped_version_) {
    return {Outcome::kIgnored, MapRefusal::kNone};
  } else if (!collecting_ || header.kind != update_.kind ||
             header.map_version != update_.map_version ||
             header.base_version != update_.base_version || header.map_hash != update_.map_hash ||
             header.chunk_count != update_.chunk_count || header.chunk_index != next_chunk_ ||
             header.first_cell != next_cell_) {
    return drop(header, MapRefusal::kTorn);
  }
  if (header.chunk_index >= header.chunk_count || header.end_cell < header.first_cell) {
    return drop(header, MapRefusal::kBadChunk);
  }
  const int work = 1 - held_;
  const MapChunkView chunk{header.kind, header.first_cell, header.end_cell, runs, runs_size};
  CellSpan changed;
  if (apply_map_chunk(chunk, words_[work], cell_count_, &changed) != Status::kOk) {
    return drop(header, MapRefusal::kBadChunk);
  }
  MapBlockHashes(block_hashes_[work], cell_count_)
      .refresh(words_[work], changed.begin, changed.end);
  next_chunk_ = header.chunk_index + 1;
  next_cell_ = header.end_cell;
  if (next_chunk_ < update_.chunk_count) {
    if (next_cell_ >= cell_count_) return drop(header, MapRefusal::kBadChunk);  // grid done early
    return {Outcome::kPending, MapRefusal::kNone};
  }
  // The last chunk: the update must cover the grid and reproduce the sender's map exactly.
  if (next_cell_ != cell_count_) return drop(header, MapRefusal::kBadChunk);
  const std::uint64_t hash = map_hash_of_blocks(block_hashes_[work], cell_count_);
  if (hash != update_.map_hash) return drop(header, MapRefusal::kHashMismatch);
  held_ = work;
  version_ = update_.map_version;
  hash_ = hash;
  collecting_ = false;
  return {Outcome::kApplied, MapRefusal::kNone};
}

}  // namespace safecell
