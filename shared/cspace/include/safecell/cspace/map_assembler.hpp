#pragma once
// The receiving end of map updates: chunks of keyframes and deltas (map_chunk.hpp) are collected
// into a working copy, and the copy becomes the held map only when the update is whole and its
// map hash matches (double buffer: a reader of map() never sees a half-applied update).
//
// The safety layer below delivers frames in order or not at all, so an update's chunks must come
// as chunk 0, 1, ... with each starting where the last one ended; anything else means a chunk was
// lost and the update is torn: it is dropped, the held map stays, and the next update (a delta
// against the version the controller acknowledged, or a keyframe) repairs it.
// Storage is the caller's, sized from the grid (words_for(cells) words per map,
// map_hash_blocks(cells) hashes per map); nothing is allocated.
// Thread context: one thread (the controller's link or cycle task). Real-time: a chunk costs
// O(its runs + the blocks it touches); the first chunk of a delta copies the held map (O(words)).

#include <cstddef>
#include <cstdint>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/cspace/map_chunk.hpp"

namespace safecell {

// Why an update was dropped (for the fault report; every one leaves the held map as it was).
enum class MapRefusal : std::uint8_t {
  kNone = 0,
  kBaseMismatch,  // a delta whose base version is not the held map's
  kStaleVersion,  // a version not above the held one
  kTorn,          // a chunk missing, out of order, or of another update
  kBadChunk,      // a chunk whose range or run list is malformed
  kHashMismatch,  // whole, but the result's hash differs from the one the sender computed
};

const char* to_string(MapRefusal refusal) noexcept;

// One chunk as the link delivers it (the fields of safecell.v1.MapChunk).
struct MapChunkHeader {
  MapChunkKind kind = MapChunkKind::kKeyframe;
  std::uint64_t map_version = 0;
  std::uint64_t base_version = 0;
  std::uint64_t map_hash = 0;
  std::uint32_t chunk_index = 0;
  std::uint32_t chunk_count = 0;
  CellIndex first_cell = 0;
  CellIndex end_cell = 0;
};

struct MapAssemblyStorage {
  std::uint64_t* words[2];         // two maps of words_for(cell_count) words each
  std::uint64_t* block_hashes[2];  // their block hashes, map_hash_blocks(cell_count) each
};

class MapAssembler {
 public:
  // kRefused once per dropped update (its first offending chunk); kIgnored for the chunks of an
  // update already dropped.
  enum class Outcome : std::uint8_t { kPending, kApplied, kRefused, kIgnored };
  struct Offer {
    Outcome outcome = Outcome::kPending;
    MapRefusal refusal = MapRefusal::kNone;
  };

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
  bool begin_update(const MapChunkHeader& header, MapRefusal& refusal) noexcept;

  std::uint64_t* words_[2];
  std::uint64_t* block_hashes_[2];
  CellIndex cell_count_;
  int held_ = 0;
  std::uint64_t version_ = 0;
  std::uint64_t hash_ = 0;
  // The update being collected into the other buffer.
  bool collecting_ = false;
  std::uint64_t dropped_version_ = 0;  // the update whose remaining chunks are ignored
  MapChunkHeader update_{};
  std::uint32_t next_chunk_ = 0;
  CellIndex next_cell_ = 0;
};

}  // namespace safecell
