#pragma once
// The protective separation check: the half of speed and separation monitoring (ISO/TS 15066)
// that the look-ahead cannot give. The look-ahead keeps the robot out of the cells the map
// forbids along its way; a person who walks into the side of a moving robot is in no cell ahead
// of it, and the robot's own cell turns forbidden only when they all but touch it - the robot is
// then still braking when they meet (controller/SAFETY_CASE.md, "Direction").
//
// The check, once per map cycle at the robot's configuration at the exposure, for each level
// (a speed f and its distance S(f), from full speed down): each ball of the robot at its
// configuration (the balls that cover its geometry, robot_balls.hpp), grown by S(f) and the
// removal's widening, is projected into every camera as the rectangle of its image. When, for
// some ball, at least `camera_threshold` cameras see an obstacle (after robot removal) inside its
// rectangle, or have an unknown view, a person may be within S(f) of the robot. The verdict is
// the speed of the first level whose vote is clear: the robot may go at that fraction of its top
// speed (the service sends it with the map, the controller caps its speed scale); when every
// level votes, the robot must stop and the service forbids the whole map.
//
// Why slowing is enough: from speed f the robot stops within f * t_stop (the deceleration the
// stop holds), so someone at S(f) = K (t_response + f t_stop) + C or beyond cannot reach it
// before it is at rest. S(f) falls at K / t_stop per unit of f, the rate at which a person
// walking in at K eats into it, while the robot slows at 1 / t_stop per second when it brakes:
// the slow-down keeps pace with the approach (docs/closed_loop_findings.md).
//
// Why it is conservative: let p be the robot's point nearest to a point x within S of it; p lies
// in some ball (centre c, radius r), so |x - c| <= |x - p| + |p - c| <= S + r: x lies in that
// ball grown by S, and in every camera that sees x its pixel lies inside that one ball's
// rectangle. So the cameras that see x all vote for the same ball - the argument of the tables'
// envelope, for one configuration and a larger margin. S covers the person's approach from the
// exposure until the robot is at rest (cell_config.hpp, SeparationDistanceConfig), not the
// robot's own travel meanwhile (ISO/TS 15066's S_R + S_S): the look-ahead checks that travel
// against the map, cell by cell until the robot is at rest (controller/SAFETY_CASE.md).
//
// Why per ball: the vote over a whole part's grown image (before commit 8311e66) also counted two
// cameras that see obstacles at opposite ends of a part grown by up to 0.64 m, a point that no
// one ball holds; the vote per ball asks the cameras to agree on one ball, as safe and tighter.
//
// Thread context: the pipeline's; not thread-safe (scratch balls and rectangles are members).

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/features/feature_mask.hpp"
#include "safecell/fusion/camera_observation.hpp"
#include "safecell/robot/robot_parts.hpp"
#include "safecell/silhouettes/configuration_silhouettes.hpp"

namespace safecell {

// One level of the check: while no obstacle is within separation_m of the robot, it may move at
// `speed` (a fraction of its top speed).
struct SeparationLevel {
  double speed = 1.0;
  double separation_m = 0.0;
};

// The levels of a cell file's protective separation: full speed at S, then each reduced speed f
// at S(f) = K (t_response + f t_stop) + C. Throws std::invalid_argument for speeds that are not
// descending within (0, 1).
[[nodiscard]] std::vector<SeparationLevel> separation_levels(
    const SeparationDistanceConfig& distance, const std::vector<double>& reduced_speeds);

struct SeparationVerdict {
  // The speed the robot may keep (a fraction of its top speed): the first clear level's; 1 when
  // nobody is within the full-speed distance, 0 when every level voted (too_close: a stop).
  double speed_limit = 1.0;
  bool too_close = false;
  // The distance the check found clear of obstacles: S of the level allowed (0 for a stop).
  double clear_m = 0.0;
  // The last level that voted (when speed_limit < 1): its distance, the part of the first ball
  // that voted at it and that ball's cameras (unknown views among them).
  double within_m = 0.0;
  std::size_t part = 0;
  std::vector<std::size_t> cameras;
};

class ProtectiveSeparation {
 public:
  // widening_m: the removal's (padding and the motion within the sync error); levels: from full
  // speed (speed 1, the largest S) down, speeds and distances descending. Throws
  // std::invalid_argument for no parts, no levels, levels out of order, a first level that is
  // not full speed, a threshold outside 1..cameras, S outside 0..0.95 m, or what
  // ConfigurationSilhouettes refuses.
  ProtectiveSeparation(const CellModel& cell, std::vector<RobotPart> parts, double ball_radius_m,
                       double widening_m, std::vector<SeparationLevel> levels,
                       int camera_threshold);

  // S at full speed.
  [[nodiscard]] double separation_m() const { return levels_.front().separation_m; }
  [[nodiscard]] const std::vector<SeparationLevel>& levels() const { return levels_; }
  [[nodiscard]] const std::vector<RobotPart>& parts() const { return parts_; }

  // The vote at joint values q (rad): `known[c]` whether camera c's view was known,
  // `obstacles[c]` its obstacles after robot removal (not read for an unknown view). Throws
  // std::invalid_argument for counts that are not the cameras', or a known view's obstacles
  // missing or not of the cell's feature grid (a smaller mask would hide part of a ball's image).
  [[nodiscard]] SeparationVerdict check(std::span<const double> q, const std::vector<bool>& known,
                                        const std::vector<const FeatureMask*>& obstacles) const;
  // The grown image (full-speed distance) of part `part` at q in every camera (for pictures and
  // tests).
  [[nodiscard]] std::vector<FeatureMask> grown_part(std::span<const double> q,
                                                    std::size_t part) const;

 private:
  // Whether, at level `level`, some ball has threshold cameras voting; fills the verdict's part
  // and cameras when one has.
  bool votes(std::size_t level, std::span<const double> q, const std::vector<bool>& known,
             const std::vector<const FeatureMask*>& obstacles, SeparationVerdict& verdict) const;

  std::vector<RobotPart> parts_;
  std::vector<SeparationLevel> levels_;
  int camera_threshold_;
  FeatureGrid grid_;
  std::vector<ConfigurationSilhouettes> grown_;  // per level
  // Scratch of votes(): a part's balls placed, and their feature rectangles per camera.
  mutable std::vector<Ball> balls_;
  mutable std::vector<std::vector<std::optional<FeatureRect>>> rects_;
};

// The kind of a stop's reason (ServiceCycle::all_forbidden's text before its colon): what the
// run's, the demo's and the closed loop's counts group by.
inline constexpr const char* kSeparationStopKind =
    "an obstacle within the protective separation distance";

// The reason of a stop (the map forbidden whole; its kind is the text before the colon):
// "an obstacle within the protective separation distance: 0.28 m of the robot's upper arm
// (links 1-2) in cameras 'cam0', 'cam2'". Of a slow-down: "slowed to 50 % by the protective
// separation: an obstacle within 0.64 m of ...".
std::string describe(const SeparationVerdict& verdict, const ProtectiveSeparation& check,
                     const CellModel& cell);

}  // namespace safecell
