#pragma once
// The paper's fusion as it describes it (§4.3), kept as the reference the fast fusion is tested
// and benchmarked against: an empty C-space of one counter per cell, and for every camera, every
// blocked pixel and every cell of that pixel's LUT-2 line, the cell's counter is increased -
// once per camera (a stamp per cell remembers which camera counted last), since the threshold
// counts cameras. Critical = counter >= threshold; forbidden = critical + static obstacles.
// Robot removal is the same as the fast fusion's. With hidden votes the robot's hidden pixels
// count their camera as well, and a cell needs one camera's obstacle pixel besides.

#include <cstdint>
#include <vector>

#include "safecell/fusion/forbidden_map_fusion.hpp"

namespace safecell {

class BaselineFusion {
 public:
  // As ForbiddenMapFusion.
  BaselineFusion(const LutSet& luts, const RobotSilhouettes& silhouettes,
                 const FusionSettings& settings);

  const CellSet& fuse(const std::vector<CameraObservation>& observations, CellIndex robot_cell);
  [[nodiscard]] const CellSet& forbidden() const { return forbidden_; }

 private:
  void count_cell(CellIndex cell, std::uint8_t camera_stamp);
  // Counts the camera for the cells of each of `pixels`; seen: they are obstacle pixels.
  void count_pixels(const FeatureMask& pixels, const PixelToCellsTable& table,
                    std::uint8_t camera_stamp, bool seen);

  const LutSet& luts_;
  const RobotSilhouettes& silhouettes_;
  FusionSettings settings_;
  std::vector<std::vector<CellIndex>> observable_;  // per part and camera, cell by cell
  std::vector<std::uint8_t> counters_;
  std::vector<std::uint8_t> stamps_;
  std::vector<FeatureMask> robot_;
  std::vector<FeatureMask> obstacles_;
  std::vector<FeatureMask> hidden_;
  CellSet pixel_cells_;  // the cells of one pixel
  CellSet seen_;         // cells some camera's obstacle pixel marks, this part's
  CellSet forbidden_;
};

}  // namespace safecell
