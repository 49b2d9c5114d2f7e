#pragma once
// One cycle of the coprocessor's sensing (DESIGN.md §1): the frames of every camera -> noise cut
// and feature images -> blocked masks against the reference -> fusion with the robot's
// configuration at the exposure time -> the forbidden map. A camera without a frame (an empty
// image) has an unknown view. Not thread-safe; after the first cycle it allocates little.

#include <opencv2/core/mat.hpp>
#include <optional>
#include <vector>

#include "safecell/acquisition/frame_set.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/features/feature_extractor.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"
#include "safecell/separation/protective_separation.hpp"

namespace safecell {

struct CycleTimes {
  double features_ms = 0.0;  // frames to blocked masks, all cameras
  // robot removal, the separation check, back-projection, threshold, static
  double fusion_ms = 0.0;
};

class SensingPipeline {
 public:
  // reference_frames: per camera, the reference image (CV_8UC1 of the camera's size).
  // noise_bits: per camera, or empty for none. Keeps references to `luts` and `silhouettes`.
  // Occlusion-aware removal takes the robot's silhouette at its configuration from the cell's
  // robot model (configuration_silhouettes.hpp), widened by settings.padding_m and the motion
  // within settings.sync_error_s; a cell whose URDF gives no speed limits falls back to LUT-1.
  // Throws std::invalid_argument when the counts or sizes do not match the cell.
  SensingPipeline(const CellModel& cell, const CspaceGrid& grid, const LutSet& luts,
                  const RobotSilhouettes& silhouettes, const std::vector<cv::Mat>& reference_frames,
                  const std::vector<int>& noise_bits, const FusionSettings& settings);
  // Fixed in place: the fusion engine points into the pipeline.
  SensingPipeline(const SensingPipeline&) = delete;
  SensingPipeline& operator=(const SensingPipeline&) = delete;

  // q: the robot's joint values (rad) when the frames were exposed; outside the grid it is
  // refused (std::out_of_range): the caller must stop the robot then.
  const CellSet& process(const std::vector<cv::Mat>& frames, const std::vector<double>& q);
  // The same for a frame set from the cameras (acquisition): a camera whose view is unknown (it
  // delivered nothing usable, or its health monitor raised a fault) counts as seeing everything
  // it can see. So does a camera exposed more than settings.sync_error_s from the median exposure
  // of the set (acquisition/exposure_sync.hpp): the robot's removal is widened for that much
  // timing error only, and q must be the robot at the median exposure. Throws
  // std::invalid_argument when the cameras are not the cell's, in its order.
  const CellSet& process(const FrameSet& frames, const std::vector<double>& q);
  // Views of the last frame set made unknown because their exposure was out of sync.
  [[nodiscard]] std::size_t out_of_sync_views() const { return out_of_sync_views_; }

  [[nodiscard]] const ForbiddenMapFusion& fusion() const { return fusion_; }
  [[nodiscard]] const std::vector<CameraObservation>& observations() const { return observations_; }
  [[nodiscard]] const CycleTimes& times() const { return times_; }
  [[nodiscard]] CellIndex robot_cell() const { return robot_cell_; }
  [[nodiscard]] const CellModel& cell() const { return cell_; }
  // The protective separation check (protective_separation.hpp) of the cell file, or nullptr when
  // the cell turns it off or its robot's motion within the sync error is unbounded; and its
  // verdict on the last frame set (not too close when there is no check).
  [[nodiscard]] const ProtectiveSeparation* separation() const {
    return separation_ ? &*separation_ : nullptr;
  }
  [[nodiscard]] const SeparationVerdict& separation_verdict() const { return verdict_; }
  // When the separation stops the robot (too_close) every cell is forbidden, whatever the map.
  // With `skip`, process() then runs robot removal and the separation check only, no
  // back-projection or vote, and gives every cell forbidden: what the service sends, in the
  // frames that are otherwise the slowest (someone close to the arm). Off by default: validation,
  // the demo's figures and pictures need the fused map of every frame.
  void skip_map_when_too_close(bool skip) { skip_map_when_too_close_ = skip; }
  [[nodiscard]] bool skips_map_when_too_close() const { return skip_map_when_too_close_; }

 private:
  const CellModel& cell_;
  const CspaceGrid& grid_;
  std::vector<FeatureExtractor> extractors_;
  std::vector<FeatureImages> references_;
  std::vector<FeatureImages> current_;
  std::vector<CameraObservation> observations_;
  std::vector<cv::Mat> images_;  // a frame set's images, unknown views empty
  std::optional<ConfigurationSilhouettes> at_configuration_;
  ForbiddenMapFusion fusion_;
  std::optional<ProtectiveSeparation> separation_;
  SeparationVerdict verdict_;
  bool skip_map_when_too_close_ = false;
  std::vector<bool> known_;                    // per camera, for the separation check
  std::vector<const FeatureMask*> obstacles_;  // per camera, the fusion's
  CycleTimes times_;
  CellIndex robot_cell_ = 0;
  double sync_error_s_;
  std::size_t out_of_sync_views_ = 0;
};

}  // namespace safecell
