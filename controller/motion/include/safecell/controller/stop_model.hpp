#pragma once
// How long a joint takes to stop from a speed: t_d(v) = latency + |v| / deceleration. The host
// module measures both from its simulated robot at init (controller/host/simulated_robot.hpp); a
// real robot's come from its stopping-time data (ISO 10218 annex: stop category, speed, load).
// Real-time safe.

#include <cstdint>

#include "safecell/cspace/grid_spec.hpp"

namespace safecell {

struct JointStop {
  double latency_s = 0.0;     // from the stop command to the deceleration starting
  double decel_rad_s2 = 1.0;  // the deceleration the joint holds while it stops (> 0)
};

struct StopModel {
  std::uint32_t joint_count = 0;
  JointStop joints[kMaxJoints]{};

  // t_d for joint j moving at speed_rad_s (its magnitude counts).
  double stop_time_s(std::uint32_t joint, double speed_rad_s) const noexcept;
  // The angle joint j travels while it stops from speed_rad_s.
  double stop_distance_rad(std::uint32_t joint, double speed_rad_s) const noexcept;
  // Every joint has a finite latency >= 0 and a finite deceleration > 0.
  bool valid() const noexcept;
};

}  // namespace safecell
