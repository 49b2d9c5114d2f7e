#include "safecell/sim/simulated_cell.hpp"

#include <stdexcept>

#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/cell_scenery.hpp"

namespace safecell {
namespace {

// Brightness of the moving bodies: a light robot, dark clothes, a lighter head.
constexpr std::uint8_t kRobotAlbedo = 215;
constexpr std::uint8_t kClothesAlbedo = 55;
constexpr std::uint8_t kSkinAlbedo = 165;
constexpr std::uint8_t kObjectAlbedo = 95;  // cardboard

}  // namespace

SimulatedCell::SimulatedCell(RobotModel robot, std::vector<PinholeCamera> cameras,
                             const Eigen::Vector3d& size_m, std::vector<PlacedShape> obstacles,
                             const SensorSettings& sensor, RobotAppearance appearance)
    : robot_(std::move(robot)), appearance_(appearance), obstacles_(std::move(obstacles)) {
  if (cameras.empty()) throw std::invalid_argument("the simulated cell needs at least one camera");
  const auto scenery = cell_scenery(size_m, obstacles_);
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    SensorSettings own = sensor;
    own.seed = sensor.seed + i;  // independent noise per camera
    renderers_.emplace_back(std::move(cameras[i]), scenery, own);
  }
}

std::vector<PlacedShape> SimulatedCell::robot_shapes(const std::vector<double>& q,
                                                     BodyRange bodies) const {
  const Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
  return appearance_ == RobotAppearance::kVisual ? visual_shapes_at(robot_, q, base, bodies)
                                                 : collision_shapes_at(robot_, q, base, bodies);
}

std::vector<SurfaceMesh> SimulatedCell::moving_surfaces(const SimScene& scene) const {
  std::vector<SurfaceMesh> surfaces;
  surfaces.push_back(surface_of(robot_shapes(scene.q), kRobotAlbedo, body_code(BodyKind::kRobot)));
  for (std::size_t h = 0; h < scene.humans.size(); ++h) {
    std::vector<PlacedShape> body = human_shapes(scene.humans[h]);
    const BodyCode code = body_code(BodyKind::kHuman, h);
    const auto head = static_cast<std::size_t>(HumanPart::kHead);
    surfaces.push_back(surface_of({body[head]}, kSkinAlbedo, code));
    body.erase(body.begin() + static_cast<std::ptrdiff_t>(head));
    surfaces.push_back(surface_of(body, kClothesAlbedo, code));
  }
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    surfaces.push_back(
        surface_of({scene.objects[o]}, kObjectAlbedo, body_code(BodyKind::kObject, o)));
  }
  return surfaces;
}

std::vector<cv::Mat> SimulatedCell::render(const SimScene& scene, std::uint64_t frame_index,
                                           double time_s, std::vector<cv::Mat>* object_ids) {
  return render_surfaces(moving_surfaces(scene), frame_index, time_s, object_ids);
}

std::vector<cv::Mat> SimulatedCell::render_surfaces(const std::vector<SurfaceMesh>& moving,
                                                    std::uint64_t frame_index, double time_s,
                                                    std::vector<cv::Mat>* object_ids) {
  std::vector<cv::Mat> frames;
  if (object_ids != nullptr) object_ids->assign(renderers_.size(), cv::Mat());
  for (std::size_t c = 0; c < renderers_.size(); ++c) {
    frames.push_back(renderers_[c].render(moving, frame_index, time_s,
                                          object_ids != nullptr ? &(*object_ids)[c] : nullptr));
  }
  return frames;
}

cv::Mat SimulatedCell::coverage(std::size_t camera_index,
                                const std::vector<SurfaceMesh>& surfaces) {
  return renderers_.at(camera_index).coverage(surfaces);
}

cv::Mat SimulatedCell::object_ids(std::size_t camera_index,
                                  const std::vector<SurfaceMesh>& surfaces) {
  return renderers_.at(camera_index).object_ids(surfaces);
}

cv::Mat SimulatedCell::robot_coverage(std::size_t camera_index, const std::vector<double>& q,
                                      BodyRange bodies) {
  return renderers_.at(camera_index).coverage({surface_of(robot_shapes(q, bodies), kRobotAlbedo)});
}

}  // namespace safecell
