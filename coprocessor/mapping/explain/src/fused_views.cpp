#include "safecell/explain/fused_views.hpp"

#include <algorithm>

namespace safecell {

FusedViewsHistory::FusedViewsHistory(std::size_t versions)
    : slots_(std::max<std::size_t>(versions, 1)) {}

FusedViews& FusedViewsHistory::next_slot(std::uint64_t map_version) {
  FusedViews& slot = slots_[next_];
  next_ = (next_ + 1) % slots_.size();
  slot.map_version = map_version;
  slot.all_forbidden.clear();
  return slot;
}

void FusedViewsHistory::record(std::uint64_t map_version, const ForbiddenMapFusion& fusion,
                               const std::vector<CameraObservation>& observations) {
  FusedViews& slot = next_slot(map_version);
  const std::size_t cameras = fusion.camera_count();
  slot.known.assign(cameras, false);
  slot.obstacles.resize(cameras);
  slot.hidden.resize(cameras);
  for (std::size_t camera = 0; camera < cameras; ++camera) {
    slot.known[camera] = camera < observations.size() && observations[camera].known;
    slot.obstacles[camera] = fusion.obstacles(camera);  // same size each cycle: no allocation
    slot.hidden[camera] = fusion.hidden(camera);
  }
}

void FusedViewsHistory::record_all_forbidden(std::uint64_t map_version, const std::string& why) {
  FusedViews& slot = next_slot(map_version);
  slot.all_forbidden = why.empty() ? std::string("forbidden whole") : why;
  slot.known.clear();
}

const FusedViews* FusedViewsHistory::find(std::uint64_t map_version) const {
  if (map_version == 0) return nullptr;
  // Newest first: an unchanged map keeps its version, and its newest views made it too.
  for (std::size_t back = 1; back <= slots_.size(); ++back) {
    const FusedViews& slot = slots_[(next_ + slots_.size() - back) % slots_.size()];
    if (slot.map_version == map_version) return &slot;
  }
  return nullptr;
}

}  // namespace safecell
