#pragma once
// The coprocessor's side of map traffic: turns each cycle's forbidden map into the chunks of one
// map update (shared/cspace/map_chunk.hpp), a delta against the last version the controller
// acknowledged, or a keyframe.
//
// A keyframe goes out at the start, when the controller asks for one, when the acknowledged
// version is no longer in the history, and when no acknowledgement has arrived for
// keyframe_after_cycles cycles. So a lost frame costs one cycle: the next delta is again against
// the version the controller holds, not the one last sent.
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
  // The controller asked for a keyframe: the next update is one.
  void request_keyframe() { keyframe_requested_ = true; }

  std::uint64_t acknowledged() const { return acknowledged_; }
  std::uint64_t last_version() const { return last_version_; }
  // The map sent as `version`, if still in the history (nullptr otherwise).
  const CellSet* sent(std::uint64_t version) const;

 private:
  std::uint32_t cell_count_;
  MapPublisherSettings settings_;
  std::deque<std::pair<std::uint64_t, CellSet>> history_;
  std::uint64_t last_version_ = 0;
  std::uint64_t acknowledged_ = 0;
  std::uint32_t cycles_since_ack_ = 0;
  bool keyframe_requested_ = true;  // the first update is a keyframe
};

}  // namespace safecell
