#include "safecell/sim/human_walker.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "number_text.hpp"

namespace safecell {
namespace {

[[noreturn]] void throw_invalid(const std::string& field, const std::string& problem) {
  throw std::invalid_argument("HumanWalker: " + field + ": " + problem);
}

void check_parameters(const std::vector<Eigen::Vector2d>& waypoints_m, double speed_m_s,
                      double arm_raise_rad) {
  if (waypoints_m.empty()) throw_invalid("waypoints_m", "none given, expected at least one");
  for (std::size_t i = 0; i < waypoints_m.size(); ++i) {
    const Eigen::Vector2d& point = waypoints_m[i];
    if (!point.allFinite()) {
      throw_invalid("waypoints_m[" + std::to_string(i) + "]", "value (" + number_text(point.x()) +
                                                                  ", " + number_text(point.y()) +
                                                                  "), expected finite coordinates");
    }
  }
  // Written so that NaN fails too.
  if (!(speed_m_s > 0.0 && speed_m_s <= kMaxWalkingSpeed_m_s)) {
    throw_invalid("speed_m_s", "value " + number_text(speed_m_s) +
                                   ", expected above 0 and at most " +
                                   number_text(kMaxWalkingSpeed_m_s) + " m/s");
  }
  if (!std::isfinite(arm_raise_rad)) {
    throw_invalid("arm_raise_rad",
                  "value " + number_text(arm_raise_rad) + ", expected a finite angle");
  }
}

double heading_of(const Eigen::Vector2d& direction) {
  return std::atan2(direction.y(), direction.x());
}

}  // namespace

HumanWalker::HumanWalker(std::vector<Eigen::Vector2d> waypoints_m, double speed_m_s,
                         double arm_raise_rad)
    : waypoints_m_(std::move(waypoints_m)), speed_m_s_(speed_m_s), arm_raise_rad_(arm_raise_rad) {
  check_parameters(waypoints_m_, speed_m_s_, arm_raise_rad_);
  distance_at_m_.reserve(waypoints_m_.size());
  distance_at_m_.push_back(0.0);
  for (std::size_t i = 1; i < waypoints_m_.size(); ++i) {
    const Eigen::Vector2d step = waypoints_m_[i] - waypoints_m_[i - 1];
    distance_at_m_.push_back(distance_at_m_.back() + step.norm());
    if (step.norm() > 0.0) final_heading_rad_ = heading_of(step);
  }
}

HumanPose HumanWalker::pose_at(double time_s) const {
  if (std::isnan(time_s)) throw std::invalid_argument("HumanWalker::pose_at: time_s is NaN");
  const double walked_s = std::max(time_s, 0.0);
  const double travelled_m = speed_m_s_ * walked_s;
  HumanPose pose;
  pose.arm_raise_rad = arm_raise_rad_;
  if (travelled_m >= path_length_m()) {
    pose.position_m = waypoints_m_.back();
    pose.heading_rad = final_heading_rad_;
    pose.gait_amplitude = 0.0;
    return pose;
  }
  // The segment [k - 1, k] with distance_at_m_[k - 1] <= travelled_m < distance_at_m_[k]: it has
  // a non-zero length, so segments of length 0 are passed over.
  const auto next = std::upper_bound(distance_at_m_.begin(), distance_at_m_.end(), travelled_m);
  const auto k = static_cast<std::size_t>(next - distance_at_m_.begin());
  const Eigen::Vector2d& from = waypoints_m_[k - 1];
  const Eigen::Vector2d step = waypoints_m_[k] - from;
  const double fraction = (travelled_m - distance_at_m_[k - 1]) / (*next - distance_at_m_[k - 1]);
  pose.position_m = from + fraction * step;
  pose.heading_rad = heading_of(step);
  // Half a gait cycle per step.
  pose.gait_phase_rad =
      std::fmod(std::numbers::pi * kCadence_steps_s * walked_s, 2.0 * std::numbers::pi);
  pose.gait_amplitude = 1.0;
  return pose;
}

}  // namespace safecell
