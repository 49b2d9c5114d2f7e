#pragma once
// What defines a C-space grid: the joints' ranges and lever arms, and the max-move distance.

#include <cstdint>

#include "safecell/base/status.hpp"

namespace safecell {

inline constexpr std::uint32_t kMaxJoints = 8;

struct JointSpec {
  double lo_rad = 0.0;
  double hi_rad = 0.0;
  // l_i: the largest distance from the joint's axis to any point of the robot the joint moves.
  double l_m = 0.0;
  // false: the joint (typically a wrist joint with small l_i) gets a single cell, and every
  // cell's envelope sweeps it over its whole range.
  bool discretised = true;
};

struct GridSpec {
  // m_max: the largest distance any point of the robot may move within one cell step.
  double m_max_m = 0.0;
  std::uint32_t joint_count = 0;
  JointSpec joints[kMaxJoints]{};
};

// Which part of a GridSpec was refused, so that a caller can name the offending field.
enum class GridField : std::uint8_t {
  kJointCount,  // 0 or more than kMaxJoints joints
  kMaxMove,     // m_max_m not finite and positive
  kRange,       // lo_rad/hi_rad not finite, or lo_rad >= hi_rad (joint set)
  kLeverArm,    // l_m not finite, negative, or (discretised) smaller than m_max_m / 2 (joint set)
  kCellCount,  // the joint's or the grid's cell count does not fit 32 bits (joint set if per joint)
};

struct GridSpecError {
  Status status = Status::kInvalidArgument;
  GridField field = GridField::kJointCount;
  std::uint8_t joint = 0;  // the offending joint, for per-joint fields
};

const char* to_string(GridField field) noexcept;

}  // namespace safecell
