#include "safecell/cli/images_show_command.hpp"

#include <filesystem>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "png_output.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/features/blocked_mask.hpp"
#include "safecell/features/feature_extractor.hpp"
#include "safecell/features/noise_bits.hpp"
#include "safecell/reference/median_image.hpp"
#include "safecell/reference/random_configurations.hpp"
#include "safecell/reference/reference_configurations.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "scene_options.hpp"

namespace safecell {
namespace {

constexpr std::size_t kCandidateConfigurations = 40;
constexpr int kStillFrames = 6;  // of the empty cell, to measure the sensor noise
constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// Per camera, the median of frames with the robot in the chosen configurations.
std::vector<cv::Mat> reference_images(SimulatedCell& sim, const CellModel& model,
                                      const ImagesShowOptions& options, std::ostream& out) {
  std::vector<std::array<double, 2>> ranges;
  for (const auto& joint : model.config.joints) {
    const auto& range = joint.range_deg.value();
    ranges.push_back({range[0] * kRadPerDeg, range[1] * kRadPerDeg});
  }
  const auto candidates = random_configurations(ranges, kCandidateConfigurations, options.seed);
  std::vector<std::vector<cv::Mat>> coverage;
  for (const auto& q : candidates) {
    std::vector<cv::Mat> masks;
    for (std::size_t c = 0; c < sim.camera_count(); ++c) masks.push_back(sim.robot_coverage(c, q));
    coverage.push_back(std::move(masks));
  }
  const auto chosen =
      choose_reference_configurations(coverage, static_cast<std::size_t>(options.reference_frames));
  out << "reference: median of " << chosen.size() << " frames, robot configurations chosen from "
      << candidates.size() << " candidates\n";
  std::vector<std::vector<cv::Mat>> frames(sim.camera_count());
  for (const std::size_t k : chosen) {
    const auto rendered = sim.render(SimScene{candidates[k], {}}, 1000 + k, 0.0);
    for (std::size_t c = 0; c < rendered.size(); ++c) frames[c].push_back(rendered[c]);
  }
  std::vector<cv::Mat> references;
  references.reserve(frames.size());
  for (const auto& camera_frames : frames) references.push_back(median_image(camera_frames));
  return references;
}

// The five feature images side by side (the paper's Figure 6), each cell 4 x 4 pixels.
cv::Mat feature_sheet(const FeatureImages& images) {
  std::vector<cv::Mat> tiles;
  tiles.reserve(kAllFeatures.size());
  for (const Feature feature : kAllFeatures) {
    tiles.push_back(labelled(images[feature], 4.0, std::string(feature_name(feature))));
  }
  return contact_sheet(tiles, tiles.size());
}

// The frame in gray with the blocked feature cells tinted red.
cv::Mat blocked_overlay(const cv::Mat& frame, const cv::Mat& blocked, const FeatureGrid& grid) {
  cv::Mat overlay;
  cv::cvtColor(frame, overlay, cv::COLOR_GRAY2BGR);
  for (int row = 0; row < grid.rows(); ++row) {
    for (int column = 0; column < grid.columns(); ++column) {
      if (blocked.at<std::uint8_t>(row, column) == 0) continue;
      cv::Mat cell = overlay(grid.cell_rect_px(FeatureCell{column, row}));
      cell = 0.5 * cell + 0.5 * cv::Scalar(0, 0, 255);
    }
  }
  return overlay;
}

}  // namespace

void run_images_show(const ImagesShowOptions& options, std::ostream& out) {
  const CellModel model = load_cell_model(
      load_cell_file_or_default(options.cell_path));
  if (options.reference_frames < 1 ||
      options.reference_frames > static_cast<int>(kCandidateConfigurations)) {
    bad_option("--reference-frames", std::to_string(options.reference_frames),
               "expected 1 to " + std::to_string(kCandidateConfigurations));
  }
  SimulatedCell sim = simulate_cell(model, SensorSettings{2.0, 0.0, 30.0, options.seed});
  SimScene scene{joint_values_rad("--q", options.q_deg, true, model), {}};
  for (const auto& human : options.humans) scene.humans.push_back(human_of(human));

  const std::vector<cv::Mat> references = reference_images(sim, model, options, out);
  std::vector<std::vector<cv::Mat>> still(sim.camera_count());
  for (int f = 0; f < kStillFrames; ++f) {
    const auto frames = sim.render_surfaces({}, 2000 + static_cast<std::uint64_t>(f), 0.0);
    for (std::size_t c = 0; c < frames.size(); ++c) still[c].push_back(frames[c]);
  }
  const std::vector<cv::Mat> frames = sim.render(scene, 0, 0.0);

  const std::filesystem::path directory(options.out_dir);
  std::filesystem::create_directories(directory);
  for (std::size_t c = 0; c < frames.size(); ++c) {
    const std::string name = sim.camera(c).name();
    FeatureExtractor extractor(model.feature_grid, choose_noise_bits(still[c]));
    const FeatureImages current = extractor.extract(frames[c]);
    const FeatureImages reference = extractor.extract(references[c]);
    const cv::Mat blocked =
        blocked_mask(current, reference, model.feature_weights, model.blocked_threshold);
    write_png(directory / (name + "_frame.png"), frames[c]);
    write_png(directory / (name + "_features.png"), feature_sheet(current));
    write_png(directory / (name + "_reference.png"), references[c]);
    write_png(directory / (name + "_blocked.png"),
              blocked_overlay(frames[c], blocked, model.feature_grid));
    out << name << ": noise cut " << extractor.noise_bits() << " bits, "
        << cv::countNonZero(blocked) << " of " << model.feature_grid.cell_count()
        << " feature cells blocked; wrote " << (directory / (name + "_*.png")).string() << '\n';
  }
}

}  // namespace safecell
