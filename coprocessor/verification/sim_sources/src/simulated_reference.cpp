#include "safecell/sim_sources/simulated_reference.hpp"

#include <array>
#include <numbers>

#include "safecell/reference/median_image.hpp"
#include "safecell/reference/random_configurations.hpp"
#include "safecell/reference/reference_configurations.hpp"

namespace safecell {

SimulatedReference simulated_reference(SimulatedCell& sim, const CellModel& cell,
                                       std::size_t frames, std::uint64_t seed,
                                       std::size_t candidates) {
  constexpr double kRadPerDeg = std::numbers::pi / 180.0;
  std::vector<std::array<double, 2>> ranges;
  for (const auto& joint : cell.config.joints) {
    const auto& range = joint.range_deg.value();
    ranges.push_back({range[0] * kRadPerDeg, range[1] * kRadPerDeg});
  }
  const auto configurations = random_configurations(ranges, candidates, seed);
  std::vector<std::vector<cv::Mat>> coverage;
  coverage.reserve(configurations.size());
  for (const auto& q : configurations) {
    std::vector<cv::Mat> masks;
    for (std::size_t c = 0; c < sim.camera_count(); ++c) masks.push_back(sim.robot_coverage(c, q));
    coverage.push_back(std::move(masks));
  }
  const auto chosen = choose_reference_configurations(coverage, frames);
  SimulatedReference reference;
  reference.candidates = candidates;
  std::vector<std::vector<cv::Mat>> per_camera(sim.camera_count());
  for (const std::size_t k : chosen) {
    reference.configurations.push_back(configurations[k]);
    const auto rendered = sim.render(SimScene{configurations[k], {}}, 1000 + k, 0.0);
    for (std::size_t c = 0; c < rendered.size(); ++c) per_camera[c].push_back(rendered[c]);
  }
  for (const auto& camera_frames : per_camera)
    reference.frames.push_back(median_image(camera_frames));
  return reference;
}

}  // namespace safecell
