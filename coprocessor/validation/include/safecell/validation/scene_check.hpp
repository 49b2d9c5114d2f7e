#pragma once
// Checks one processed scene of the simulated cell against the exact ground truth: robot
// configurations (half random, half turned towards a human) are tested for collision with FCL and
// compared with the forbidden map the pipeline made (definitions in ground_truth_validation.hpp).
// The scene's humans and objects are its moving obstacles; the cell file's boxes are static.
// Shared by `safecell validate` and `safecell demo`.

#include <random>
#include <string>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

struct MissedCollision {
  std::size_t scene = 0;
  std::vector<double> q;
  std::string obstacle;
  int cameras_seeing = 0;
};

struct SceneCheck {
  std::size_t configs_checked = 0;
  std::size_t colliding = 0;
  std::size_t missed = 0;
  std::size_t unseen = 0;
  std::size_t free = 0;
  std::size_t false_positives = 0;
  std::vector<MissedCollision> missed_cases;
  std::vector<int> cameras_seeing;  // per human, then per object

  SceneCheck& operator+=(const SceneCheck& other);
  // Forbidden but free, as a share of the free configurations checked.
  [[nodiscard]] double false_positive_rate() const {
    return free == 0 ? 0.0 : static_cast<double>(false_positives) / static_cast<double>(free);
  }
};

// Joint values drawn uniformly within the grid's ranges.
[[nodiscard]] std::vector<double> random_configuration(const CspaceGrid& grid,
                                                       std::mt19937_64& rng);

// `pipeline` has just processed the frames of the scene (robot at scene.q, the humans).
[[nodiscard]] SceneCheck check_scene(const CellModel& cell, const CspaceGrid& grid,
                                     SimulatedCell& sim, const SensingPipeline& pipeline,
                                     const SimScene& scene, std::size_t configurations,
                                     std::mt19937_64& rng, std::size_t scene_index);

// The shapes of the scene's humans and objects.
[[nodiscard]] std::vector<PlacedShape> moving_bodies(const SimScene& scene);

// Critical cells of the last cycle whose robot, at the cell's centre, stays farther than
// `distance_m` from every body (moving_bodies()): sampled (`samples` cells) and scaled to all
// critical cells.
[[nodiscard]] double estimate_phantom_cells(const CellModel& cell, const CspaceGrid& grid,
                                            const SensingPipeline& pipeline,
                                            const std::vector<PlacedShape>& bodies,
                                            std::size_t samples, double distance_m,
                                            std::mt19937_64& rng);

}  // namespace safecell
