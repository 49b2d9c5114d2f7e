#include "safecell/cspace/map_update_sequence.hpp"

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
    case MapRefusal::kBaseInexact:
      return "delta onto blocks held only as all-forbidden";
  }
  return "unknown map refusal";
}

MapUpdateSequence::Verdict MapUpdateSequence::check(const MapChunkHeader& header,
                                                    std::uint64_t held_version) noexcept {
  if (header.chunk_index == 0) {
    // A new update; one still being collected is torn (its rest was lost) and abandoned silently:
    // the refusal that matters is this one's, if any.
    collecting_ = false;
    if (header.chunk_count == 0 || header.first_cell != 0 || header.end_cell < header.first_cell) {
      return {Step::kRefuse, MapRefusal::kBadChunk};
    }
    if (header.map_version <= held_version) return {Step::kRefuse, MapRefusal::kStaleVersion};
    if (header.kind == MapChunkKind::kDelta &&
        (held_version == 0 || header.base_version != held_version)) {
      return {Step::kRefuse, MapRefusal::kBaseMismatch};
    }
    collecting_ = true;
    update_ = header;
    next_chunk_ = 0;
    next_cell_ = 0;
    return {Step::kBegin, MapRefusal::kNone};
  }
  if (!collecting_ && header.map_version == dropped_version_) {
    return {Step::kIgnore, MapRefusal::kNone};
  }
  if (!collecting_ || header.kind != update_.kind || header.map_version != update_.map_version ||
      header.base_version != update_.base_version || header.map_hash != update_.map_hash ||
      header.chunk_count != update_.chunk_count || header.chunk_index != next_chunk_ ||
      header.first_cell != next_cell_) {
    return {Step::kRefuse, MapRefusal::kTorn};
  }
  if (header.chunk_index >= header.chunk_count || header.end_cell < header.first_cell) {
    return {Step::kRefuse, MapRefusal::kBadChunk};
  }
  return {Step::kContinue, MapRefusal::kNone};
}

MapUpdateSequence::Progress MapUpdateSequence::advanced(const MapChunkHeader& header,
                                                        CellIndex cell_count) noexcept {
  next_chunk_ = header.chunk_index + 1;
  next_cell_ = header.end_cell;
  if (next_chunk_ < update_.chunk_count) {
    return next_cell_ >= cell_count ? Progress::kBadChunk : Progress::kPending;  // grid done early
  }
  return next_cell_ == cell_count ? Progress::kComplete : Progress::kBadChunk;
}

void MapUpdateSequence::dropped(const MapChunkHeader& header) noexcept {
  collecting_ = false;
  dropped_version_ = header.map_version;
}

}  // namespace safecell
