#pragma once
// The receiving end of map updates, dense: chunks of keyframes and deltas (map_chunk.hpp) are
// collected into a working copy, and the copy becomes the held map only when the update is whole
// and its map hash matches (double buffer: a reader of map() never sees a half-applied update).
// Which chunks make an update is map_update_sequence.hpp's. The controller holds its map in the
// MapStore (controller/map_store: sliced work, dense or compressed); this one is the reference the
// tests hold it against.
// Storage is the caller's, sized from the grid (words_for(cells) words per map,
// map_hash_blocks(cells) hashes per map); nothing is allocated.
// Thread context: one thread (the controller's link or cycle task). Real-time: a chunk costs
// O(its runs + the blocks it touches); the first chunk of a delta copies the held map (O(words)).

#include <cstddef>
#include <cstdint>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/cspace/map_chunk.hpp"
#include "safecell/cspace/map_update_sequence.hpp"

namespace safecell {

struct MapAssemblyStorage {
  std::uint64_t* words[2];         // two maps of words_for(cell_count) words each
  std::uint64_t* block_hashes[2];  // their block hashes, map_hash_blocks(cell_count) each
};

class MapAssembler {
 public:
  using Outcome = MapOutcome;
  using Offer = MapOffer;

  // Starts with no map (version 0): nothing is allowed until a keyframe is applied.
  MapAssembler(const MapAssemblyStorage& storage, CellIndex cell_count) noexcept;

  Offer offer(const MapChunkHeader& header, const std::uint8_t* runs,
              std::size_t runs_size) noexcept;

  // The held map: version 0 means none yet. map() is valid until the next offer() that applies.
  std::uint64_t version() const noexcept { return version_; }
  std::uint64_t hash() const noexcept { return hash_; }
  const std::uint64_t* map() const noexcept { return words_[held_]; }
  CellIndex cell_count() const noexcept { return cell_count_; }

  // Forgets the held map (a new session): version 0 again.
  void reset() noexcept;

 private:
  Offer drop(const MapChunkHeader& header, MapRefusal refusal) noexcept;

  std::uint64_t* words_[2];
  std::uint64_t* block_hashes_[2];
  CellIndex cell_count_;
  int held_ = 0;
  std::uint64_t version_ = 0;
  std::uint64_t hash_ = 0;
  MapUpdateSequence sequence_;  // the update being collected into the other buffer
};

}  // namespace safecell
