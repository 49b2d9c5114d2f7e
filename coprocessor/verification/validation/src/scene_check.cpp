#include "safecell/validation/scene_check.hpp"

#include <algorithm>

#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "safecell/validation/configuration_strata.hpp"

namespace safecell {
namespace {

constexpr std::size_t kMissedCasesKept = 10;
constexpr int kStaticBody = -1;

double share(std::size_t part, std::size_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

// One human or object of the scene as the check sees it.
struct CheckedBody {
  BodyCode code = 0;
  int cameras_visible = 0;
  UnseenReason reason = UnseenReason::kOutsideViews;  // when visible in too few cameras
};

// The reason most of the cameras that do not see the body give (ties: the earlier reason).
UnseenReason dominant_reason(const UnseenReasons& counts) {
  const auto most = std::max_element(counts.begin(), counts.end());
  return static_cast<UnseenReason>(most - counts.begin());
}

std::vector<CheckedBody> check_bodies(const CellModel& cell, SimulatedCell& sim,
                                      const SimScene& scene, const std::vector<cv::Mat>& object_ids,
                                      int threshold) {
  const std::vector<SurfaceMesh> surfaces = sim.moving_surfaces(scene);
  std::vector<CheckedBody> bodies;
  for (std::size_t b = 0; b < scene.humans.size() + scene.objects.size(); ++b) {
    CheckedBody body;
    body.code = scene_body_code(scene.humans.size(), b);
    const std::vector<bool> visible = visible_per_camera(object_ids, body.code, cell.feature_grid);
    body.cameras_visible = static_cast<int>(std::count(visible.begin(), visible.end(), true));
    if (body.cameras_visible < threshold) {
      std::vector<SurfaceMesh> own;
      for (const auto& surface : surfaces) {
        if (surface.body == body.code) own.push_back(surface);
      }
      UnseenReasons reasons{};
      for (std::size_t c = 0; c < sim.camera_count(); ++c) {
        if (visible[c]) continue;
        const auto reason =
            why_not_visible(object_ids[c], sim.coverage(c, own), body.code, cell.feature_grid);
        ++reasons[static_cast<std::size_t>(reason)];
      }
      body.reason = dominant_reason(reasons);
    }
    bodies.push_back(body);
  }
  return bodies;
}

constexpr int kInCellSamples = 24;     // configurations tried for a collision in the cell
constexpr int kSilhouetteSamples = 6;  // configurations whose exact silhouettes are rendered

enum class NeedlessStopCause { kInCell, kVisualHull, kEnvelope };

// Why the clear configuration q is forbidden (see scene_check.hpp).
NeedlessStopCause cause_of_needless_stop(const CellModel& cell, const CspaceGrid& grid,
                                         SimulatedCell& sim, const GroundTruth& truth,
                                         const SceneUnderTest& under_test,
                                         const std::vector<double>& q, std::mt19937_64& rng) {
  const CellIndex at = cell_of(grid, q);
  for (int k = 0; k < kInCellSamples; ++k) {
    if (truth.collides(collision_shapes_at(*cell.robot, configuration_in_cell(grid, at, rng)))) {
      return NeedlessStopCause::kInCell;
    }
  }
  const std::vector<RobotPart> whole_robot = robot_parts(*cell.robot, PartSplit::kWholeRobot);
  const std::vector<RobotPart>& parts =
      under_test.parts != nullptr ? *under_test.parts : whole_robot;
  const FeatureGrid& features = cell.feature_grid;
  const std::size_t cameras = sim.camera_count();
  std::vector<FeatureMask> exact(parts.size() * cameras, FeatureMask(features));  // part-major
  for (int k = 0; k < kSilhouetteSamples; ++k) {
    const std::vector<double> sample = configuration_in_cell(grid, at, rng);
    for (std::size_t p = 0; p < parts.size(); ++p) {
      for (std::size_t c = 0; c < cameras; ++c) {
        const cv::Mat covered =
            sim.robot_coverage(c, sample, BodyRange{parts[p].first_body, parts[p].end_body});
        FeatureMask& mask = exact[p * cameras + c];
        for (int y = 0; y < covered.rows; ++y) {
          const auto* row = covered.ptr<std::uint8_t>(y);
          for (int x = 0; x < covered.cols; ++x) {
            if (row[x] != 0) mask.set(x / features.cell_width_px(), y / features.cell_height_px());
          }
        }
      }
    }
  }
  for (std::size_t p = 0; p < parts.size(); ++p) {
    int meeting = 0;
    for (std::size_t c = 0; c < cameras; ++c) {
      const FeatureMask& obstacles = (*under_test.obstacles)[c];
      const FeatureMask& mask = exact[p * cameras + c];
      meeting += obstacles.columns() == mask.columns() && mask.intersects(obstacles) ? 1 : 0;
    }
    if (meeting >= under_test.camera_threshold) return NeedlessStopCause::kVisualHull;
  }
  return NeedlessStopCause::kEnvelope;
}

}  // namespace

NeedlessStopCauses& NeedlessStopCauses::operator+=(const NeedlessStopCauses& other) {
  traced += other.traced;
  in_cell += other.in_cell;
  visual_hull += other.visual_hull;
  envelope += other.envelope;
  return *this;
}

StratumCounts& StratumCounts::operator+=(const StratumCounts& other) {
  configs += other.configs;
  colliding += other.colliding;
  missed += other.missed;
  unseen += other.unseen;
  clear += other.clear;
  clear_forbidden += other.clear_forbidden;
  return *this;
}

SceneCheck& SceneCheck::operator+=(const SceneCheck& other) {
  configs_checked += other.configs_checked;
  colliding += other.colliding;
  missed += other.missed;
  unseen += other.unseen;
  unseen_forbidden += other.unseen_forbidden;
  for (std::size_t r = 0; r < kUnseenReasonCount; ++r) unseen_reasons[r] += other.unseen_reasons[r];
  free += other.free;
  false_positives += other.false_positives;
  clear += other.clear;
  clear_forbidden += other.clear_forbidden;
  causes += other.causes;
  bodies += other.bodies;
  bodies_visible_enough += other.bodies_visible_enough;
  for (const auto& [name, counts] : other.strata) strata[name] += counts;
  for (const auto& missed_case : other.missed_cases) {
    if (missed_cases.size() < kMissedCasesKept) missed_cases.push_back(missed_case);
  }
  return *this;
}

double SceneCheck::false_positive_rate() const { return share(false_positives, free); }
double SceneCheck::needless_stop_share() const { return share(clear_forbidden, clear); }
double StratumCounts::needless_stop_share() const { return share(clear_forbidden, clear); }
double NeedlessStopCauses::share(std::size_t part) const { return safecell::share(part, traced); }

std::vector<PlacedShape> moving_bodies(const SimScene& scene) {
  std::vector<PlacedShape> bodies = scene.objects;
  for (const auto& human : scene.humans) {
    for (auto& part : human_shapes(human)) bodies.push_back(std::move(part));
  }
  return bodies;
}

SceneCheck check_scene(const CellModel& cell, const CspaceGrid& grid, SimulatedCell& sim,
                       const SceneUnderTest& under_test, std::size_t configurations,
                       std::mt19937_64& rng) {
  const SimScene& scene = under_test.scene;
  const int threshold = under_test.camera_threshold;
  const std::vector<CheckedBody> bodies =
      check_bodies(cell, sim, scene, under_test.object_ids, threshold);
  SceneCheck check;
  check.bodies = bodies.size();
  for (const auto& body : bodies) check.bodies_visible_enough += body.cameras_visible >= threshold;

  // Every shape the robot can touch, and whose it is: a body of the scene or a static obstacle.
  std::vector<PlacedShape> shapes;
  std::vector<int> owner;
  for (std::size_t h = 0; h < scene.humans.size(); ++h) {
    for (auto& part : human_shapes(scene.humans[h])) {
      shapes.push_back(std::move(part));
      owner.push_back(static_cast<int>(h));
    }
  }
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    shapes.push_back(scene.objects[o]);
    owner.push_back(static_cast<int>(scene.humans.size() + o));
  }
  for (const auto& obstacle : cell.obstacles) {
    shapes.push_back(obstacle);
    owner.push_back(kStaticBody);
  }
  const GroundTruth truth(shapes);
  const CellSet& forbidden = under_test.forbidden;

  for (std::size_t k = 0; k < configurations; ++k) {
    const ConfigurationStratum stratum = kAllConfigurationStrata[k % kConfigurationStrata];
    const std::vector<double> q =
        sample_configuration(stratum, grid, scene, k / kConfigurationStrata, rng);
    const bool is_forbidden = forbidden.test(cell_of(grid, q));
    const std::vector<PlacedShape> robot = collision_shapes_at(*cell.robot, q);
    StratumCounts counts;
    counts.configs = 1;
    const std::vector<std::size_t> hits =
        shapes.empty() ? std::vector<std::size_t>{} : truth.colliding_obstacles(robot);
    if (hits.empty()) {
      ++check.free;
      check.false_positives += is_forbidden ? 1 : 0;
      if (truth.min_distance_m(robot) >= kClearDistance_m) {
        counts.clear = 1;
        counts.clear_forbidden = is_forbidden ? 1 : 0;
        if (is_forbidden && under_test.obstacles != nullptr &&
            check.causes.traced < under_test.decompose) {
          ++check.causes.traced;
          // Its own generator, so that tracing leaves the configurations drawn after it alone.
          std::mt19937_64 trace_rng((static_cast<std::uint64_t>(under_test.index) << 20) ^ k);
          switch (cause_of_needless_stop(cell, grid, sim, truth, under_test, q, trace_rng)) {
            case NeedlessStopCause::kInCell:
              ++check.causes.in_cell;
              break;
            case NeedlessStopCause::kVisualHull:
              ++check.causes.visual_hull;
              break;
            case NeedlessStopCause::kEnvelope:
              ++check.causes.envelope;
              break;
          }
        }
      }
    } else {
      counts.colliding = 1;
      // Must the map hold it? When any touched body is static or visible in enough cameras.
      const CheckedBody* seen = nullptr;
      const CheckedBody* unseen = nullptr;
      bool touches_static = false;
      for (const std::size_t hit : hits) {
        if (owner[hit] == kStaticBody) {
          touches_static = true;
          continue;
        }
        const CheckedBody& body = bodies[static_cast<std::size_t>(owner[hit])];
        const CheckedBody*& first = body.cameras_visible >= threshold ? seen : unseen;
        if (first == nullptr) first = &body;
      }
      if (touches_static || seen != nullptr) {
        if (!is_forbidden) {
          counts.missed = 1;
          if (check.missed_cases.size() < kMissedCasesKept) {
            check.missed_cases.push_back(
                MissedCollision{under_test.index, under_test.stratum, q,
                                seen != nullptr ? body_name(seen->code) : "static obstacle",
                                seen != nullptr ? seen->cameras_visible : -1});
          }
        }
      } else if (unseen != nullptr) {  // always: a hit that is not static is some body's
        counts.unseen = 1;
        check.unseen_forbidden += is_forbidden ? 1 : 0;
        ++check.unseen_reasons[static_cast<std::size_t>(unseen->reason)];
      }
    }
    check.configs_checked += counts.configs;
    check.colliding += counts.colliding;
    check.missed += counts.missed;
    check.unseen += counts.unseen;
    check.clear += counts.clear;
    check.clear_forbidden += counts.clear_forbidden;
    check.strata["scene/" + under_test.stratum] += counts;
    check.strata[std::string("configs/") + to_string(stratum)] += counts;
  }
  return check;
}

}  // namespace safecell
