#include "safecell/pipeline/sensing_pipeline.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

#include "safecell/acquisition/exposure_sync.hpp"
#include "safecell/cell/entry_zones.hpp"
#include "safecell/features/blocked_mask.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"

namespace safecell {
namespace {

// The robot's silhouette at its configuration, for occlusion-aware removal; none when the cell
// has no robot model or its motion within the sync error is unbounded.
std::optional<ConfigurationSilhouettes> silhouettes_at_configuration(
    const CellModel& cell, const CspaceGrid& grid, const FusionSettings& settings) {
  if (settings.removal != RobotRemoval::kOcclusionAware || !cell.robot) return std::nullopt;
  const auto widening =
      removal_widening_m(*cell.robot, grid, settings.padding_m, settings.sync_error_s);
  if (!widening) return std::nullopt;
  return std::optional<ConfigurationSilhouettes>(std::in_place, cell, cell.ball_radius_m,
                                                 *widening);
}

// The protective separation check the cell file asks for; none when it turns it off, the cell
// has no robot model or the robot's motion within the sync error is unbounded.
std::optional<ProtectiveSeparation> separation_check(const CellModel& cell, const CspaceGrid& grid,
                                                     const LutSet& luts,
                                                     const FusionSettings& settings) {
  if (!cell.config.protective_separation || !cell.robot) return std::nullopt;
  const auto widening =
      removal_widening_m(*cell.robot, grid, settings.padding_m, settings.sync_error_s);
  if (!widening) return std::nullopt;
  return std::optional<ProtectiveSeparation>(
      std::in_place, cell, luts.parts, cell.ball_radius_m, *widening,
      separation_levels(*cell.config.protective_separation, cell.config.protective_reduced_speeds),
      settings.camera_threshold);
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

SensingPipeline::SensingPipeline(const CellModel& cell, const CspaceGrid& grid, const LutSet& luts,
                                 const RobotSilhouettes& silhouettes,
                                 const std::vector<cv::Mat>& reference_frames,
                                 const std::vector<int>& noise_bits, const FusionSettings& settings)
    : cell_(cell),
      grid_(grid),
      at_configuration_(silhouettes_at_configuration(cell, grid, settings)),
      fusion_(luts, silhouettes, settings, at_configuration_ ? &*at_configuration_ : nullptr),
      separation_(separation_check(cell, grid, luts, settings)),
      sync_error_s_(settings.sync_error_s) {
  const std::size_t cameras = cell.cameras.size();
  if (reference_frames.size() != cameras || (!noise_bits.empty() && noise_bits.size() != cameras) ||
      luts.cameras.size() != cameras) {
    throw std::invalid_argument("sensing pipeline: " + std::to_string(cameras) + " cameras, " +
                                std::to_string(reference_frames.size()) + " reference images, " +
                                std::to_string(luts.cameras.size()) + " LUT cameras");
  }
  for (std::size_t c = 0; c < cameras; ++c) {
    if (luts.cameras[c].camera != cell.cameras[c].name()) {
      throw std::invalid_argument("LUT camera " + std::to_string(c) + " is '" +
                                  luts.cameras[c].camera + "', the cell's is '" +
                                  cell.cameras[c].name() + "'");
    }
    extractors_.emplace_back(cell.feature_grid, noise_bits.empty() ? 0 : noise_bits[c]);
    references_.push_back(extractors_.back().extract(reference_frames[c]));
  }
  current_.resize(cameras);
  observations_.assign(cameras, CameraObservation{false, FeatureMask(cell.feature_grid)});
}

const CellSet& SensingPipeline::process(const FrameSet& frames, const std::vector<double>& q) {
  if (frames.frames.size() != cell_.cameras.size()) {
    throw std::invalid_argument("a frame set of " + std::to_string(frames.frames.size()) +
                                " cameras for a cell of " + std::to_string(cell_.cameras.size()));
  }
  // A copy holds only image headers; out-of-sync views become unknown in it.
  FrameSet checked = frames;
  out_of_sync_views_ =
      sync_error_s_ > 0.0 ? reject_out_of_sync_exposures(checked, 2.0 * sync_error_s_) : 0;
  images_.resize(checked.frames.size());
  for (std::size_t c = 0; c < checked.frames.size(); ++c) {
    const CameraFrame& frame = checked.frames[c];
    if (frame.camera != cell_.cameras[c].name()) {
      throw std::invalid_argument("frame set camera " + std::to_string(c) + " is '" + frame.camera +
                                  "', the cell's is '" + cell_.cameras[c].name() + "'");
    }
    images_[c] = frame.known() ? frame.image : cv::Mat();
  }
  return process(images_, q);
}

const CellSet& SensingPipeline::process(const std::vector<cv::Mat>& frames,
                                        const std::vector<double>& q) {
  if (frames.size() != extractors_.size()) {
    throw std::invalid_argument(std::to_string(frames.size()) + " frames for " +
                                std::to_string(extractors_.size()) + " cameras");
  }
  JointAngles angles;
  if (q.size() != grid_.joint_count()) throw std::invalid_argument("wrong number of joint values");
  for (std::size_t j = 0; j < q.size(); ++j) angles.rad[j] = q[j];
  const auto cell = grid_.cell_containing(angles);
  if (!cell.ok()) throw std::out_of_range("the robot's configuration is outside the C-space grid");
  robot_cell_ = cell.value();

  const auto start = std::chrono::steady_clock::now();
  for (std::size_t c = 0; c < frames.size(); ++c) {
    CameraObservation& observation = observations_[c];
    observation.known = !frames[c].empty();
    if (!observation.known) continue;
    extractors_[c].extract(frames[c], current_[c]);
    observation.blocked = FeatureMask::from_image(
        blocked_mask(current_[c], references_[c], cell_.feature_weights, cell_.blocked_threshold));
  }
  times_.features_ms = ms_since(start);
  const auto fusion_start = std::chrono::steady_clock::now();
  fusion_.remove_robot(observations_, robot_cell_, q);
  verdict_ = SeparationVerdict{};
  if (separation_) {
    known_.resize(observations_.size());
    obstacles_.resize(observations_.size());
    for (std::size_t c = 0; c < observations_.size(); ++c) {
      known_[c] = observations_[c].known;
      obstacles_[c] = &fusion_.obstacles(c);
    }
    verdict_ = separation_->check(q, known_, obstacles_);
  }
  const CellSet& forbidden = skip_map_when_too_close_ && verdict_.too_close
                                 ? fusion_.forbid_all()
                                 : fusion_.vote(observations_);
  times_.fusion_ms = ms_since(fusion_start);
  return forbidden;
}

}  // namespace safecell
