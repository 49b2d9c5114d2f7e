#include "safecell/controller/stop_model.hpp"

#include "safecell/base/freestanding_math.hpp"

namespace safecell {
namespace {

double magnitude(double value) noexcept { return value < 0.0 ? -value : value; }

}  // namespace

double StopModel::stop_time_s(std::uint32_t joint, double speed_rad_s) const noexcept {
  const JointStop& stop = joints[joint < kMaxJoints ? joint : 0];
  return stop.latency_s + magnitude(speed_rad_s) / stop.decel_rad_s2;
}

double StopModel::stop_distance_rad(std::uint32_t joint, double speed_rad_s) const noexcept {
  const JointStop& stop = joints[joint < kMaxJoints ? joint : 0];
  const double speed = magnitude(speed_rad_s);
  return speed * stop.latency_s + speed * speed / (2.0 * stop.decel_rad_s2);
}

bool StopModel::valid() const noexcept {
  if (joint_count == 0 || joint_count > kMaxJoints) return false;
  for (std::uint32_t j = 0; j < joint_count; ++j) {
    if (!is_finite_non_negative(joints[j].latency_s) || !is_finite(joints[j].decel_rad_s2) ||
        !(joints[j].decel_rad_s2 > 0.0)) {
      return false;
    }
  }
  return true;
}

}  // namespace safecell
