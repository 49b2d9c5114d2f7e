#pragma once
// The coprocessor's side of map traffic: turns each cycle's forbidden map into the chunks of one
// map update (shared/cspace/map_chunk.hpp), a delta or a keyframe.
//
// A delta is based on the version sent last: the link delivers updates in order and the
// controller applies them in order, so on a link without faults each delta finds its base held,
// however many updates are on their way (an update built against the last *acknowledged* version
// was refused whenever the one before it was still in flight: about a quarter of them). When the
// controller refuses an update, or finds one lost (from the heartbeat CoprocessorLink sends after
// each, naming it), it asks for a repair naming the version it holds (KeyframeRequest): the next
// update is a delta from that version while it is in the history, else a keyframe. A request naming
// a version that a repair sent within the last two updates was based on already is one the repair
// answers (a second refusal of the same loss) and changes nothing. A keyframe goes out at the
// start, on a request naming a version no longer in the history (or none), and when no
// acknowledgement has arrived for keyframe_after_cycles cycles.
// Thread context: the coprocessor's link thread; not synchronised.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "safecell/cellsets/cell_set.hpp"
#include "safecell/v1/map.pb.h"

namespace safecell {

struct MapPublisherSettings {
  std::size_t history = 16;                  // maps kept as possible delta bases
  std::uint32_t keyframe_after_cycles = 10;  // cycles without an acknowledgement
  std::size_t runs_per_chunk_bytes = 1370;   // the run list of one frame (map.options)
};

struct MapUpdate {
  std::uint64_t version = 0;
  bool keyframe = false;
  std::uint64_t hash = 0;
  std::vector<v1::MapChunk> chunks;
};

class MapPublisher {
 public:
  MapPublisher(std::uint32_t cell_count, const MapPublisherSettings& settings);

  // The update for this cycle's map (which becomes version last + 1), sent with the camera counts
  // it was fused from and the protective separation's speed reduction (thousandths of the top
  // speed; 0 none), all three bound into its hash (shared/cspace/map_hash.hpp).
  MapUpdate publish(const CellSet& map, std::uint32_t healthy_cameras, std::uint32_t camera_count,
                    std::uint32_t speed_reduction_permille = 0);

  // The controller holds `version` (from its joint stream). Versions never sent are ignored.
  void acknowledge(std::uint64_t version);
  // The controller refused or lost an update and holds `held_version` (0: none): the next update
  // repairs from it (see above).
  void request_repair(std::uint64_t held_version);

  std::uint64_t acknowledged() const { return acknowledged_; }
  std::uint64_t last_version() const { return last_version_; }
  // Repair requests answered, and those ignored as answered already.
  std::uint64_t repairs() const { return repairs_; }
  std::uint64_t repeated_requests() const { return repeated_requests_; }
  // The map sent as `version`, if still in the history (nullptr otherwise).
  const CellSet* sent(std::uint64_t version) const;

 private:
  std::uint32_t cell_count_;
  MapPublisherSettings settings_;
  std::deque<std::pair<std::uint64_t, CellSet>> history_;
  std::uint64_t last_version_ = 0;
  std::uint64_t base_version_ = 0;  // what the next delta is based on
  std::uint64_t acknowledged_ = 0;
  std::uint32_t cycles_since_ack_ = 0;
  bool keyframe_requested_ = true;  // the first update is a keyframe
  // The last repair: the version it was based on and the update that carried it (0: none).
  std::uint64_t repair_base_ = 0;
  std::uint64_t repair_version_ = 0;
  bool repair_pending_ = false;
  std::uint64_t repairs_ = 0;
  std::uint64_t repeated_requests_ = 0;
};

}  // namespace safecell
