#pragma once
// Recorded mode of the implicit calibration (paper §4.1, DESIGN.md §3): LUT-1 from difference
// images of the real robot instead of from its model. The robot is moved to key configurations,
// every camera's blocked feature cells are taken (the robot against the reference), and a C-space
// cell's silhouette is the union of the recordings of the keys around it, dilated so that it holds
// the robot anywhere inside the cell.
//
// Keys: along each discretised joint the centres of every key_stride-th cell and of the last cell
// (key_stride 1 is the paper's brute force, one key per cell; larger strides its interpolating
// variant); each joint that is not discretised is recorded at wrist_samples values spread evenly
// over its range (one: its middle), and a key's mask is the union over those.
//
// Why the dilation is enough: any configuration of a cell is within max(k, 1) / 2 cells of one of
// the keys around it along every discretised joint (k the stride), and within half a sample
// spacing of a wrist sample. Moving a joint by an angle a moves no robot point farther than the
// chord 2 l sin(a / 2) (l_i of the grid), so every point stays within
// motion_bound_m() = the sum of those chords + padding of where a key saw it. Every robot point is
// at least d = (distance from the camera to joint 1's axis) - l_1 from the camera, so it moves by
// at most asin(motion / d) in angle, which at the image's widest field angle is at most
// dilation_columns() / dilation_rows() feature cells (plus one for the feature cells' edges).
// Where d < 1.25 x the motion bound there is no useful bound: that camera's silhouettes are its
// whole image, and unbounded_cameras() names it. The bound is a worst case for every point (the
// largest lever arms, the nearest distance), so it is only small for fine keys, many wrist
// samples and cameras far from the robot; model mode bounds each ball of the robot instead.
//
// The recordings are only as good as the difference images: a robot part the features do not tell
// from the background is missed. silhouette_agreement.hpp compares them with the model.

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/compute/parallel_chunks.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/features/feature_mask.hpp"
#include "safecell/silhouettes/robot_silhouettes.hpp"

namespace safecell {

struct RecordingOptions {
  int key_stride = 2;     // cells between keys along each discretised joint (1: every cell)
  int wrist_samples = 3;  // values per joint that is not discretised
  double padding_m = 0.02;
};

// The robot at configuration q (one value per joint of the grid), seen by every camera of the cell:
// per camera the blocked feature cells of its difference image. The real robot and cameras, or the
// simulated cell (pipeline/simulated_robot_viewer.hpp).
using RobotViewer = std::function<std::vector<FeatureMask>(const std::vector<double>& q)>;

class RecordedSilhouettes final : public RobotSilhouettes {
 public:
  // Throws std::invalid_argument for a stride or sample count below 1, a negative padding or a
  // grid of another joint count than the robot's.
  RecordedSilhouettes(const CellModel& cell, const CspaceGrid& grid, RecordingOptions options);

  // Moves the robot through every key (wrist samples innermost) and keeps the masks. Throws
  // std::runtime_error when the viewer returns the wrong number or size of masks.
  void record(const RobotViewer& viewer, const ProgressCallback& progress = {});
  [[nodiscard]] bool recorded() const { return !masks_.empty(); }

  [[nodiscard]] std::size_t key_count() const { return key_count_; }
  [[nodiscard]] std::size_t wrist_combinations() const { return wrist_combinations_; }
  // Configurations recorded: key_count() * wrist_combinations().
  [[nodiscard]] std::size_t configuration_count() const { return key_count_ * wrist_combinations_; }
  // The configuration of one key and one combination of wrist samples.
  [[nodiscard]] std::vector<double> configuration(std::size_t key, std::size_t wrist) const;
  // What the cameras saw at one key, undilated (precondition: recorded()).
  [[nodiscard]] const FeatureMask& key_mask(std::size_t key, std::size_t camera) const {
    return masks_[key * camera_count_ + camera];
  }

  [[nodiscard]] double motion_bound_m() const { return motion_bound_m_; }
  [[nodiscard]] int dilation_columns(std::size_t camera) const { return dilation_[camera][0]; }
  [[nodiscard]] int dilation_rows(std::size_t camera) const { return dilation_[camera][1]; }
  [[nodiscard]] const RecordingOptions& options() const { return options_; }
  // Cameras too close to the robot for the bound, with their distance (empty when none).
  [[nodiscard]] const std::vector<std::string>& unbounded_cameras() const { return unbounded_; }

  [[nodiscard]] std::size_t camera_count() const override { return camera_count_; }
  // Precondition: recorded(). Thread-safe.
  void add_silhouette(CellIndex cell, std::size_t camera, FeatureMask& mask) const override;

 private:
  // Per joint: the key cell indices (discretised) or the wrist sample angles (not).
  struct JointKeys {
    bool discretised = true;
    std::vector<std::uint32_t> cells;  // ascending, first 0 and last cells_along - 1
    std::vector<double> samples_rad;
  };

  const CspaceGrid& grid_;
  RecordingOptions options_;
  std::size_t camera_count_ = 0;
  int columns_ = 0;
  int rows_ = 0;
  std::vector<JointKeys> joints_;
  std::size_t key_count_ = 1;
  std::size_t wrist_combinations_ = 1;
  double motion_bound_m_ = 0.0;
  std::vector<std::array<int, 2>> dilation_;  // per camera: columns, rows
  std::vector<bool> bounded_;                 // per camera
  std::vector<std::string> unbounded_;
  std::vector<FeatureMask> masks_;  // key-major, camera-minor
};

}  // namespace safecell
