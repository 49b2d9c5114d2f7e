#pragma once
// Which chunks make one map update, whatever the receiver stores the map in: the dense
// MapAssembler (map_assembler.hpp) and the controller's MapStore share these rules.
//
// The safety layer below delivers frames in order or not at all, so an update's chunks must come
// as chunk 0, 1, ... with each starting where the last one ended and the last ending at the grid's
// end; anything else means a chunk was lost and the update is torn: it is dropped, the held map
// stays, and the next update (a delta against the version the controller acknowledged, or a
// keyframe) repairs it. A delta applies only onto the map of its base version; every update's
// version is above the held one.
// Thread context: the receiver's; not synchronised. Real-time: O(1) per chunk, no allocation.

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
  kBaseInexact,   // a delta onto blocks the receiver holds only as all-forbidden (pool full)
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

// What became of a chunk offered to a receiver. kRefused once per dropped update (its first
// offending chunk); kIgnored for the chunks of an update already dropped; kWorking from a receiver
// that works in slices (the controller's MapStore): no outcome yet.
enum class MapOutcome : std::uint8_t { kPending, kApplied, kRefused, kIgnored, kWorking };
struct MapOffer {
  MapOutcome outcome = MapOutcome::kPending;
  MapRefusal refusal = MapRefusal::kNone;
};

class MapUpdateSequence {
 public:
  enum class Step : std::uint8_t {
    kBegin,     // the first chunk of a new update (any update being collected is abandoned)
    kContinue,  // the next chunk of the update being collected
    kIgnore,    // a chunk of an update already dropped
    kRefuse,    // drop the update (the refusal says why)
  };
  struct Verdict {
    Step step = Step::kRefuse;
    MapRefusal refusal = MapRefusal::kNone;
  };
  enum class Progress : std::uint8_t { kPending, kComplete, kBadChunk };

  // Where `header` fits, given the version of the map the receiver holds (0: none). A kBegin or
  // kContinue chunk is then applied by the receiver and passed to advanced().
  Verdict check(const MapChunkHeader& header, std::uint64_t held_version) noexcept;
  // After the chunk was applied: kComplete when it was the last and the update covers the grid,
  // kBadChunk when the update ends early or runs past the grid's end.
  Progress advanced(const MapChunkHeader& header, CellIndex cell_count) noexcept;
  // The update is over: `dropped` ignores its remaining chunks; finished() after it was applied.
  void dropped(const MapChunkHeader& header) noexcept;
  void finished() noexcept { collecting_ = false; }

  bool collecting() const noexcept { return collecting_; }
  // The first chunk's header of the update being collected.
  const MapChunkHeader& update() const noexcept { return update_; }

 private:
  bool collecting_ = false;
  std::uint64_t dropped_version_ = 0;  // the update whose remaining chunks are ignored
  MapChunkHeader update_{};
  std::uint32_t next_chunk_ = 0;
  CellIndex next_cell_ = 0;
};

}  // namespace safecell
