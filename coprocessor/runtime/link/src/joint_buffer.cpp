#include "safecell/link/joint_buffer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace safecell {

JointBuffer::JointBuffer(JointBufferLimits limits) : limits_(std::move(limits)) {
  if (limits_.max_acceleration_rad_s2.empty()) {
    throw std::invalid_argument("joint buffer: no joints (max_acceleration_rad_s2 is empty)");
  }
  for (const double a : limits_.max_acceleration_rad_s2) {
    if (!(a > 0.0) || !std::isfinite(a)) {
      throw std::invalid_argument("joint buffer: max_acceleration_rad_s2 must be finite and > 0");
    }
  }
  if (limits_.capacity < 2) throw std::invalid_argument("joint buffer: capacity must be >= 2");
}

bool JointBuffer::add(std::uint64_t time_ns, std::uint64_t time_uncertainty_ns,
                      const std::vector<double>& position_rad,
                      const std::vector<double>& velocity_rad_s) {
  if (position_rad.size() != joint_count() || velocity_rad_s.size() != joint_count()) {
    throw std::invalid_argument("joint buffer: a sample of " + std::to_string(position_rad.size()) +
                                " joints for a robot of " + std::to_string(joint_count()));
  }
  if (!samples_.empty() && time_ns <= samples_.back().time_ns) return false;
  samples_.push_back({time_ns, time_uncertainty_ns, position_rad, velocity_rad_s});
  while (samples_.size() > limits_.capacity) samples_.pop_front();
  return true;
}

JointsAtTime JointBuffer::at(std::uint64_t exposure_ns) const {
  JointsAtTime result;
  if (samples_.empty()) {
    result.unknown_because = "no joint sample yet";
    return result;
  }
  const Sample& newest = samples_.back();
  if (exposure_ns > newest.time_ns && exposure_ns - newest.time_ns > limits_.max_sample_age_ns) {
    result.unknown_because = "the newest joint sample is older than max_sample_age";
    return result;
  }
  if (exposure_ns < samples_.front().time_ns) {
    result.unknown_because = "the exposure is older than every joint sample kept";
    return result;
  }
  const std::size_t joints = joint_count();
  result.position_rad.resize(joints);
  result.error_rad.resize(joints);
  if (exposure_ns >= newest.time_ns) {
    const std::uint64_t ahead = exposure_ns - newest.time_ns;
    if (ahead > limits_.max_extrapolation_ns) {
      result.unknown_because = "the exposure lies beyond max_extrapolation after the newest sample";
      result.position_rad.clear();
      result.error_rad.clear();
      return result;
    }
    const double tau = static_cast<double>(ahead) * 1e-9;
    const double u = static_cast<double>(newest.uncertainty_ns) * 1e-9;
    for (std::size_t j = 0; j < joints; ++j) {
      const double v = newest.velocity_rad_s[j];
      result.position_rad[j] = newest.position_rad[j] + v * tau;
      // The true time since the sample is tau give or take u.
      result.error_rad[j] =
          0.5 * limits_.max_acceleration_rad_s2[j] * (tau + u) * (tau + u) + std::abs(v) * u;
    }
    result.known = true;
    return result;
  }
  // The two samples around the exposure.
  const auto after =
      std::upper_bound(samples_.begin(), samples_.end(), exposure_ns,
                       [](std::uint64_t t, const Sample& sample) { return t < sample.time_ns; });
  const Sample& b = *after;
  const Sample& a = *(after - 1);
  const double dt = static_cast<double>(b.time_ns - a.time_ns) * 1e-9;
  const double s = static_cast<double>(exposure_ns - a.time_ns) * 1e-9 / dt;
  const double u = static_cast<double>(std::max(a.uncertainty_ns, b.uncertainty_ns)) * 1e-9;
  for (std::size_t j = 0; j < joints; ++j) {
    result.position_rad[j] = a.position_rad[j] + s * (b.position_rad[j] - a.position_rad[j]);
    // The fastest the joint moves within u of the interval.
    const double v_max = std::max(std::abs(a.velocity_rad_s[j]), std::abs(b.velocity_rad_s[j])) +
                         limits_.max_acceleration_rad_s2[j] * (dt / 2.0 + u);
    result.error_rad[j] = limits_.max_acceleration_rad_s2[j] * dt * dt / 8.0 + v_max * u;
  }
  result.known = true;
  return result;
}

}  // namespace safecell
