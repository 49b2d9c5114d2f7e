#include "safecell/sim/human_figure.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace safecell {
namespace {

// A 1.75 m adult. Heights and lengths from the segment-length fractions of body height H
// (Drillis and Contini, as tabulated in D. A. Winter, "Biomechanics and Motor Control of Human
// Movement"): hip joint 0.530 H = 0.93 m, knee 0.285 H = 0.50 m, shoulder 0.818 H = 1.43 m,
// chin 0.870 H = 1.52 m, upper arm 0.186 H = 0.33 m, forearm and hand (0.146 + 0.108) H = 0.44 m.
// Shoulder joints 0.40 m apart (biacromial breadth), hip joints 0.18 m apart.
// Capsule radii are rounded girths: thigh 0.08 m, shank 0.06 m, upper arm 0.06 m,
// forearm and hand 0.05 m, torso 0.15 m (its cap reaches from the crotch to the chin);
// the head is a sphere of radius 0.11 m whose top is the body height.
constexpr double kHipHeight_m = 0.93;  // standing, = thigh + shank + shank radius
constexpr double kHipHalfSpacing_m = 0.09;
constexpr double kThighLength_m = 0.43;  // hip to knee
constexpr double kThighRadius_m = 0.08;
constexpr double kShankLength_m = 0.44;  // knee to the centre of the cap that is the sole
constexpr double kShankRadius_m = 0.06;
constexpr double kTorsoTop_m = 1.38;  // upper end of the torso's axis; its cap ends at the chin
constexpr double kTorsoRadius_m = 0.15;
constexpr double kHeadCentre_m = 1.64;
constexpr double kHeadRadius_m = 0.11;
constexpr double kShoulderHeight_m = 1.43;
constexpr double kShoulderHalfWidth_m = 0.20;
constexpr double kUpperArmLength_m = 0.33;  // shoulder to elbow
constexpr double kUpperArmRadius_m = 0.06;
constexpr double kForearmLength_m = 0.39;  // elbow to the centre of the fingertip cap
constexpr double kForearmRadius_m = 0.05;

// Gait: sagittal angles from the vertical, positive forward, at gait_amplitude 1.
constexpr double kHipSwing_rad = 0.30;   // thigh swing amplitude
constexpr double kKneeFlex_rad = 0.60;   // largest knee flexion, in mid-swing
constexpr double kArmSwing_rad = 0.25;   // upper arm swing amplitude, opposite to the leg
constexpr double kElbowFlex_rad = 0.20;  // relaxed elbow, always

struct LimbAngles {
  double upper_rad = 0.0;  // upper segment from the vertical, positive forward
  double lower_rad = 0.0;  // lower segment from the vertical, positive forward
};

// A leg at its own phase: the thigh swings sinusoidally; the knee flexes while the thigh swings
// forward (the swing phase) and is straight while it swings back (the stance phase).
LimbAngles leg_angles(double leg_phase_rad, double amplitude) {
  const double thigh_rad = amplitude * kHipSwing_rad * std::sin(leg_phase_rad);
  const double knee_rad = amplitude * kKneeFlex_rad * std::max(0.0, std::cos(leg_phase_rad));
  return {thigh_rad, thigh_rad - knee_rad};
}

// Height of the sole's cap centre below the hip joint.
double leg_drop_m(const LimbAngles& leg) {
  return kThighLength_m * std::cos(leg.upper_rad) + kShankLength_m * std::cos(leg.lower_rad);
}

// Unit vector of a limb segment in the body frame (x forward, y left, z up).
Eigen::Vector3d limb_direction(double angle_rad) {
  return {std::sin(angle_rad), 0.0, -std::cos(angle_rad)};
}

PlacedShape capsule_between(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double radius_m,
                            const Eigen::Isometry3d& body_to_cell) {
  const Eigen::Vector3d axis = to - from;
  Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
  local.translation() = (from + to) / 2.0;
  local.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).matrix();
  return {Capsule{radius_m, axis.norm()}, body_to_cell * local};
}

struct Segment {
  double length_m;
  double radius_m;
};

// Appends the two capsules of a limb hanging from `root`.
void add_limb(std::vector<PlacedShape>& shapes, const Eigen::Vector3d& root,
              const LimbAngles& angles, Segment upper, Segment lower,
              const Eigen::Isometry3d& body_to_cell) {
  const Eigen::Vector3d joint = root + upper.length_m * limb_direction(angles.upper_rad);
  const Eigen::Vector3d end = joint + lower.length_m * limb_direction(angles.lower_rad);
  shapes.push_back(capsule_between(root, joint, upper.radius_m, body_to_cell));
  shapes.push_back(capsule_between(joint, end, lower.radius_m, body_to_cell));
}

}  // namespace

std::vector<PlacedShape> human_shapes(const HumanPose& pose) {
  const double amplitude = pose.gait_amplitude;
  const LimbAngles left_leg = leg_angles(pose.gait_phase_rad, amplitude);
  const LimbAngles right_leg = leg_angles(pose.gait_phase_rad + std::numbers::pi, amplitude);
  // The pelvis sinks until the longer-reaching leg stands on the floor.
  const double hip_z_m = std::max(leg_drop_m(left_leg), leg_drop_m(right_leg)) + kShankRadius_m;
  const double sink_m = hip_z_m - kHipHeight_m;

  const Eigen::Isometry3d body_to_cell =
      Eigen::Translation3d(pose.position_m.x(), pose.position_m.y(), 0.0) *
      Eigen::AngleAxisd(pose.heading_rad, Eigen::Vector3d::UnitZ());

  std::vector<PlacedShape> shapes;
  shapes.reserve(kHumanPartCount);
  shapes.push_back(capsule_between({0.0, 0.0, hip_z_m}, {0.0, 0.0, kTorsoTop_m + sink_m},
                                   kTorsoRadius_m, body_to_cell));
  Eigen::Isometry3d head = body_to_cell;
  head.translate(Eigen::Vector3d(0.0, 0.0, kHeadCentre_m + sink_m));
  shapes.push_back({Sphere{kHeadRadius_m}, head});

  // Each arm swings with the opposite leg.
  const double arm_swing_rad = amplitude * kArmSwing_rad * std::sin(pose.gait_phase_rad);
  for (const double side : {1.0, -1.0}) {  // left, right
    const bool reaching = side < 0.0 && pose.right_arm_reach_rad > 0.0;
    const double upper_rad =
        reaching ? pose.right_arm_reach_rad : pose.arm_raise_rad - side * arm_swing_rad;
    const double elbow_rad = reaching ? 0.0 : kElbowFlex_rad;
    add_limb(shapes, {0.0, side * kShoulderHalfWidth_m, kShoulderHeight_m + sink_m},
             {upper_rad, upper_rad + elbow_rad}, {kUpperArmLength_m, kUpperArmRadius_m},
             {kForearmLength_m, kForearmRadius_m}, body_to_cell);
  }
  for (const auto& [side, leg] : {std::pair{1.0, left_leg}, std::pair{-1.0, right_leg}}) {
    add_limb(shapes, {0.0, side * kHipHalfSpacing_m, hip_z_m}, leg,
             {kThighLength_m, kThighRadius_m}, {kShankLength_m, kShankRadius_m}, body_to_cell);
  }
  return shapes;
}

}  // namespace safecell
