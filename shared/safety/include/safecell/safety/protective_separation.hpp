#pragma once
// ISO/TS 15066 speed and separation monitoring: the protective separation distance
//   S_p = S_h + S_r + S_s + C + Z_d + Z_r
// with S_h = v_h (T_r + T_s) (the human during reaction and stopping), S_r = v_r T_r (the robot
// during reaction), S_s the robot's stopping distance, C the intrusion distance, Z_d and Z_r the
// position uncertainties of sensor and robot. Reported beside the paper's relation.

#include "safecell/base/result.hpp"

namespace safecell {

struct SeparationInputs {
  double human_speed_m_s = 0.0;       // v_h
  double robot_speed_m_s = 0.0;       // v_r, towards the human
  double reaction_time_s = 0.0;       // T_r: sensing, processing and communication
  double stop_time_s = 0.0;           // T_s
  double stop_distance_m = 0.0;       // S_s
  double intrusion_m = 0.0;           // C
  double sensor_uncertainty_m = 0.0;  // Z_d
  double robot_uncertainty_m = 0.0;   // Z_r
};

Result<double> protective_separation_m(const SeparationInputs& inputs) noexcept;

}  // namespace safecell
