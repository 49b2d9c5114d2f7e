#include "safecell/validation/separation_check.hpp"

#include <algorithm>
#include <limits>

#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "safecell/sim/human_figure.hpp"
#include "safecell/validation/body_visibility.hpp"
#include "safecell/validation/scene_check.hpp"

namespace safecell {

SeparationFigures& SeparationFigures::operator+=(const SeparationFigures& other) {
  scenes += other.scenes;
  fired += other.fired;
  slowed += other.slowed;
  within += other.within;
  missed += other.missed;
  far += other.far;
  needless += other.needless;
  return *this;
}

double SeparationFigures::needless_share() const {
  return far == 0 ? 0.0 : static_cast<double>(needless) / static_cast<double>(far);
}

SeparationFigures check_separation(const CellModel& world, const SimScene& scene,
                                   const std::vector<cv::Mat>& object_ids, int camera_threshold,
                                   double separation_m, double speed_limit, double clear_m) {
  const std::vector<PlacedShape> robot = collision_shapes_at(*world.robot, scene.q);
  const std::size_t bodies = scene.humans.size() + scene.objects.size();
  double nearest_visible_m = std::numeric_limits<double>::infinity();
  double nearest_m = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < bodies; ++b) {
    const bool human = b < scene.humans.size();
    const std::vector<PlacedShape> shapes =
        human ? human_shapes(scene.humans[b])
              : std::vector<PlacedShape>{scene.objects[b - scene.humans.size()]};
    const double distance_m = GroundTruth(shapes).min_distance_m(robot);
    const std::vector<bool> visible =
        visible_per_camera(object_ids, scene_body_code(scene.humans.size(), b), world.feature_grid);
    const auto cameras_visible = std::count(visible.begin(), visible.end(), true);
    nearest_m = std::min(nearest_m, distance_m);
    if (cameras_visible >= camera_threshold) {
      nearest_visible_m = std::min(nearest_visible_m, distance_m);
    }
  }
  SeparationFigures figures;
  figures.scenes = 1;
  const bool fired = speed_limit < 1.0;
  figures.fired = fired ? 1 : 0;
  figures.slowed = fired && speed_limit > 0.0 ? 1 : 0;
  figures.within = nearest_visible_m < separation_m ? 1 : 0;
  // A stop allows no speed: nothing is missed. Otherwise the allowed speed's S must hold.
  figures.missed = speed_limit > 0.0 && nearest_visible_m < clear_m ? 1 : 0;
  if (nearest_m >= separation_m + kClearDistance_m) {
    figures.far = 1;
    figures.needless = fired ? 1 : 0;
  }
  return figures;
}

}  // namespace safecell
