#pragma once
// A person's visit to the cell, in seconds since the run began (it may begin before): they walk
// in along a path, stand for a while facing a point (the robot's base), the right arm reaching
// towards it or hanging, and walk out along another path. Outside the visit nobody is in the
// cell.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "safecell/sim/human_walker.hpp"

namespace safecell {

struct PersonVisitPlan {
  double enters_s = 0.0;
  std::vector<Eigen::Vector2d> approach_m;  // floor waypoints, from where they come in
  std::vector<Eigen::Vector2d> leave_m;     // from where they stood to where they go out
  double speed_m_s = kWalkingSpeed_m_s;
  double stand_s = 0.0;
  Eigen::Vector2d face_m = Eigen::Vector2d::Zero();  // what they face while standing
  bool reach = false;  // the right arm comes up over the first second of standing
};

class PersonVisit {
 public:
  // Throws std::invalid_argument (from HumanWalker) for an empty path or a speed out of range.
  explicit PersonVisit(PersonVisitPlan plan);

  // The person at time_s; nullopt while they are outside the cell.
  [[nodiscard]] std::optional<HumanPose> at(double time_s) const;
  [[nodiscard]] double enters_s() const { return plan_.enters_s; }
  [[nodiscard]] double leaves_s() const;
  [[nodiscard]] const PersonVisitPlan& plan() const { return plan_; }

 private:
  PersonVisitPlan plan_;
  HumanWalker approach_;
  HumanWalker leave_;
};

}  // namespace safecell
