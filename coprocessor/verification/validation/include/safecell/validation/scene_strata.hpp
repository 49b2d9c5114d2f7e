#pragma once
// The scenes `safecell validate` draws, on purpose from the cases where the method is weakest
// (../shared/VALIDATION.md, "strata"), each reported on its own:
//   uniform                 1..max_humans people anywhere, 0..max_objects boxes on the floor;
//   against_arm             a person standing against the arm (within a few centimetres of it);
//   behind_arm              a person behind the arm as one camera sees it (the arm between);
//   reaching                a person 0.4-1 m from the arm, facing it, one arm reaching out;
//   behind_static_obstacle  a person behind a static obstacle as one camera sees it;
//   boxes                   boxes on the floor and on top of the static obstacles (a workbench).
// Every body stands where there is room (not in the robot at the scene's configuration, a static
// obstacle, another body or a wall). A stratum without room at the scene's robot configuration is
// tried at up to 8 others; one that cannot be placed at all (no static obstacle, no room) falls
// back to uniform and says so in the returned scene's stratum.

#include <array>
#include <cstddef>
#include <random>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

enum class SceneStratum : std::uint8_t {
  kUniform,
  kAgainstArm,
  kBehindArm,
  kReaching,
  kBehindStaticObstacle,
  kBoxes,
};
inline constexpr std::size_t kSceneStrata = 6;
inline constexpr std::array<SceneStratum, kSceneStrata> kAllSceneStrata = {
    SceneStratum::kUniform,  SceneStratum::kAgainstArm,           SceneStratum::kBehindArm,
    SceneStratum::kReaching, SceneStratum::kBehindStaticObstacle, SceneStratum::kBoxes};

[[nodiscard]] const char* to_string(SceneStratum stratum);

struct SceneLimits {
  int max_humans = 2;   // uniform scenes: 1..max_humans
  int max_objects = 1;  // uniform scenes: 0..max_objects; boxes scenes: 1..max(1, max_objects) + 1
};

struct StratifiedScene {
  SimScene scene;
  SceneStratum stratum = SceneStratum::kUniform;  // the one placed (after any fallback)
};

// Throws std::invalid_argument for a cell without a robot model.
[[nodiscard]] StratifiedScene make_scene(SceneStratum stratum, const CellModel& cell,
                                         const CspaceGrid& grid, const SceneLimits& limits,
                                         std::mt19937_64& rng);

}  // namespace safecell
