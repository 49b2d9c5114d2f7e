#pragma once
// The smart buffer of paper §4.5: the robot's joints at any camera exposure time, from the joint
// stream, with a bound on their error.
//
// Samples are stamped in the coprocessor's clock (the logical sensor converts the controller's
// read time with ClockSync), so every stamp is uncertain by the clock offset's uncertainty u.
//   between two samples  linear interpolation; error <= a_max dt^2 / 8 (the largest deviation of
//                        a motion with |acceleration| <= a_max from its chord over dt) + v_max u,
//                        v_max = max(|v_a|, |v_b|) + a_max (dt / 2 + u)
//   after the last one   extrapolation with its velocity, up to max_extrapolation;
//                        error <= a_max (tau + u)^2 / 2 + |v| u
// Outside that (before the oldest sample kept, further ahead, or a newest sample older than
// max_sample_age at the exposure) the pose is unknown: the caller must then treat the robot as
// anywhere it could be (DESIGN.md: the cycle forbids what an unknown robot pose requires).
// Joint i's error turns into a distance at the robot by l_i (the removal mask widens by it).
// Thread context: the link thread adds, the pipeline reads: not synchronised (callers lock).

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace safecell {

struct JointBufferLimits {
  std::vector<double> max_acceleration_rad_s2;  // a_max per joint (the robot's limits)
  std::uint64_t max_extrapolation_ns = 20'000'000;
  std::uint64_t max_sample_age_ns = 50'000'000;  // the newest sample may be this old at most
  std::size_t capacity = 256;                    // samples kept
};

struct JointsAtTime {
  bool known = false;
  std::string unknown_because;       // when not known
  std::vector<double> position_rad;  // per joint
  std::vector<double> error_rad;     // per joint: |true - returned| <= error
};

class JointBuffer {
 public:
  explicit JointBuffer(JointBufferLimits limits);

  // A sample of the joint stream: its time in the coprocessor's clock and that time's uncertainty.
  // Samples must come in time order; an older or equal one is ignored (returns false).
  bool add(std::uint64_t time_ns, std::uint64_t time_uncertainty_ns,
           const std::vector<double>& position_rad, const std::vector<double>& velocity_rad_s);

  JointsAtTime at(std::uint64_t exposure_ns) const;

  std::size_t size() const { return samples_.size(); }
  std::size_t joint_count() const { return limits_.max_acceleration_rad_s2.size(); }

 private:
  struct Sample {
    std::uint64_t time_ns;
    std::uint64_t uncertainty_ns;
    std::vector<double> position_rad;
    std::vector<double> velocity_rad_s;
  };
  JointBufferLimits limits_;
  std::deque<Sample> samples_;
};

}  // namespace safecell
