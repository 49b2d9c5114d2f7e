#pragma once
// CspaceGrid: the robot's configuration space cut into cells by the max-move rule of the paper
// (Henrich 1998): along joint i a cell is at most dq_i = 2 asin(m_max / (2 l_i)) wide, so moving
// one cell along any joint moves no point of the robot by more than m_max.
//
// Cells are numbered with joint 0 varying fastest: index = sum_i coord_i * stride_i, with
// stride_0 = 1 and stride_{i+1} = stride_i * cells_i. Indices are 32 bits (DESIGN.md §5).
// All methods are real-time safe: no allocation, bounded loops (at most kMaxJoints).

#include <cstdint>

#include "safecell/base/result.hpp"
#include "safecell/cspace/grid_spec.hpp"

namespace safecell {

using CellIndex = std::uint32_t;

// Integer cell coordinates; along[i] counts cells along joint i from its lower limit.
struct GridCoords {
  std::uint32_t along[kMaxJoints]{};
};

struct JointAngles {
  double rad[kMaxJoints]{};
};

struct AngleInterval {
  double lo_rad = 0.0;
  double hi_rad = 0.0;
};

enum class Direction : std::int8_t { kNegative = -1, kPositive = 1 };

class CspaceGrid {
 public:
  // Validates the spec and derives the cell sizes; every refusal names the field and joint.
  static Result<CspaceGrid, GridSpecError> create(const GridSpec& spec) noexcept;

  // The same joints with every discretised joint's cells cut into `factor` equal cells: cell c
  // of this grid along such a joint holds cells c * factor .. c * factor + factor - 1 of the
  // result (up to the rounding of the widths, about 1e-16 rad), and its max-move steps are this
  // grid's divided by factor. The spec, m_max included, stays this grid's; the fingerprint
  // differs through the cell counts. Used to draw a cell's envelope as the union of its sub-cells'.
  // kInvalidArgument (field kCellCount) for factor 0; kOverflow when the cells do not fit 32 bits.
  Result<CspaceGrid, GridSpecError> subdivided(std::uint32_t factor) const noexcept;

  std::uint32_t joint_count() const noexcept { return spec_.joint_count; }
  double m_max_m() const noexcept { return spec_.m_max_m; }
  const GridSpec& spec() const noexcept { return spec_; }
  std::uint32_t cell_count() const noexcept { return cell_count_; }

  // Per joint (precondition, checked: joint < joint_count()).
  const JointSpec& joint(std::uint32_t joint) const;
  // dq_i from the max-move formula; for a joint that is not discretised, its whole range.
  double max_move_step_rad(std::uint32_t joint) const;
  // The actual cell width: the range split evenly into cells_along() cells, never above dq_i.
  double cell_width_rad(std::uint32_t joint) const;
  std::uint32_t cells_along(std::uint32_t joint) const;
  CellIndex stride(std::uint32_t joint) const;

  // A hash of everything that defines the grid (ranges, lever arms, m_max, which joints are
  // discretised, counts), equal on every platform. Stamped into LUT files and protocol sessions.
  std::uint64_t fingerprint() const noexcept { return fingerprint_; }

  Result<CellIndex> index_of(const GridCoords& coords) const noexcept;
  Result<GridCoords> coords_of(CellIndex index) const noexcept;
  // The cell containing a configuration; an angle exactly on a joint's upper limit belongs to the
  // last cell. kOutOfRange outside the limits, kInvalidArgument for NaN.
  Result<GridCoords> coords_containing(const JointAngles& angles) const noexcept;
  Result<CellIndex> cell_containing(const JointAngles& angles) const noexcept;

  Result<JointAngles> cell_centre(const GridCoords& coords) const noexcept;
  Result<AngleInterval> cell_bounds(const GridCoords& coords, std::uint32_t joint) const noexcept;

  // The next cell along one joint; kOutOfRange past the joint's first or last cell.
  Result<CellIndex> neighbour(CellIndex index, std::uint32_t joint,
                              Direction direction) const noexcept;

 private:
  bool coords_valid(const GridCoords& coords) const noexcept;
  // Strides, cell count and fingerprint from spec_ and cells_along_ (every count >= 1).
  Result<bool, GridSpecError> derive_from_counts() noexcept;

  GridSpec spec_{};
  double max_move_step_rad_[kMaxJoints]{};
  double cell_width_rad_[kMaxJoints]{};
  std::uint32_t cells_along_[kMaxJoints]{};
  CellIndex stride_[kMaxJoints]{};
  std::uint32_t cell_count_ = 0;
  std::uint64_t fingerprint_ = 0;
};

}  // namespace safecell
