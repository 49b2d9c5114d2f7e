#include "safecell/cspace/map_assembler.hpp"

#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/map_hash.hpp"

namespace safecell {

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
  sequence_ = MapUpdateSequence{};
}

MapAssembler::Offer MapAssembler::drop(const MapChunkHeader& header, MapRefusal refusal) noexcept {
  sequence_.dropped(header);
  return {Outcome::kRefused, refusal};
}

MapAssembler::Offer MapAssembler::offer(const MapChunkHeader& header, const std::uint8_t* runs,
                                        std::size_t runs_size) noexcept {
  const MapUpdateSequence::Verdict verdict = sequence_.check(header, version_);
  if (verdict.step == MapUpdateSequence::Step::kIgnore)
    return {Outcome::kIgnored, MapRefusal::kNone};
  if (verdict.step == MapUpdateSequence::Step::kRefuse) return drop(header, verdict.refusal);
  const int work = 1 - held_;
  if (verdict.step == MapUpdateSequence::Step::kBegin && header.kind == MapChunkKind::kDelta) {
    const std::uint32_t words = cell_bits::words_for(cell_count_);
    const std::uint32_t blocks = map_hash_blocks(cell_count_);
    for (std::uint32_t w = 0; w < words; ++w) words_[work][w] = words_[held_][w];
    for (std::uint32_t b = 0; b < blocks; ++b) block_hashes_[work][b] = block_hashes_[held_][b];
  }
  const MapChunkView chunk{header.kind, header.first_cell, header.end_cell, runs, runs_size};
  CellSpan changed;
  if (apply_map_chunk(chunk, words_[work], cell_count_, &changed) != Status::kOk) {
    return drop(header, MapRefusal::kBadChunk);
  }
  MapBlockHashes(block_hashes_[work], cell_count_)
      .refresh(words_[work], changed.begin, changed.end);
  const MapUpdateSequence::Progress progress = sequence_.advanced(header, cell_count_);
  if (progress == MapUpdateSequence::Progress::kBadChunk)
    return drop(header, MapRefusal::kBadChunk);
  if (progress == MapUpdateSequence::Progress::kPending)
    return {Outcome::kPending, MapRefusal::kNone};
  // The last chunk: the update must reproduce the sender's map exactly.
  const std::uint64_t hash = map_hash_of_blocks(block_hashes_[work], cell_count_);
  if (hash != sequence_.update().map_hash) return drop(header, MapRefusal::kHashMismatch);
  held_ = work;
  version_ = sequence_.update().map_version;
  hash_ = hash;
  sequence_.finished();
  return {Outcome::kApplied, MapRefusal::kNone};
}

}  // namespace safecell
