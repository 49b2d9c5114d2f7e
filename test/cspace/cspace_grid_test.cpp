#include "safecell/cspace/cspace_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

GridSpec two_joint_spec() {
  GridSpec spec;
  spec.m_max_m = 0.5;
  spec.joint_count = 2;
  spec.joints[0] = JointSpec{0.0, 1.0, 1.0, true};
  spec.joints[1] = JointSpec{-1.0, 1.0, 0.2, false};
  return spec;
}

// The paper's cell: RX130-class arm, m_max = 18 cm, joints 1-4 discretised, wrist swept.
GridSpec paper_spec() {
  GridSpec spec;
  spec.m_max_m = 0.18;
  spec.joint_count = 6;
  spec.joints[0] = JointSpec{-160 * kDeg, 160 * kDeg, 1.45, true};
  spec.joints[1] = JointSpec{-127.5 * kDeg, 127.5 * kDeg, 1.38, true};
  spec.joints[2] = JointSpec{-142.5 * kDeg, 142.5 * kDeg, 0.76, true};
  spec.joints[3] = JointSpec{-180 * kDeg, 180 * kDeg, 0.14, true};
  spec.joints[4] = JointSpec{-105 * kDeg, 120 * kDeg, 0.12, false};
  spec.joints[5] = JointSpec{-270 * kDeg, 270 * kDeg, 0.06, false};
  return spec;
}

CspaceGrid grid_of(const GridSpec& spec) {
  auto grid = CspaceGrid::create(spec);
  EXPECT_TRUE(grid.ok());
  return grid.value();
}

GridSpecError refusal_of(const GridSpec& spec) {
  auto grid = CspaceGrid::create(spec);
  EXPECT_FALSE(grid.ok());
  return grid.ok() ? GridSpecError{} : grid.error();
}

TEST(CspaceGrid, MaxMoveStepByHand) {
  const CspaceGrid grid = grid_of(two_joint_spec());
  // dq = 2 asin(0.5 / (2 * 1.0)) = 2 asin(0.25) = 0.5053605102841573 rad;
  // cells = ceil(1.0 / 0.50536...) = ceil(1.9788) = 2, so each cell is 0.5 rad wide.
  EXPECT_NEAR(grid.max_move_step_rad(0), 0.5053605102841573, 1e-15);
  EXPECT_EQ(grid.cells_along(0), 2u);
  EXPECT_DOUBLE_EQ(grid.cell_width_rad(0), 0.5);
  // The swept joint is one cell covering its whole range.
  EXPECT_EQ(grid.cells_along(1), 1u);
  EXPECT_DOUBLE_EQ(grid.cell_width_rad(1), 2.0);
  EXPECT_EQ(grid.cell_count(), 2u);
  EXPECT_EQ(grid.stride(0), 1u);
  EXPECT_EQ(grid.stride(1), 2u);
}

TEST(CspaceGrid, PaperCellByHand) {
  const CspaceGrid grid = grid_of(paper_spec());
  // Joint 1: dq = 2 asin(0.18 / 2.90) = 0.1242177776 rad; 320 deg = 5.585053606 rad;
  // 5.585053606 / 0.1242177776 = 44.96 -> 45 cells.
  EXPECT_NEAR(grid.max_move_step_rad(0), 0.12421777760323388, 1e-15);
  EXPECT_EQ(grid.cells_along(0), 45u);
  EXPECT_EQ(grid.cells_along(1), 35u);
  EXPECT_EQ(grid.cells_along(2), 21u);
  EXPECT_EQ(grid.cells_along(3), 5u);
  EXPECT_EQ(grid.cell_count(), 45u * 35u * 21u * 5u);  // 165,375; the paper reports 181,400
  for (std::uint32_t j = 0; j < 4; ++j) {
    EXPECT_LE(grid.cell_width_rad(j), grid.max_move_step_rad(j)) << "joint " << j;
    // Moving one cell moves the farthest point by a chord of at most m_max.
    const double chord_m = 2.0 * grid.joint(j).l_m * std::sin(grid.cell_width_rad(j) / 2.0);
    EXPECT_LE(chord_m, 0.18 + 1e-12) << "joint " << j;
  }
}

// The fingerprint is part of the wire protocol and the LUT files: it must not drift between
// builds or platforms. This value was computed once and is checked natively and under qemu.
TEST(CspaceGrid, FingerprintIsStable) {
  EXPECT_EQ(grid_of(paper_spec()).fingerprint(), 0x7ab9f329017ab61eull);
  EXPECT_EQ(grid_of(paper_spec()).fingerprint(), grid_of(paper_spec()).fingerprint());
}

TEST(CspaceGrid, FingerprintChangesWithEveryDefiningField) {
  const std::uint64_t base = grid_of(paper_spec()).fingerprint();
  const auto differs = [&](auto&& change) {
    GridSpec spec = paper_spec();
    change(spec);
    return grid_of(spec).fingerprint() != base;
  };
  EXPECT_TRUE(differs([](GridSpec& s) { s.m_max_m = 0.1800001; }));
  EXPECT_TRUE(differs([](GridSpec& s) { s.joint_count = 5; }));
  for (std::uint32_t j = 0; j < 6; ++j) {
    SCOPED_TRACE(j);
    EXPECT_TRUE(differs([j](GridSpec& s) { s.joints[j].lo_rad += 1e-9; }));
    EXPECT_TRUE(differs([j](GridSpec& s) { s.joints[j].hi_rad -= 1e-9; }));
    EXPECT_TRUE(differs([j](GridSpec& s) { s.joints[j].l_m += 1e-9; }));
    // Joint 6 (l = 0.06 m < m_max / 2) can only be swept.
    if (j != 5) {
      EXPECT_TRUE(
          differs([j](GridSpec& s) { s.joints[j].discretised = !s.joints[j].discretised; }));
    }
  }
  // Joints beyond joint_count do not define the grid.
  EXPECT_FALSE(differs([](GridSpec& s) { s.joints[7].l_m = 3.0; }));
}

TEST(CspaceGrid, RefusesMeaninglessSpecs) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  GridSpec spec = paper_spec();
  spec.joint_count = 0;
  EXPECT_EQ(refusal_of(spec).field, GridField::kJointCount);
  spec.joint_count = 9;
  EXPECT_EQ(refusal_of(spec).status, Status::kCapacityExceeded);

  spec = paper_spec();
  spec.m_max_m = -0.18;
  EXPECT_EQ(refusal_of(spec).field, GridField::kMaxMove);
  spec.m_max_m = nan;
  EXPECT_EQ(refusal_of(spec).field, GridField::kMaxMove);

  spec = paper_spec();
  spec.joints[2].lo_rad = 1.0;
  spec.joints[2].hi_rad = -1.0;  // reversed
  const GridSpecError reversed = refusal_of(spec);
  EXPECT_EQ(reversed.field, GridField::kRange);
  EXPECT_EQ(reversed.joint, 2);
  spec.joints[2].hi_rad = 1.0;  // empty
  EXPECT_EQ(refusal_of(spec).field, GridField::kRange);
  spec.joints[2].hi_rad = std::numeric_limits<double>::infinity();
  EXPECT_EQ(refusal_of(spec).field, GridField::kRange);

  spec = paper_spec();
  spec.joints[1].l_m = 0.0899;  // below m_max / 2 = 0.09: no step could keep within m_max
  const GridSpecError short_arm = refusal_of(spec);
  EXPECT_EQ(short_arm.field, GridField::kLeverArm);
  EXPECT_EQ(short_arm.joint, 1);
  spec.joints[1].l_m = 0.09;  // exactly m_max / 2: dq = pi
  EXPECT_NEAR(grid_of(spec).max_move_step_rad(1), 3.14159265358979323846, 1e-15);
  spec.joints[4].l_m = -0.1;  // even a swept joint needs a real lever arm
  EXPECT_EQ(refusal_of(spec).joint, 4);

  spec = paper_spec();
  spec.m_max_m = 1e-6;  // 10^5 cells per joint: far beyond 32-bit indices
  EXPECT_EQ(refusal_of(spec).status, Status::kOverflow);
}

// Random grids of 1..8 joints, some swept.
GridSpec random_spec(std::mt19937_64& rng) {
  std::uniform_int_distribution<std::uint32_t> joints(1, kMaxJoints);
  std::uniform_real_distribution<double> lo(-3.0, 0.0), span(0.1, 5.0), lever(0.1, 0.5);
  GridSpec spec;
  spec.m_max_m = 0.2;
  spec.joint_count = joints(rng);
  for (std::uint32_t j = 0; j < spec.joint_count; ++j) {
    const double from = lo(rng);
    // l >= 0.1 m keeps dq >= 0.40 rad, so at most 13 cells per joint and 13^8 < 2^32 cells.
    spec.joints[j] = JointSpec{from, from + span(rng), lever(rng), rng() % 4 != 0};
  }
  return spec;
}

TEST(CspaceGrid, IndexAndCoordinatesRoundTrip) {
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    const GridSpec spec = random_spec(run.rng());
    auto created = CspaceGrid::create(spec);
    ASSERT_TRUE(created.ok()) << "iteration " << i;
    const CspaceGrid& grid = created.value();
    for (int k = 0; k < 50; ++k) {
      GridCoords coords;
      for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
        coords.along[j] = static_cast<std::uint32_t>(run.rng()() % grid.cells_along(j));
      }
      const auto index = grid.index_of(coords);
      ASSERT_TRUE(index.ok());
      ASSERT_LT(index.value(), grid.cell_count());
      const auto back = grid.coords_of(index.value());
      ASSERT_TRUE(back.ok());
      for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
        ASSERT_EQ(back.value().along[j], coords.along[j]) << "iteration " << i << " joint " << j;
      }
      // The centre of a cell lies in that cell.
      const auto centre = grid.cell_centre(coords);
      ASSERT_TRUE(centre.ok());
      ASSERT_EQ(grid.cell_containing(centre.value()).value(), index.value());
    }
    EXPECT_EQ(grid.coords_of(grid.cell_count()).error(), Status::kOutOfRange);
  }
}

TEST(CspaceGrid, EveryAngleInRangeLiesInsideTheBoundsOfItsCell) {
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    const CspaceGrid grid = grid_of(random_spec(run.rng()));
    JointAngles angles;
    for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
      const JointSpec& joint = grid.joint(j);
      std::uniform_real_distribution<double> in_range(joint.lo_rad, joint.hi_rad);
      // Limits are hit on purpose now and then: they must map to the first and last cell.
      const auto pick = run.rng()() % 8;
      angles.rad[j] = pick == 0 ? joint.lo_rad : pick == 1 ? joint.hi_rad : in_range(run.rng());
    }
    const auto coords = grid.coords_containing(angles);
    ASSERT_TRUE(coords.ok()) << "iteration " << i;
    for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
      const auto bounds = grid.cell_bounds(coords.value(), j);
      ASSERT_TRUE(bounds.ok());
      EXPECT_LE(bounds.value().lo_rad, angles.rad[j] + 1e-12)
          << "iteration " << i << " joint " << j;
      EXPECT_GE(bounds.value().hi_rad, angles.rad[j] - 1e-12)
          << "iteration " << i << " joint " << j;
    }
  }
}

TEST(CspaceGrid, AnglesOutsideTheLimitsAreRefused) {
  const CspaceGrid grid = grid_of(two_joint_spec());
  JointAngles angles;
  angles.rad[0] = 1.0000001;
  EXPECT_EQ(grid.cell_containing(angles).error(), Status::kOutOfRange);
  angles.rad[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(grid.cell_containing(angles).error(), Status::kInvalidArgument);
  angles.rad[0] = 1.0;
  angles.rad[1] = -1.0;
  EXPECT_EQ(grid.cell_containing(angles).value(), 1u);
}

TEST(CspaceGrid, NeighboursStepOneCellAndStopAtTheEdges) {
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    const CspaceGrid grid = grid_of(random_spec(run.rng()));
    const auto index = static_cast<CellIndex>(run.rng()() % grid.cell_count());
    const GridCoords coords = grid.coords_of(index).value();
    for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
      for (const Direction direction : {Direction::kNegative, Direction::kPositive}) {
        const auto next = grid.neighbour(index, j, direction);
        const auto step = static_cast<std::int64_t>(direction);
        const std::int64_t along = static_cast<std::int64_t>(coords.along[j]) + step;
        if (along < 0 || along >= static_cast<std::int64_t>(grid.cells_along(j))) {
          ASSERT_EQ(next.error(), Status::kOutOfRange) << "iteration " << i << " joint " << j;
          continue;
        }
        ASSERT_TRUE(next.ok());
        GridCoords expected = coords;
        expected.along[j] = static_cast<std::uint32_t>(along);
        ASSERT_EQ(next.value(), grid.index_of(expected).value()) << "iteration " << i;
      }
    }
    EXPECT_EQ(grid.neighbour(index, grid.joint_count(), Direction::kPositive).error(),
              Status::kOutOfRange);
  }
}

// Cell c of a grid holds cells c * f .. c * f + f - 1 of the grid subdivided by f, along every
// discretised joint, and nothing else: their bounds tile the coarse cell's.
TEST(CspaceGrid, ASubdividedGridCutsEveryDiscretisedCellIntoEqualParts) {
  test::PropertyRun run(100);
  for (int i = 0; i < run.iterations(); ++i) {
    const CspaceGrid coarse = grid_of(random_spec(run.rng()));
    const auto factor = static_cast<std::uint32_t>(1 + run.rng()() % 3);
    const auto made = coarse.subdivided(factor);
    double fine_cells = 1.0;
    for (std::uint32_t j = 0; j < coarse.joint_count(); ++j) {
      fine_cells *= coarse.cells_along(j) * (coarse.joint(j).discretised ? factor : 1.0);
    }
    if (fine_cells > 4294967295.0) {
      ASSERT_FALSE(made.ok()) << "iteration " << i << ": " << fine_cells << " cells";
      EXPECT_EQ(made.error().status, Status::kOverflow);
      continue;
    }
    ASSERT_TRUE(made.ok()) << "iteration " << i << " factor " << factor;
    const CspaceGrid& fine = made.value();
    ASSERT_EQ(fine.joint_count(), coarse.joint_count());
    EXPECT_EQ(fine.m_max_m(), coarse.m_max_m());
    bool cut = false;
    for (std::uint32_t j = 0; j < coarse.joint_count(); ++j)
      cut = cut || coarse.joint(j).discretised;
    cut = cut && factor > 1;
    EXPECT_EQ(fine.fingerprint() != coarse.fingerprint(), cut)
        << "iteration " << i << " factor " << factor;
    const auto index = static_cast<CellIndex>(run.rng()() % coarse.cell_count());
    const GridCoords coords = coarse.coords_of(index).value();
    for (std::uint32_t j = 0; j < coarse.joint_count(); ++j) {
      const std::uint32_t parts = coarse.joint(j).discretised ? factor : 1;
      ASSERT_EQ(fine.cells_along(j), coarse.cells_along(j) * parts) << "joint " << j;
      EXPECT_NEAR(fine.max_move_step_rad(j) * parts, coarse.max_move_step_rad(j), 1e-12);
      const AngleInterval whole = coarse.cell_bounds(coords, j).value();
      GridCoords child = coords;
      double reached = whole.lo_rad;
      for (std::uint32_t part = 0; part < parts; ++part) {
        child.along[j] = coords.along[j] * parts + part;
        const AngleInterval piece = fine.cell_bounds(child, j).value();
        EXPECT_NEAR(piece.lo_rad, reached, 1e-12)
            << "iteration " << i << " joint " << j << " cell " << coords.along[j] << " part "
            << part << " of " << parts;
        EXPECT_NEAR(piece.hi_rad - piece.lo_rad, (whole.hi_rad - whole.lo_rad) / parts, 1e-12);
        reached = piece.hi_rad;
      }
      EXPECT_NEAR(reached, whole.hi_rad, 1e-12) << "iteration " << i << " joint " << j;
    }
  }
}

TEST(CspaceGrid, ASubdivisionThatDoesNotFitIsRefused) {
  const CspaceGrid grid = grid_of(paper_spec());
  EXPECT_EQ(grid.subdivided(0).error().field, GridField::kCellCount);
  const auto huge = grid.subdivided(1u << 20);
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.error().status, Status::kOverflow);
  EXPECT_EQ(grid.subdivided(2).value().cell_count(), grid.cell_count() * 16);
}

TEST(CspaceGrid, PerJointAccessBeyondTheJointCountAsserts) {
  const CspaceGrid grid = grid_of(two_joint_spec());
  EXPECT_THROW(static_cast<void>(grid.cells_along(2)), test::AssertFailure);
  EXPECT_THROW(static_cast<void>(grid.joint(8)), test::AssertFailure);
}

}  // namespace
}  // namespace safecell
