#include "safecell/cspace/cspace_grid.hpp"

#include "safecell/base/fnv1a.hpp"
#include "safecell/base/freestanding_math.hpp"

namespace safecell {
namespace {

// Version of the fingerprint's byte layout; bump it whenever the hashed fields change.
constexpr std::uint32_t kFingerprintLayout = 1;
constexpr std::uint64_t kMaxCellIndexCount = 0xFFFFFFFFull;

GridSpecError refuse(Status status, GridField field, std::uint32_t joint = 0) noexcept {
  return GridSpecError{status, field, static_cast<std::uint8_t>(joint)};
}

// Returns kOk, or the first problem with one joint's range and lever arm.
Result<bool, GridSpecError> check_joint(const JointSpec& joint, std::uint32_t index,
                                        double m_max_m) noexcept {
  if (!is_finite(joint.lo_rad) || !is_finite(joint.hi_rad) || !(joint.lo_rad < joint.hi_rad)) {
    return refuse(Status::kInvalidArgument, GridField::kRange, index);
  }
  if (!is_finite(joint.l_m) || joint.l_m < 0.0 ||
      (joint.discretised && joint.l_m < m_max_m / 2.0)) {
    return refuse(Status::kInvalidArgument, GridField::kLeverArm, index);
  }
  return true;
}

}  // namespace

Result<CspaceGrid, GridSpecError> CspaceGrid::create(const GridSpec& spec) noexcept {
  if (spec.joint_count == 0) return refuse(Status::kInvalidArgument, GridField::kJointCount);
  if (spec.joint_count > kMaxJoints) {
    return refuse(Status::kCapacityExceeded, GridField::kJointCount);
  }
  if (!is_finite(spec.m_max_m) || !(spec.m_max_m > 0.0)) {
    return refuse(Status::kInvalidArgument, GridField::kMaxMove);
  }

  CspaceGrid grid;
  grid.spec_ = spec;
  for (std::uint32_t j = spec.joint_count; j < kMaxJoints; ++j) grid.spec_.joints[j] = JointSpec{};

  for (std::uint32_t j = 0; j < spec.joint_count; ++j) {
    const JointSpec& joint = spec.joints[j];
    const auto checked = check_joint(joint, j, spec.m_max_m);
    if (!checked.ok()) return checked.error();

    const double range_rad = joint.hi_rad - joint.lo_rad;
    std::uint64_t cells = 1;
    double step_rad = range_rad;
    if (joint.discretised) {
      step_rad = 2.0 * asin_rad(spec.m_max_m / (2.0 * joint.l_m));
      const double exact_cells = range_rad / step_rad;
      if (!(exact_cells <= static_cast<double>(kMaxCellIndexCount))) {
        return refuse(Status::kOverflow, GridField::kCellCount, j);
      }
      cells = ceil_to_u64(exact_cells);
    }
    grid.max_move_step_rad_[j] = step_rad;
    grid.cells_along_[j] = static_cast<std::uint32_t>(cells);
    grid.cell_width_rad_[j] = range_rad / static_cast<double>(cells);
  }
  const auto derived = grid.derive_from_counts();
  if (!derived.ok()) return derived.error();
  return grid;
}

Result<CspaceGrid, GridSpecError> CspaceGrid::subdivided(std::uint32_t factor) const noexcept {
  if (factor == 0) return refuse(Status::kInvalidArgument, GridField::kCellCount);
  CspaceGrid grid = *this;
  for (std::uint32_t j = 0; j < spec_.joint_count; ++j) {
    if (!spec_.joints[j].discretised) continue;
    const std::uint64_t cells = std::uint64_t{cells_along_[j]} * factor;
    if (cells > kMaxCellIndexCount) return refuse(Status::kOverflow, GridField::kCellCount, j);
    const double range_rad = spec_.joints[j].hi_rad - spec_.joints[j].lo_rad;
    grid.max_move_step_rad_[j] = max_move_step_rad_[j] / static_cast<double>(factor);
    grid.cells_along_[j] = static_cast<std::uint32_t>(cells);
    grid.cell_width_rad_[j] = range_rad / static_cast<double>(cells);
  }
  const auto derived = grid.derive_from_counts();
  if (!derived.ok()) return derived.error();
  return grid;
}

Result<bool, GridSpecError> CspaceGrid::derive_from_counts() noexcept {
  std::uint64_t total = 1;
  for (std::uint32_t j = 0; j < spec_.joint_count; ++j) {
    stride_[j] = static_cast<CellIndex>(total);
    total *= cells_along_[j];
    if (total > kMaxCellIndexCount) return refuse(Status::kOverflow, GridField::kCellCount, j);
  }
  cell_count_ = static_cast<std::uint32_t>(total);

  Fnv1a64 hash;
  hash.add_u32(kFingerprintLayout);
  hash.add_u32(spec_.joint_count);
  hash.add_double(spec_.m_max_m);
  for (std::uint32_t j = 0; j < spec_.joint_count; ++j) {
    const JointSpec& joint = spec_.joints[j];
    hash.add_double(joint.lo_rad);
    hash.add_double(joint.hi_rad);
    hash.add_double(joint.l_m);
    hash.add_byte(joint.discretised ? 1 : 0);
    hash.add_u32(cells_along_[j]);
  }
  fingerprint_ = hash.value();
  return true;
}

const JointSpec& CspaceGrid::joint(std::uint32_t joint) const {
  SAFECELL_ASSERT(joint < spec_.joint_count);
  return spec_.joints[joint];
}

double CspaceGrid::max_move_step_rad(std::uint32_t joint) const {
  SAFECELL_ASSERT(joint < spec_.joint_count);
  return max_move_step_rad_[joint];
}

double CspaceGrid::cell_width_rad(std::uint32_t joint) const {
  SAFECELL_ASSERT(joint < spec_.joint_count);
  return cell_width_rad_[joint];
}

std::uint32_t CspaceGrid::cells_along(std::uint32_t joint) const {
  SAFECELL_ASSERT(joint < spec_.joint_count);
  return cells_along_[joint];
}

CellIndex CspaceGrid::stride(std::uint32_t joint) const {
  SAFECELL_ASSERT(joint < spec_.joint_count);
  return stride_[joint];
}

bool CspaceGrid::coords_valid(const GridCoords& coords) const noexcept {
  for (std::uint32_t j = 0; j < spec_.joint_count; ++j) {
    if (coords.along[j] >= cells_along_[j]) return false;
  }
  return true;
}

Result<CellIndex> CspaceGrid::index_of(const GridCoords& coords) const noexcept {
  if (!coords_valid(coords)) return Status::kOutOfRange;
  CellIndex index = 0;
  for (std::uint32_t j = 0; j < spec_.joint_count; ++j) index += coords.along[j] * stride_[j];
  return index;
}

Result<GridCoords> CspaceGrid::coords_of(CellIndex index) const noexcept {
  if (index >= cell_count_) return Status::kOutOfRange;
  GridCoords coords;
  for (std::uint32_t j = 0; j < spec_.joint_count; ++j) {
    coords.along[j] = index % cells_along_[j];
    index /= cells_along_[j];
  }
  return coords;
}

Result<GridCoords> CspaceGrid::coords_containing(const JointAngles& angles) const noexcept {
  GridCoords coords;
  for (std::uint32_t j = 0; j < spec_.joint_count; ++j) {
    const double angle = angles.rad[j];
    if (angle != angle) return Status::kInvalidArgument;
    const JointSpec& joint = spec_.joints[j];
    if (angle < joint.lo_rad || angle > joint.hi_rad) return Status::kOutOfRange;
    auto along = static_cast<std::uint32_t>((angle - joint.lo_rad) / cell_width_rad_[j]);
    // Rounding can put a value at (or just below) the upper limit one past the last cell.
    if (along >= cells_along_[j]) along = cells_along_[j] - 1;
    coords.along[j] = along;
  }
  return coords;
}

Result<CellIndex> CspaceGrid::cell_containing(const JointAngles& angles) const noexcept {
  SAFECELL_TRY_ASSIGN(const GridCoords coords, coords_containing(angles));
  return index_of(coords);
}

Result<AngleInterval> CspaceGrid::cell_bounds(const GridCoords& coords,
                                              std::uint32_t joint) const noexcept {
  if (joint >= spec_.joint_count || !coords_valid(coords)) return Status::kOutOfRange;
  const JointSpec& spec = spec_.joints[joint];
  const auto along = coords.along[joint];
  AngleInterval bounds;
  bounds.lo_rad = spec.lo_rad + static_cast<double>(along) * cell_width_rad_[joint];
  // The last cell ends exactly on the limit, whatever the rounding of the width.
  bounds.hi_rad = along + 1 == cells_along_[joint]
                      ? spec.hi_rad
                      : spec.lo_rad + static_cast<double>(along + 1) * cell_width_rad_[joint];
  return bounds;
}

Result<JointAngles> CspaceGrid::cell_centre(const GridCoords& coords) const noexcept {
  JointAngles centre;
  for (std::uint32_t j = 0; j < spec_.joint_count; ++j) {
    SAFECELL_TRY_ASSIGN(const AngleInterval bounds, cell_bounds(coords, j));
    centre.rad[j] = 0.5 * (bounds.lo_rad + bounds.hi_rad);
  }
  if (spec_.joint_count == 0) return Status::kOutOfRange;
  return centre;
}

Result<CellIndex> CspaceGrid::neighbour(CellIndex index, std::uint32_t joint,
                                        Direction direction) const noexcept {
  if (joint >= spec_.joint_count) return Status::kOutOfRange;
  SAFECELL_TRY_ASSIGN(const GridCoords coords, coords_of(index));
  const auto along = coords.along[joint];
  if (direction == Direction::kPositive) {
    if (along + 1 >= cells_along_[joint]) return Status::kOutOfRange;
    return index + stride_[joint];
  }
  if (along == 0) return Status::kOutOfRange;
  return index - stride_[joint];
}

}  // namespace safecell
