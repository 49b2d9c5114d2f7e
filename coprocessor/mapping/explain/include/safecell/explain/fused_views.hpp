#pragma once
// What the cameras' vote was taken on in one map cycle, kept for the last few map versions, so
// that a stop the controller reports against the map it held (a few cycles behind the newest)
// is explained with that map's views, not the newest ones.
// Thread context: the service's thread; not synchronised.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "safecell/fusion/forbidden_map_fusion.hpp"

namespace safecell {

struct FusedViews {
  std::uint64_t map_version = 0;  // 0: an empty slot
  // Why the whole map was forbidden without a vote (the robot's pose unknown, ...); empty when
  // the cameras voted.
  std::string all_forbidden;
  std::vector<bool> known;             // per camera: its view was known
  std::vector<FeatureMask> obstacles;  // per camera, after robot removal
  std::vector<FeatureMask> hidden;     // per camera, with hidden votes
};

class FusedViewsHistory {
 public:
  // Keeps the views of the last `versions` maps (at least 1).
  explicit FusedViewsHistory(std::size_t versions = 32);

  // The views `fusion` voted on for map `map_version` (after its fuse()); after the first few
  // cycles this allocates nothing.
  void record(std::uint64_t map_version, const ForbiddenMapFusion& fusion,
              const std::vector<CameraObservation>& observations);
  // A map that was forbidden whole, without a vote, and why.
  void record_all_forbidden(std::uint64_t map_version, const std::string& why);
  // The views of map `map_version`, or nullptr when it is older than the history keeps or was
  // never recorded.
  [[nodiscard]] const FusedViews* find(std::uint64_t map_version) const;

 private:
  FusedViews& next_slot(std::uint64_t map_version);

  std::vector<FusedViews> slots_;
  std::size_t next_ = 0;
};

}  // namespace safecell
