#include "safecell/silhouettes/recorded_silhouettes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace safecell {
namespace {

// The farthest a point at distance l from a joint's axis moves when the joint turns by `angle`.
double chord_m(double l_m, double angle_rad) {
  return 2.0 * l_m * std::sin(std::min(angle_rad, std::numbers::pi) / 2.0);
}

// Feature cells by which a point seen at least `distance_m` away, moved by at most `motion_m`,
// can move in the image along one axis (focal length f, principal point c, image size `size`).
int dilation_cells(double motion_m, double distance_m, double f_px, double c_px, int size_px,
                   int cell_px) {
  const double angle = std::asin(motion_m / distance_m);
  const double widest = std::atan(std::max(c_px, static_cast<double>(size_px) - c_px) / f_px);
  const double shift_px =
      f_px * (std::tan(std::min(widest + angle, 1.5)) - std::tan(widest));  // 1.5 rad: ~86 deg
  return static_cast<int>(std::ceil(shift_px / static_cast<double>(cell_px))) + 1;
}

}  // namespace

RecordedSilhouettes::RecordedSilhouettes(const CellModel& cell, const CspaceGrid& grid,
                                         RecordingOptions options)
    : grid_(grid),
      options_(options),
      camera_count_(cell.cameras.size()),
      columns_(cell.feature_grid.columns()),
      rows_(cell.feature_grid.rows()) {
  if (options.key_stride < 1) {
    throw std::invalid_argument("recording: key stride " + std::to_string(options.key_stride) +
                                ", expected at least 1 cell");
  }
  if (options.wrist_samples < 1) {
    throw std::invalid_argument("recording: " + std::to_string(options.wrist_samples) +
                                " wrist samples, expected at least 1");
  }
  if (!(options.padding_m >= 0.0)) {
    throw std::invalid_argument("recording: padding must be >= 0 m");
  }
  if (!cell.robot || cell.robot->dof() != grid.joint_count()) {
    throw std::invalid_argument("recording: the grid's joints are not the robot's");
  }
  motion_bound_m_ = options.padding_m;
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const JointSpec& spec = grid.joint(j);
    JointKeys keys;
    keys.discretised = spec.discretised;
    if (spec.discretised) {
      const std::uint32_t cells = grid.cells_along(j);
      for (std::uint32_t i = 0; i < cells; i += static_cast<std::uint32_t>(options.key_stride)) {
        keys.cells.push_back(i);
      }
      if (keys.cells.back() != cells - 1) keys.cells.push_back(cells - 1);
      key_count_ *= keys.cells.size();
      const double reach = std::max(options.key_stride, 1) / 2.0 * grid.cell_width_rad(j);
      motion_bound_m_ += chord_m(spec.l_m, reach);
    } else {
      const int n = options.wrist_samples;
      const double range = spec.hi_rad - spec.lo_rad;
      for (int s = 0; s < n; ++s) {
        keys.samples_rad.push_back(n == 1 ? spec.lo_rad + range / 2.0
                                          : spec.lo_rad + range * s / (n - 1));
      }
      wrist_combinations_ *= keys.samples_rad.size();
      motion_bound_m_ += chord_m(spec.l_m, n == 1 ? range / 2.0 : range / (2.0 * (n - 1)));
    }
    joints_.push_back(std::move(keys));
  }

  const RobotJoint& first = cell.robot->joints.front();
  const Eigen::Vector3d axis_point = first.origin.translation();
  const Eigen::Vector3d axis = (first.origin.linear() * first.axis).normalized();
  for (const PinholeCamera& camera : cell.cameras) {
    const Eigen::Vector3d offset = camera.position_m() - axis_point;
    const double nearest_m = offset.cross(axis).norm() - grid.joint(0).l_m;
    if (nearest_m < 1.25 * motion_bound_m_) {
      // No useful bound: the silhouette is the whole image (build_recorded_luts refuses it).
      unbounded_.push_back(camera.name() + " (" + std::to_string(nearest_m) + " m)");
      dilation_.push_back({columns_, rows_});
      bounded_.push_back(false);
      continue;
    }
    const CameraIntrinsics& k = camera.intrinsics();
    dilation_.push_back({dilation_cells(motion_bound_m_, nearest_m, k.fx_px, k.cx_px, k.width_px,
                                        cell.feature_grid.cell_width_px()),
                         dilation_cells(motion_bound_m_, nearest_m, k.fy_px, k.cy_px, k.height_px,
                                        cell.feature_grid.cell_height_px())});
    bounded_.push_back(true);
  }
}

std::vector<double> RecordedSilhouettes::configuration(std::size_t key, std::size_t wrist) const {
  std::vector<double> q(joints_.size());
  for (std::uint32_t j = 0; j < joints_.size(); ++j) {
    const JointKeys& keys = joints_[j];
    if (keys.discretised) {
      const std::uint32_t cell = keys.cells[key % keys.cells.size()];
      key /= keys.cells.size();
      q[j] = grid_.joint(j).lo_rad + (cell + 0.5) * grid_.cell_width_rad(j);
    } else {
      q[j] = keys.samples_rad[wrist % keys.samples_rad.size()];
      wrist /= keys.samples_rad.size();
    }
  }
  return q;
}

void RecordedSilhouettes::record(const RobotViewer& viewer, const ProgressCallback& progress) {
  std::vector<FeatureMask> masks(key_count_ * camera_count_, FeatureMask(columns_, rows_));
  for (std::size_t key = 0; key < key_count_; ++key) {
    for (std::size_t wrist = 0; wrist < wrist_combinations_; ++wrist) {
      const std::vector<FeatureMask> seen = viewer(configuration(key, wrist));
      if (seen.size() != camera_count_) {
        throw std::runtime_error("recording: " + std::to_string(seen.size()) +
                                 " camera views of the robot, expected " +
                                 std::to_string(camera_count_));
      }
      for (std::size_t camera = 0; camera < camera_count_; ++camera) {
        if (seen[camera].columns() != columns_ || seen[camera].rows() != rows_) {
          throw std::runtime_error("recording: camera " + std::to_string(camera) + " gave a " +
                                   std::to_string(seen[camera].columns()) + " x " +
                                   std::to_string(seen[camera].rows()) + " mask, expected " +
                                   std::to_string(columns_) + " x " + std::to_string(rows_));
        }
        masks[key * camera_count_ + camera] |= seen[camera];
      }
    }
    if (progress) progress(static_cast<double>(key + 1) / static_cast<double>(key_count_));
  }
  masks_ = std::move(masks);
}

void RecordedSilhouettes::add_silhouette(CellIndex cell, std::size_t camera,
                                         FeatureMask& mask) const {
  if (!bounded_[camera]) {
    mask.set_rect(FeatureRect{0, 0, static_cast<std::uint16_t>(columns_ - 1),
                              static_cast<std::uint16_t>(rows_ - 1)});
    return;
  }
  const GridCoords coords = grid_.coords_of(cell).value();
  // Per discretised joint the keys just below and just above the cell (the same key where the
  // cell is one), and the key number's place value.
  std::size_t below[kMaxJoints]{};
  std::size_t above[kMaxJoints]{};
  std::size_t place[kMaxJoints]{};
  std::uint32_t axis_count = 0;
  std::size_t place_value = 1;
  for (std::uint32_t j = 0; j < joints_.size(); ++j) {
    const JointKeys& keys = joints_[j];
    if (!keys.discretised) continue;
    const auto upper = std::lower_bound(keys.cells.begin(), keys.cells.end(), coords.along[j]);
    above[axis_count] = static_cast<std::size_t>(upper - keys.cells.begin());
    below[axis_count] = *upper == coords.along[j] ? above[axis_count] : above[axis_count] - 1;
    place[axis_count] = place_value;
    place_value *= keys.cells.size();
    ++axis_count;
  }
  FeatureMask around(columns_, rows_);
  for (std::uint32_t corner = 0; corner < (1U << axis_count); ++corner) {
    std::size_t key = 0;
    for (std::uint32_t a = 0; a < axis_count; ++a) {
      key += ((corner >> a) & 1U ? above[a] : below[a]) * place[a];
    }
    around |= key_mask(key, camera);
  }
  around.dilate(dilation_[camera][0], dilation_[camera][1]);
  mask |= around;
}

}  // namespace safecell
