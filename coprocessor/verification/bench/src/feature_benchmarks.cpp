// The image pipeline up to the blocked masks on the paper's set-up: 4 frames of 704 x 576 ->
// noise cut -> feature images (64 x 64 cells of 11 x 9 px) -> 4 blocked masks against 4 reference
// feature images. Target (DESIGN.md section 5): <= 1 ms per cycle on one core. Reported, never
// asserted. The frames come from the simulated default cell, rendered once before timing: the
// reference without a human, the current frames with one walking near the robot.
#include "safecell/bench/project_benchmarks.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/features/blocked_mask.hpp"
#include "safecell/features/feature_extractor.hpp"
#include "safecell/features/noise_bits.hpp"
#include "safecell/features/noise_cut.hpp"
#include "safecell/health/camera_health_monitor.hpp"
#include "safecell/sim/cell_simulation.hpp"

namespace safecell {
namespace {

constexpr int kStillFrames = 8;  // per camera, to choose the noise bits
constexpr FeatureWeights kWeights = kDefaultFeatureWeights;
constexpr int kThreshold = kDefaultBlockedThreshold;

struct CameraSetUp {
  FeatureGrid grid;
  int noise_bits = 0;
  FeatureImages reference;
  cv::Mat current_frame;  // with the human
  cv::Mat empty_frame;    // without, new noise: shows what the threshold lets through
};

std::vector<CameraSetUp> render_set_up() {
  const CellModel model = load_cell_model(default_cell());
  SimulatedCell sim = simulate_cell(model, SensorSettings{});
  const std::vector<double> q{0.6, 0.3, 0.8, 0.0, 0.5, 0.0};
  HumanPose human;
  human.position_m = Eigen::Vector2d(1.0, -0.8);
  human.heading_rad = 2.5;

  std::vector<CameraSetUp> cameras(sim.camera_count());
  std::vector<std::vector<cv::Mat>> still(sim.camera_count());
  for (std::uint64_t frame = 0; frame < kStillFrames; ++frame) {
    const std::vector<cv::Mat> frames = sim.render(SimScene{q, {}}, frame, 0.0);
    for (std::size_t c = 0; c < frames.size(); ++c) still[c].push_back(frames[c]);
  }
  const std::vector<cv::Mat> empty = sim.render(SimScene{q, {}}, 100, 0.0);
  const std::vector<cv::Mat> with_human = sim.render(SimScene{q, {human}}, 101, 0.0);
  const std::vector<cv::Mat> empty_again = sim.render(SimScene{q, {}}, 102, 0.0);
  FeatureExtractor extractor(model.feature_grid);
  for (std::size_t c = 0; c < cameras.size(); ++c) {
    cameras[c].grid = model.feature_grid;
    cameras[c].noise_bits = choose_noise_bits(still[c]);
    cv::Mat cut;
    cut_noise_bits(empty[c], cameras[c].noise_bits, cut);
    cameras[c].reference = extractor.extract(cut);
    cameras[c].current_frame = with_human[c];
    cameras[c].empty_frame = empty_again[c];
  }
  return cameras;
}

const std::vector<CameraSetUp>& set_up() {
  static const std::vector<CameraSetUp> cameras = render_set_up();
  return cameras;
}

// Blocked cells over the four cameras with the human, and in an empty scene (false alarms).
void report_blocked_cells(benchmark::State& state, const std::vector<cv::Mat>& masks) {
  int blocked = 0;
  for (const cv::Mat& mask : masks) blocked += cv::countNonZero(mask);
  state.counters["blocked_cells"] = blocked;
  int false_alarms = 0;
  for (const CameraSetUp& camera : set_up()) {
    const FeatureImages empty =
        FeatureExtractor(camera.grid, camera.noise_bits).extract(camera.empty_frame);
    false_alarms += cv::countNonZero(blocked_mask(empty, camera.reference, kWeights, kThreshold));
  }
  state.counters["blocked_cells_empty_scene"] = false_alarms;
}

// The production path: each extractor cuts the noise bits as it reads its frame.
void four_frames_to_blocked_masks(benchmark::State& state) {
  const std::vector<CameraSetUp>& cameras = set_up();
  std::vector<FeatureExtractor> extractors;
  extractors.reserve(cameras.size());
  for (const CameraSetUp& camera : cameras) extractors.emplace_back(camera.grid, camera.noise_bits);
  std::vector<FeatureImages> images(cameras.size());
  std::vector<cv::Mat> masks(cameras.size());
  while (state.KeepRunning()) {
    for (std::size_t c = 0; c < cameras.size(); ++c) {
      extractors[c].extract(cameras[c].current_frame, images[c]);
      masks[c] = blocked_mask(images[c], cameras[c].reference, kWeights, kThreshold);
    }
    benchmark::DoNotOptimize(masks.data());
    benchmark::ClobberMemory();
  }
  report_blocked_cells(state, masks);
}

// The same with the noise cut as a pass of its own (cut_noise_bits, then the features).
void four_frames_to_blocked_masks_separate_cut(benchmark::State& state) {
  const std::vector<CameraSetUp>& cameras = set_up();
  std::vector<FeatureExtractor> extractors;
  extractors.reserve(cameras.size());
  for (const CameraSetUp& camera : cameras) extractors.emplace_back(camera.grid);
  std::vector<cv::Mat> cut(cameras.size());
  std::vector<FeatureImages> images(cameras.size());
  std::vector<cv::Mat> masks(cameras.size());
  while (state.KeepRunning()) {
    for (std::size_t c = 0; c < cameras.size(); ++c) {
      cut_noise_bits(cameras[c].current_frame, cameras[c].noise_bits, cut[c]);
      extractors[c].extract(cut[c], images[c]);
      masks[c] = blocked_mask(images[c], cameras[c].reference, kWeights, kThreshold);
    }
    benchmark::DoNotOptimize(masks.data());
    benchmark::ClobberMemory();
  }
  report_blocked_cells(state, masks);
}

// The feature images of one frame alone: the bulk of the cycle.
void feature_images_of_one_frame(benchmark::State& state) {
  const CameraSetUp& camera = set_up()[0];
  FeatureExtractor extractor(camera.grid, camera.noise_bits);
  FeatureImages images;
  while (state.KeepRunning()) {
    extractor.extract(camera.current_frame, images);
    benchmark::ClobberMemory();
  }
}

// One camera's health check of a frame (camera_health_monitor.hpp), as the service runs it on
// every camera every cycle: the frame with the human and a frame of the empty cell in turn, against
// the empty cell's reference. Counter "faults": frames the check found faulty, which return before
// the alignment and so time less than a healthy frame; 0 when the figure is the healthy path's.
void camera_health_check_one_frame(benchmark::State& state) {
  const CameraSetUp& camera = set_up()[0];
  CameraHealthMonitor monitor("cam0", camera.empty_frame);
  const cv::Mat* frames[] = {&camera.current_frame, &camera.empty_frame};
  std::size_t checked = 0;
  double faults = 0.0;
  while (state.KeepRunning()) {
    const HealthReport report = monitor.check(*frames[checked++ % 2]);
    faults += report.healthy() ? 0.0 : 1.0;
    benchmark::DoNotOptimize(report);
  }
  state.counters["faults"] = faults;
}

}  // namespace

void register_feature_benchmarks() {
  register_benchmark("four_frames_to_blocked_masks", four_frames_to_blocked_masks,
                     benchmark::kMillisecond);
  register_benchmark("four_frames_to_blocked_masks_separate_cut",
                     four_frames_to_blocked_masks_separate_cut, benchmark::kMillisecond);
  register_benchmark("feature_images_of_one_frame", feature_images_of_one_frame,
                     benchmark::kMillisecond);
  register_benchmark("camera_health_check_one_frame", camera_health_check_one_frame,
                     benchmark::kMillisecond);
}

}  // namespace safecell
