#pragma once
// The robot's silhouette where it is, for robot removal (DESIGN.md §3, "Images"): the balls that
// cover its collision geometry (robot_balls.hpp) placed at the joint values of the frames'
// exposure, each grown by a widening, projected into every camera as feature rectangles. Much
// tighter than LUT-1, which holds the robot anywhere in its C-space cell, so that a person
// standing next to the arm keeps their pixels.
//
// The widening must cover whatever puts the real robot outside the balls at those joint values:
// the calibration and model error (the padding of the tables) and the motion possible between
// the exposure and the joint values given for it (removal_widening_m()).

#include <optional>
#include <span>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/envelope/ball_projection.hpp"
#include "safecell/envelope/robot_balls.hpp"
#include "safecell/features/feature_mask.hpp"

namespace safecell {

// padding_m + sum over the joints of l_i * (the joint's speed limit) * sync_error_s: how far any
// point of the robot can be from where its joint values place it. nullopt when a joint has no
// speed limit (the URDF gives none) and sync_error_s > 0: the motion is then unbounded.
[[nodiscard]] std::optional<double> removal_widening_m(const RobotModel& robot,
                                                       const CspaceGrid& grid, double padding_m,
                                                       double sync_error_s);

class ConfigurationSilhouettes {
 public:
  // Throws std::invalid_argument when the cell has no robot model or no camera, or for a ball
  // radius outside kMinBallRadius_m..kMaxBallRadius_m or a widening outside 0..1 m.
  ConfigurationSilhouettes(const CellModel& cell, double ball_radius_m, double widening_m);

  [[nodiscard]] std::size_t camera_count() const { return projections_.size(); }
  [[nodiscard]] double widening_m() const { return widening_m_; }

  // masks[camera] |= the silhouette at joint values q (one per robot joint, rad).
  // Thread-safe (scratch per thread). Throws std::invalid_argument for the wrong number of masks
  // or joint values.
  void add_silhouettes(std::span<const double> q, std::vector<FeatureMask>& masks) const;
  // The same for the bodies first_body .. end_body - 1 alone (0: the base, 1 + j: link j; a
  // robot part's range, robot_parts.hpp); a range past the robot's bodies is cut at its end.
  void add_silhouettes(std::span<const double> q, std::vector<FeatureMask>& masks,
                       std::size_t first_body, std::size_t end_body) const;
  // The balls of bodies first_body .. end_body - 1 placed at q, in the cell frame, grown by the
  // widening (into `balls`, cleared first): what add_silhouettes projects. Thread-safe. Throws
  // std::invalid_argument for the wrong number of joint values.
  void place_balls(std::span<const double> q, std::size_t first_body, std::size_t end_body,
                   std::vector<Ball>& balls) const;
  [[nodiscard]] const BallProjection& projection(std::size_t camera) const {
    return projections_.at(camera);
  }

 private:
  RobotModel robot_;
  RobotBalls balls_;
  double widening_m_;
  std::vector<BallProjection> projections_;
};

}  // namespace safecell
