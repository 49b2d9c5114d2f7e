#include "safecell/safety/protective_separation.hpp"

#include "safecell/base/freestanding_math.hpp"

namespace safecell {

Result<double> protective_separation_m(const SeparationInputs& in) noexcept {
  const double all[] = {in.human_speed_m_s,      in.robot_speed_m_s,    in.reaction_time_s,
                        in.stop_time_s,          in.stop_distance_m,    in.intrusion_m,
                        in.sensor_uncertainty_m, in.robot_uncertainty_m};
  for (const double value : all) {
    if (!is_finite_non_negative(value)) return Status::kInvalidArgument;
  }
  const double human_m = in.human_speed_m_s * (in.reaction_time_s + in.stop_time_s);
  const double robot_m = in.robot_speed_m_s * in.reaction_time_s;
  return human_m + robot_m + in.stop_distance_m + in.intrusion_m + in.sensor_uncertainty_m +
         in.robot_uncertainty_m;
}

}  // namespace safecell
