#include "safecell/camera/default_cameras.hpp"

#include <array>
#include <numbers>
#include <string>

namespace safecell {

std::vector<PinholeCamera> default_cameras() {
  // The cell is 4 m x 4 m x 3 m with the floor centre at the origin; the cameras sit 5 cm in
  // from each wall and 10 cm below the ceiling.
  constexpr double kCornerM = 1.95;
  constexpr double kHeightM = 2.9;
  const Eigen::Vector3d target_m(0.0, 0.0, 0.8);
  constexpr std::array<std::array<double, 2>, 4> kSigns = {{{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}};
  std::vector<PinholeCamera> cameras;
  for (std::size_t i = 0; i < kSigns.size(); ++i) {
    const Eigen::Vector3d position_m(kSigns[i][0] * kCornerM, kSigns[i][1] * kCornerM, kHeightM);
    cameras.push_back(PinholeCamera::look_at(
        "cam" + std::to_string(i), position_m, target_m, Eigen::Vector3d::UnitZ(),
        kDefaultCameraHorizontalFovDeg * std::numbers::pi / 180.0, kDefaultCameraWidthPx,
        kDefaultCameraHeightPx));
  }
  return cameras;
}

}  // namespace safecell
