#pragma once
// LUT-1 as the fusion reads it: the feature cells of one camera that the robot can cover while
// its configuration is anywhere in a given C-space cell. Robot removal asks for one cell per
// cycle. Two sources: a stored table (recorded mode) and the robot model (model mode, computed
// on demand, bit for bit what the table build used).

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/features/feature_mask.hpp"

namespace safecell {

class RobotSilhouettes {
 public:
  virtual ~RobotSilhouettes() = default;
  RobotSilhouettes() = default;
  RobotSilhouettes(const RobotSilhouettes&) = delete;
  RobotSilhouettes& operator=(const RobotSilhouettes&) = delete;

  [[nodiscard]] virtual std::size_t camera_count() const = 0;
  // Adds the silhouette of `cell` in `camera` to `mask` (the feature grid's size). Thread-safe.
  virtual void add_silhouette(CellIndex cell, std::size_t camera, FeatureMask& mask) const = 0;
  // Every camera at once: masks[camera] |= its silhouette (masks.size() == camera_count(), else
  // std::invalid_argument). A source that shares work between the cameras overrides it.
  virtual void add_silhouettes(CellIndex cell, std::vector<FeatureMask>& masks) const {
    if (masks.size() != camera_count()) {
      throw std::invalid_argument(std::to_string(masks.size()) + " masks for " +
                                  std::to_string(camera_count()) + " cameras");
    }
    for (std::size_t camera = 0; camera < masks.size(); ++camera) {
      add_silhouette(cell, camera, masks[camera]);
    }
  }
};

}  // namespace safecell
