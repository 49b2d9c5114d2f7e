#include "safecell/reference/reference_configurations.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/reference/median_image.hpp"
#include "safecell/sim/cell_simulation.hpp"

namespace safecell {
namespace {

// Three "cameras" of one 1 x 4 image each; candidates cover pixel sets.
cv::Mat row(std::initializer_list<int> covered) {
  cv::Mat mask = cv::Mat::zeros(1, 4, CV_8UC1);
  for (const int x : covered) mask.at<std::uint8_t>(0, x) = 255;
  return mask;
}

TEST(ReferenceConfigurations, PrefersConfigurationsThatShareNoPixels) {
  // 0 and 1 overlap on pixel 1; 2 is disjoint from both.
  const std::vector<std::vector<cv::Mat>> coverage{{row({0, 1})}, {row({1, 2})}, {row({3})}};
  const auto chosen = choose_reference_configurations(coverage, 2);
  ASSERT_EQ(chosen.size(), 2u);
  // The first pick costs its pixel count (2, 2, 1): candidate 2; then 0 (no overlap, cost 2).
  EXPECT_EQ(chosen[0], 2u);
  EXPECT_EQ(chosen[1], 0u);
  const auto counts = coverage_counts(coverage, chosen);
  EXPECT_EQ(counts[0].at<std::uint16_t>(0, 1), 1);
  EXPECT_THROW(static_cast<void>(choose_reference_configurations(coverage, 4)),
               std::invalid_argument);
  EXPECT_THROW(static_cast<void>(choose_reference_configurations(coverage, 0)),
               std::invalid_argument);
  const std::vector<std::vector<cv::Mat>> uneven{{row({0})}, {row({1}), row({2})}};
  EXPECT_THROW(static_cast<void>(choose_reference_configurations(uneven, 1)),
               std::invalid_argument);
}

// The paper's Figure 7: the median of frames with the robot in chosen configurations shows the
// empty cell wherever the robot stands in fewer than half of them.
TEST(ReferenceConfigurations, TheMedianRemovesTheRobotOnTheSimulatedCell) {
  SimulatedCell sim =
      simulate_cell(load_cell_model(default_cell()), SensorSettings{0.0, 0.0, 30.0, 1});
  // Candidates: the base joint at 12 angles with the arm leaning out, and at 12 with it upright.
  std::vector<std::vector<double>> candidates;
  for (int k = 0; k < 24; ++k) {
    const double base = (-150.0 + 25.0 * (k % 12)) * std::numbers::pi / 180.0;
    candidates.push_back(k < 12 ? std::vector<double>{base, 0.9, 0.9, 0.0, 0.5, 0.0}
                                : std::vector<double>{base, -0.3, 1.2, 0.0, -0.8, 0.0});
  }
  std::vector<std::vector<cv::Mat>> coverage;
  for (const auto& q : candidates) {
    std::vector<cv::Mat> masks;
    for (std::size_t c = 0; c < sim.camera_count(); ++c) masks.push_back(sim.robot_coverage(c, q));
    coverage.push_back(masks);
  }
  constexpr std::size_t kFrames = 9;
  const auto chosen = choose_reference_configurations(coverage, kFrames);
  std::vector<std::vector<cv::Mat>> frames(sim.camera_count());
  for (const std::size_t k : chosen) {
    const auto rendered = sim.render(SimScene{candidates[k], {}}, k, 0.0);
    for (std::size_t c = 0; c < rendered.size(); ++c) frames[c].push_back(rendered[c]);
  }
  const auto empty = sim.render_surfaces({}, 0, 0.0);
  const auto counts = coverage_counts(coverage, chosen);
  for (std::size_t c = 0; c < sim.camera_count(); ++c) {
    const cv::Mat median = median_image(frames[c]);
    // Covered in at most 4 of the 9: the median is the empty cell's pixel, exactly.
    const cv::Mat removable = counts[c] <= 4;
    cv::Mat differs = median != empty[c];
    cv::bitwise_and(differs, removable, differs);
    EXPECT_EQ(cv::countNonZero(differs), 0) << "camera " << c;
    // What stays is the base, covered in every configuration; the arm is gone.
    const cv::Mat kept = counts[c] > 4;
    const cv::Mat base = counts[c] == kFrames;
    EXPECT_LT(cv::countNonZero(kept), cv::countNonZero(base) + 400) << "camera " << c;
    EXPECT_GT(cv::countNonZero(removable & (counts[c] > 0)), 5000) << "camera " << c;
  }
}

}  // namespace
}  // namespace safecell
