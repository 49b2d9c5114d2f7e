#include "safecell/link/map_publisher.hpp"

#include <stdexcept>
#include <string>

#include "safecell/cspace/map_chunk.hpp"
#include "safecell/cspace/map_hash.hpp"

namespace safecell {

MapPublisher::MapPublisher(std::uint32_t cell_count, const MapPublisherSettings& settings)
    : cell_count_(cell_count), settings_(settings) {
  if (settings.history < 1) throw std::invalid_argument("map publisher: history must be >= 1");
  if (settings.keyframe_after_cycles < 1) {
    throw std::invalid_argument("map publisher: keyframe_after_cycles must be >= 1");
  }
  if (settings.runs_per_chunk_bytes < kMaxRunRecordBytes) {
    throw std::invalid_argument("map publisher: runs_per_chunk_bytes must be >= " +
                                std::to_string(kMaxRunRecordBytes));
  }
}

const CellSet* MapPublisher::sent(std::uint64_t version) const {
  for (const auto& [sent_version, map] : history_) {
    if (sent_version == version) return &map;
  }
  return nullptr;
}

void MapPublisher::acknowledge(std::uint64_t version) {
  if (version == 0 || version > last_version_) return;
  if (version != acknowledged_) {
    acknowledged_ = version;
    cycles_since_ack_ = 0;
  }
}

void MapPublisher::request_repair(std::uint64_t held_version) {
  const bool repair_waiting = repair_pending_ && held_version == repair_base_;
  const bool repair_just_sent = !repair_pending_ && repair_version_ != 0 &&
                                held_version == repair_base_ &&
                                last_version_ <= repair_version_ + 1;
  if (repair_waiting || repair_just_sent) {
    ++repeated_requests_;  // the repair from this version is on its way already
    return;
  }
  ++repairs_;
  repair_pending_ = true;
  repair_base_ = held_version;
  if (held_version == 0 || held_version > last_version_ || sent(held_version) == nullptr) {
    keyframe_requested_ = true;
  } else {
    base_version_ = held_version;
  }
}

MapUpdate MapPublisher::publish(const CellSet& map, std::uint32_t healthy_cameras,
                                std::uint32_t camera_count,
                                std::uint32_t speed_reduction_permille) {
  if (speed_reduction_permille > 1000) {
    throw std::invalid_argument("map publisher: a speed reduction of " +
                                std::to_string(speed_reduction_permille) +
                                " permille, expected 0..1000");
  }
  if (map.cell_count() != cell_count_) {
    throw std::invalid_argument("map publisher: a map of " + std::to_string(map.cell_count()) +
                                " cells for a grid of " + std::to_string(cell_count_));
  }
  const CellSet* base = base_version_ != 0 ? sent(base_version_) : nullptr;
  // Acknowledgements run one cycle or so behind; this counts cycles in which none came at all.
  const bool ack_stalled = ++cycles_since_ack_ > settings_.keyframe_after_cycles;
  const bool keyframe = keyframe_requested_ || base == nullptr || ack_stalled;
  if (ack_stalled) cycles_since_ack_ = 0;
  keyframe_requested_ = false;

  MapUpdate update;
  update.version = ++last_version_;
  if (repair_pending_) {
    repair_pending_ = false;
    repair_version_ = update.version;
  }
  update.keyframe = keyframe;
  update.hash = map_hash(map.words().data(), cell_count_);
  std::vector<std::uint8_t> runs(settings_.runs_per_chunk_bytes);
  CellIndex from = 0;
  do {
    std::size_t size = 0;
    const CellIndex end =
        keyframe ? encode_keyframe_chunk(map.words().data(), cell_count_, from, runs.data(),
                                         runs.size(), size)
                 : encode_delta_chunk(base->words().data(), map.words().data(), cell_count_, from,
                                      runs.data(), runs.size(), size);
    v1::MapChunk& chunk = update.chunks.emplace_back();
    chunk.set_kind(keyframe ? v1::MAP_UPDATE_KIND_KEYFRAME : v1::MAP_UPDATE_KIND_DELTA);
    chunk.set_map_version(update.version);
    chunk.set_base_version(keyframe ? 0 : base_version_);
    chunk.set_map_hash(map_hash_with_speed_reduction(
        map_hash_with_cameras(update.hash, healthy_cameras, camera_count),
        speed_reduction_permille));
    chunk.set_chunk_index(static_cast<std::uint32_t>(update.chunks.size() - 1));
    chunk.set_first_cell(from);
    chunk.set_end_cell(end);
    chunk.set_runs(runs.data(), size);
    chunk.set_healthy_cameras(healthy_cameras);
    chunk.set_camera_count(camera_count);
    chunk.set_speed_reduction_permille(speed_reduction_permille);
    from = end;
  } while (from < cell_count_);
  for (auto& chunk : update.chunks) {
    chunk.set_chunk_count(static_cast<std::uint32_t>(update.chunks.size()));
  }
  history_.emplace_back(update.version, map);
  while (history_.size() > settings_.history) history_.pop_front();
  base_version_ = update.version;  // the next delta follows this one (in order, see above)
  return update;
}

}  // namespace safecell
