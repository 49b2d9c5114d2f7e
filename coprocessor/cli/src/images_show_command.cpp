#include "safecell/cli/images_show_command.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "command_line.hpp"
#include "png_output.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/features/blocked_mask.hpp"
#include "safecell/features/feature_extractor.hpp"
#include "safecell/features/noise_bits.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim_sources/simulated_reference.hpp"
#include "scene_options.hpp"

namespace safecell {
namespace {

constexpr std::size_t kCandidateConfigurations = 40;
constexpr int kStillFrames = 6;  // of the empty cell, to measure the sensor noise

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
  const CellModel model = load_cell_model(load_cell_file_or_default(options.cell_path));
  if (options.reference_frames < 1 ||
      options.reference_frames > static_cast<int>(kCandidateConfigurations)) {
    bad_option("--reference-frames", std::to_string(options.reference_frames),
               "expected 1 to " + std::to_string(kCandidateConfigurations));
  }
  SimulatedCell sim = simulate_cell(model, SensorSettings{2.0, 0.0, 30.0, options.seed});
  SimScene scene{joint_values_rad("--q", options.q_deg, true, model), {}};
  for (const auto& human : options.humans) scene.humans.push_back(human_of(human));

  const SimulatedReference median =
      simulated_reference(sim, model, static_cast<std::size_t>(options.reference_frames),
                          options.seed, kCandidateConfigurations);
  out << "reference: median of " << median.configurations.size()
      << " frames, robot configurations chosen from " << median.candidates << " candidates\n";
  const std::vector<cv::Mat>& references = median.frames;
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

void add_images_show_command(CLI::App& images, CommandLine& line) {
  const auto show = std::make_shared<ImagesShowOptions>();
  CLI::App* show_command = images.add_subcommand(
      "show",
      "Write, per camera of the simulated cell, the frame, its five feature images, the reference "
      "image and the blocked feature cells over the frame (PNG)");
  show_command->add_option("--cell", show->cell_path,
                           "Cell file (YAML); without it the built-in default cell");
  show_command->add_option("--q", show->q_deg, "Joint values of the shown frame in degrees")
      ->capture_default_str();
  show_command->add_option("--human", show->humans, "A human at x,y[,heading_deg]; repeat for more")
      ->capture_default_str();
  show_command->add_option("--out", show->out_dir, "Folder for the PNG files")->required();
  show_command
      ->add_option("--seed", show->seed, "Seed of the noise and the candidate configurations")
      ->capture_default_str();
  show_command
      ->add_option("--reference-frames", show->reference_frames,
                   "Frames in the median reference image (the paper: 9)")
      ->capture_default_str();
  show_command->callback(
      [=, &line] { line.action = [=, &line] { run_images_show(*show, line.out); }; });
}

}  // namespace safecell
