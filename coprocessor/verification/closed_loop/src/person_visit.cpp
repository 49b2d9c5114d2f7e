#include "safecell/closed_loop/person_visit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace safecell {

PersonVisit::PersonVisit(PersonVisitPlan plan)
    : plan_(std::move(plan)),
      approach_(plan_.approach_m, plan_.speed_m_s),
      leave_(plan_.leave_m, plan_.speed_m_s) {}

double PersonVisit::leaves_s() const {
  return plan_.enters_s + approach_.arrival_time_s() + plan_.stand_s + leave_.arrival_time_s();
}

std::optional<HumanPose> PersonVisit::at(double time_s) const {
  const double t = time_s - plan_.enters_s;
  if (t < 0.0 || time_s > leaves_s()) return std::nullopt;
  if (t <= approach_.arrival_time_s()) return approach_.pose_at(t);
  const double standing = t - approach_.arrival_time_s();
  if (standing <= plan_.stand_s) {
    HumanPose pose = approach_.pose_at(approach_.arrival_time_s());
    const Eigen::Vector2d towards = plan_.face_m - pose.position_m;
    if (towards.norm() > 1e-6) pose.heading_rad = std::atan2(towards.y(), towards.x());
    pose.gait_amplitude = 0.0;
    if (plan_.reach) pose.right_arm_reach_rad = std::min(1.0, standing) * std::numbers::pi / 2.0;
    return pose;
  }
  return leave_.pose_at(standing - plan_.stand_s);
}

}  // namespace safecell
