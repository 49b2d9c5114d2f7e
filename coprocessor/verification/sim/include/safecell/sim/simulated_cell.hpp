#pragma once
// The simulated work cell: the robot, the humans and the static boxes as every camera sees them,
// and the exact ground truth of what collides. It stands in for the real cell and cameras in
// tests, in validation and in the demo.

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "safecell/camera/pinhole_camera.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/robot/robot_model.hpp"
#include "safecell/sim/camera_renderer.hpp"
#include "safecell/sim/human_figure.hpp"

namespace safecell {

// One moment of the cell: the robot's joint values, where the humans are, and objects put into
// the cell that the cell file does not know (boxes left on the floor: seen and hit like humans).
struct SimScene {
  std::vector<double> q;
  std::vector<HumanPose> humans;
  std::vector<PlacedShape> objects{};
};

// Which of the robot's shapes the cameras see: its collision geometry (what the look-up tables
// and the ground truth use) or its visual geometry (what a real camera would see).
enum class RobotAppearance { kCollision, kVisual };

class SimulatedCell {
 public:
  // size_m: the cell's inside (floor centre at the origin, z up); the robot base stands at the
  // origin. Throws std::invalid_argument when there is no camera.
  SimulatedCell(RobotModel robot, std::vector<PinholeCamera> cameras, const Eigen::Vector3d& size_m,
                std::vector<PlacedShape> obstacles, const SensorSettings& sensor,
                RobotAppearance appearance = RobotAppearance::kCollision);

  std::size_t camera_count() const { return renderers_.size(); }
  const PinholeCamera& camera(std::size_t index) const { return renderers_.at(index).camera(); }
  const RobotModel& robot() const { return robot_; }
  const std::vector<PlacedShape>& obstacles() const { return obstacles_; }

  // One 8-bit frame per camera. With `object_ids`, per camera also the renderer's object-id image
  // (camera_renderer.hpp): the robot, static obstacle b, human n and object n of the scene by
  // their body codes (body_id.hpp).
  std::vector<cv::Mat> render(const SimScene& scene, std::uint64_t frame_index, double time_s,
                              std::vector<cv::Mat>* object_ids = nullptr);
  // As render(), with any moving surfaces (none: the empty cell).
  std::vector<cv::Mat> render_surfaces(const std::vector<SurfaceMesh>& moving,
                                       std::uint64_t frame_index, double time_s,
                                       std::vector<cv::Mat>* object_ids = nullptr);

  // The robot, the humans and the objects as surfaces to render (robot first, then one or more
  // per human, then one per object), each with its body code.
  std::vector<SurfaceMesh> moving_surfaces(const SimScene& scene) const;
  // One camera's object-id image of the still cell with `surfaces` in it (no robot unless among
  // them): CameraRenderer::object_ids().
  cv::Mat object_ids(std::size_t camera_index, const std::vector<SurfaceMesh>& surfaces);
  // Pixels of one camera the robot's bodies `bodies` (as they appear; default all) cover,
  // occlusion ignored (CV_8UC1, 255 = covered).
  cv::Mat robot_coverage(std::size_t camera_index, const std::vector<double>& q,
                         BodyRange bodies = {});
  // Pixels of one camera the surfaces cover, occlusion ignored (CV_8UC1, 255 = covered).
  cv::Mat coverage(std::size_t camera_index, const std::vector<SurfaceMesh>& surfaces);

 private:
  std::vector<PlacedShape> robot_shapes(const std::vector<double>& q, BodyRange bodies = {}) const;

  RobotModel robot_;
  RobotAppearance appearance_;
  std::vector<PlacedShape> obstacles_;
  std::vector<CameraRenderer> renderers_;
};

}  // namespace safecell
