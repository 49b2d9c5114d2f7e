#pragma once
// The reference images of the simulated cell as the paper makes them (§5, Figure 7): the
// per-pixel median of frames with the robot in configurations chosen so that it covers as few
// common pixels as possible. The robot's base, covered in every frame, stays in the reference.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

struct SimulatedReference {
  std::vector<cv::Mat> frames;                      // per camera, CV_8UC1
  std::vector<std::vector<double>> configurations;  // the chosen robot configurations
  std::size_t candidates = 0;
};

// frames: how many configurations (the paper: 9), chosen from `candidates` random ones drawn with
// `seed` within the cell's joint ranges. Throws std::invalid_argument for frames outside
// 1..candidates.
[[nodiscard]] SimulatedReference simulated_reference(SimulatedCell& sim, const CellModel& cell,
                                                     std::size_t frames, std::uint64_t seed,
                                                     std::size_t candidates = 40);

}  // namespace safecell
