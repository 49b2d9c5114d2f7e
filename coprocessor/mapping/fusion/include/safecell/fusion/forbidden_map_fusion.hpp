#pragma once
// The fusion of paper §4.3-4.4 (DESIGN.md §3, "Fusion"): per camera, remove the robot from the
// blocked mask (robot_removal.hpp), back-project what remains with LUT-2 into the camera's set of
// suspicious cells (the union of the cells of its blocked pixels); a cell is critical when at
// least `camera_threshold` cameras suspect it; forbidden = critical + static obstacles.
//
// The vote is taken per robot part (robot_parts.hpp): each part has its own LUT-2, and a cell is
// critical when, for some part, at least `camera_threshold` cameras suspect it through that
// part's tables. A configuration collides where one part meets the obstacle; that part's
// silhouette holds the obstacle in every camera that sees it, so this is exactly as safe as the
// paper's vote over the whole robot, without its phantoms (one camera's obstacle at the wrist,
// another's at the elbow). A part that fewer than `camera_threshold` cameras can suspect at all
// this cycle (their obstacles miss its every non-empty pixel) is skipped.
//
// Back-projection uses LUT-2's block levels where it can: a block of 2^l x 2^l pixels that are
// all obstacles adds its precomputed union at once (pixel_table_builder.hpp), and a pixel or block
// whose left or upper neighbour is all obstacles adds only its difference to it (the shorter one
// where both are). Runs are filled in
// the line layout (cell_lines.hpp), where the cameras are also counted; only the critical cells
// are packed. A camera stops early once its set holds every cell it can see.
//
// The parts are voted on one after the other into one critical set. A part whose every cell
// that `camera_threshold` cameras can see through it at all is critical already cannot add to
// the set and is skipped (FusionCounts::part_covered). With someone close to the arm the upper
// arm's vote often makes every cell critical; the forearm's back-projection after it, which the
// skip saves, was about 80 % of those frames' time on the 6 cm grid (34 of the demo's 300 frames
// there: 12-14 ms before, at most 5.7 ms with the skip).
//
// Counting is per camera, not per pixel: many pixels of one camera marking a cell still count
// once. An unknown view counts as suspecting every cell the camera can see at all.
//
// Hidden votes (FusionSettings::hidden_votes, off by default): a camera whose blocked pixels
// inside the robot's silhouette (what removal dropped: the robot, or whatever it hides) fall in a
// part's silhouette of a cell may be looking at an obstacle there through the robot, so it votes
// for the cell as well - but only where some camera does see an obstacle through that part. A
// cell is then critical when, for some part, at least one camera suspects it and at least
// `camera_threshold` cameras suspect it or have it hidden. A person hidden from some cameras by
// the arm then needs only one camera with a clear view, at any threshold. The price is high:
// with cells of m_max 0.18 m most cells' silhouettes meet the robot's own pixels in several
// cameras, so one camera's obstacle makes them critical (validate, 200 scenes: needless stops
// 8.8 % -> 75 % at threshold 3, 49 % -> 76 % at threshold 2). It is for cells whose cameras
// the robot hides often; by default what the robot hides from a camera is left to the others,
// as in the paper, and `validate` counts the bodies too few cameras see as unseen.
//
// After construction a cycle allocates nothing. Not thread-safe: one engine per fusion thread.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "safecell/fusion/camera_observation.hpp"
#include "safecell/fusion/robot_removal.hpp"
#include "safecell/silhouettes/configuration_silhouettes.hpp"
#include "safecell/silhouettes/robot_silhouettes.hpp"
#include "safecell/tables/lut_set.hpp"

namespace safecell {

struct FusionSettings {
  int camera_threshold = 2;  // 1..camera count
  RobotRemoval removal = RobotRemoval::kOcclusionAware;
  int occlusion_reach = kDefaultOcclusionReach;  // feature cells, for kOcclusionAware
  // How far apart the frames' exposure and the joint values given for it may be (the time-sync
  // error bound), s: robot removal at the configuration widens the silhouette by the motion
  // possible in that time (configuration_silhouettes.hpp).
  double sync_error_s = 0.002;
  // Calibration and model error the silhouette at the configuration is widened by, m (as the
  // padding of the tables).
  double padding_m = 0.02;
  // Whether the robot's blocked pixels vote as hidden (see above); off: the paper's vote, where
  // what the robot hides from a camera is left to the other cameras.
  bool hidden_votes = false;
};

struct FusionCounts {
  std::vector<std::size_t> obstacle_pixels;  // per camera, after robot removal (0 when unknown)
  // Per camera: blocked pixels inside the robot's silhouette that removal dropped, which vote as
  // hidden (0 when unknown or without hidden votes).
  std::vector<std::size_t> hidden_pixels;
  // Per part and camera (part * cameras + camera): back-projection stopped early because the set
  // held every cell the camera sees of the part.
  std::vector<bool> saturated;
  // Per part: whether enough cameras could suspect it to be voted on (else it was skipped), and
  // whether it made any cell critical.
  std::vector<bool> part_voted;
  std::vector<bool> part_critical;
  // Per part: voted on, but skipped, every cell it could make critical being critical already.
  std::vector<bool> part_covered;
  std::size_t critical_cells = 0;
  std::size_t forbidden_cells = 0;
};

class ForbiddenMapFusion {
 public:
  // Keeps references to `luts`, `silhouettes` and `at_configuration`: all must outlive the
  // engine. at_configuration: the robot's silhouette at its joint values, which occlusion-aware
  // removal uses when a cycle gives them; without it (or them), and for plain removal, the
  // removal uses LUT-1 of the robot's cell. Throws std::invalid_argument when the silhouettes'
  // camera count differs from the tables', or the threshold is outside 1..camera count.
  ForbiddenMapFusion(const LutSet& luts, const RobotSilhouettes& silhouettes,
                     const FusionSettings& settings,
                     const ConfigurationSilhouettes* at_configuration = nullptr);

  // One cycle. robot_cell: the cell of the robot's configuration at the frames' exposure time;
  // q: that configuration (rad, one per joint), or empty. Throws std::invalid_argument for the
  // wrong number of observations or a mask of the wrong size, std::out_of_range for a robot cell
  // outside the grid.
  const CellSet& fuse(const std::vector<CameraObservation>& observations, CellIndex robot_cell,
                      std::span<const double> q = {});
  // fuse() in two halves, for a caller that decides on the obstacles whether the map is needed
  // (the protective separation: when it stops the robot, every cell is forbidden anyway).
  // remove_robot: robot removal alone, the same arguments and errors as fuse(); obstacles(),
  // hidden(), robot_silhouette() and counts().obstacle_pixels are then this cycle's.
  void remove_robot(const std::vector<CameraObservation>& observations, CellIndex robot_cell,
                    std::span<const double> q = {});
  // Back-projection and vote on what remove_robot left of the same observations (the same
  // object); throws std::logic_error unless remove_robot ran on them since the last vote or
  // forbid_all.
  const CellSet& vote(const std::vector<CameraObservation>& observations);
  // In place of vote(): every cell forbidden, none critical, no part voted on (about a memset of
  // the map; no back-projection).
  const CellSet& forbid_all();

  [[nodiscard]] const CellSet& forbidden() const { return forbidden_; }
  [[nodiscard]] const CellSet& critical() const { return critical_; }
  // The cells one camera suspected through one part's tables in the last cycle (none for an
  // unknown view or a part not voted on); packed on each call, for pictures and tests.
  [[nodiscard]] CellSet suspicious(std::size_t part, std::size_t camera) const;
  // The obstacle pixels of one camera in the last cycle (blocked minus the robot).
  [[nodiscard]] const FeatureMask& obstacles(std::size_t camera) const {
    return obstacles_.at(camera);
  }
  // The pixels of one camera that voted as hidden in the last cycle (blocked, inside the robot's
  // silhouette, not kept as obstacles; none without hidden votes).
  [[nodiscard]] const FeatureMask& hidden(std::size_t camera) const { return hidden_.at(camera); }
  // The robot's silhouette that removal used in one camera in the last cycle (at its
  // configuration, or LUT-1 of its cell).
  [[nodiscard]] const FeatureMask& robot_silhouette(std::size_t camera) const {
    return robot_.at(camera);
  }
  [[nodiscard]] const FusionCounts& counts() const { return counts_; }
  // Cells a camera can see one part in at all (that part's LUT-2 of some pixel holds them).
  [[nodiscard]] const CellSet& observable(std::size_t part, std::size_t camera) const {
    return observable_.at(slot(part, camera));
  }
  // Cells a camera can see some part in.
  [[nodiscard]] const CellSet& observable(std::size_t camera) const {
    return observable_any_part_.at(camera);
  }
  [[nodiscard]] const LutSet& luts() const { return luts_; }
  [[nodiscard]] std::size_t camera_count() const { return luts_.cameras.size(); }
  [[nodiscard]] std::size_t part_count() const { return luts_.parts.size(); }
  [[nodiscard]] const std::vector<RobotPart>& parts() const { return luts_.parts; }
  [[nodiscard]] const FusionSettings& settings() const { return settings_; }

 private:
  // Per part and camera data are kept part-major.
  [[nodiscard]] std::size_t slot(std::size_t part, std::size_t camera) const {
    return part * luts_.cameras.size() + camera;
  }
  void check(const std::vector<CameraObservation>& observations) const;
  struct VoterCounts {
    std::size_t seeing = 0;  // cameras whose obstacles reach the part (or unknown views)
    std::size_t voting = 0;  // those, and cameras whose hidden pixels reach it
  };
  // Which cameras can suspect the part this cycle, or have some of it hidden (unknown views
  // always suspect): into seeing_, hiding_ and voting_.
  VoterCounts find_voters(const std::vector<CameraObservation>& observations, std::size_t part);
  // Adds the cells of one part that the camera's `pixels` back-project to into `into`.
  // `present`: pixels whose cells are in the set, or will be by the end of the cycle (a superset
  // of `pixels`), whose entries let a neighbour add only its difference. Returns whether it
  // stopped early, the set holding every cell the camera can see of the part.
  bool back_project(std::size_t part, std::size_t camera, const FeatureMask& pixels,
                    const FeatureMask& present, CellLines& into);

  const LutSet& luts_;
  const RobotSilhouettes& silhouettes_;
  const ConfigurationSilhouettes* at_configuration_;
  FusionSettings settings_;
  std::vector<CellSet> observable_;           // per part and camera
  std::vector<CellSet> observable_any_part_;  // per camera
  std::vector<FeatureMask> reach_;            // per part and camera: pixels with any cell
  std::vector<CellLines> suspicious_lines_;   // per part and camera, filled box by box
  std::vector<CellLines> observable_lines_;   // observable_ in the line layout
  // Per part, in the full grid's line layout: the cells at least camera_threshold cameras can
  // see through the part, the only ones its vote can make critical.
  std::vector<std::vector<std::uint64_t>> votable_lines_;
  // Per camera, for the part being voted on: its obstacles reach the part, its hidden pixels
  // do, and it votes at all.
  std::vector<bool> seeing_;
  std::vector<bool> hiding_;
  std::vector<bool> voting_;
  std::vector<CellLines> voting_lines_;  // per camera: suspicious or hidden, this part's
  // Per camera, this part's: the set it votes with and the set of what it suspects (null: it
  // does not vote). Voted on at the highest level any of them was written at (fold_to).
  std::vector<CellLines*> vote_sets_;
  std::vector<CellLines*> suspect_sets_;
  std::vector<std::span<const std::uint64_t>> camera_lines_;  // this part's vote per camera
  std::vector<std::uint64_t> seen_lines_;  // cells some camera suspects through this part
  // at_least_[k]: cells suspected by at least k + 1 cameras, a block at a time (or_at_least).
  std::vector<std::vector<std::uint64_t>> at_least_;
  CellLines critical_lines_;  // each part's vote at its level, folded before it is read
  std::vector<FeatureMask> robot_;
  std::vector<FeatureMask> obstacles_;
  std::vector<FeatureMask> hidden_;
  std::vector<FeatureMask> remaining_;  // obstacle pixels not yet covered by a whole block
  CellSet critical_;
  CellSet forbidden_;
  FusionCounts counts_;
  // The observations remove_robot ran on this cycle (vote() is allowed on them alone); null after
  // a vote, forbid_all or a refused removal. Compared, never read through.
  const std::vector<CameraObservation>* removed_from_ = nullptr;
};

inline constexpr std::size_t kAtLeastBlockWords = 512;  // 4 KB per count level

// ORs into `into` the bits that at least `threshold` of the word arrays `sets` hold and `mask`
// holds too (every bit when `mask` is empty); returns whether there were any. Word-parallel:
// at_least[k] |= at_least[k - 1] & set. scratch: at least `threshold` arrays, resized to
// block_words, their contents ignored. Throws std::invalid_argument for a threshold below 1,
// too little scratch, sets or a mask of another size than `into`, or a block of 0 words.
//
// It counts a block of `block_words` at a time, so that the counts stay in the first-level cache
// and each array is read once from memory: on the 6 cm grid's 2.8 MB line sets, counting whole
// arrays level by level (a block of all the words) moves about three times as many bytes
// (benchmark camera_votes_fine_grid_*).
bool or_at_least(const std::vector<std::span<const std::uint64_t>>& sets, int threshold,
                 std::span<const std::uint64_t> mask,
                 std::vector<std::vector<std::uint64_t>>& scratch, std::span<std::uint64_t> into,
                 std::size_t block_words = kAtLeastBlockWords);

// Every cell some pixel of the table back-projects to.
[[nodiscard]] CellSet observable_cells(const PixelToCellsTable& table);

// Where the robot is, for robot removal: its cell, and its joint values if known.
struct RobotAtExposure {
  const RobotSilhouettes& cell_silhouettes;          // LUT-1
  const ConfigurationSilhouettes* at_configuration;  // may be null
  CellIndex cell = 0;
  std::span<const double> q;  // may be empty
};

// What robot removal leaves of each camera's view.
struct ViewsWithoutRobot {
  std::vector<FeatureMask>& robot;      // the silhouettes used
  std::vector<FeatureMask>& obstacles;  // blocked minus the robot (none when unknown)
  // Blocked pixels inside the silhouette not kept as obstacles, with hidden votes (else none).
  std::vector<FeatureMask>& hidden;
};

// Robot removal for every known camera (shared by the fast fusion and the baseline): with the
// silhouette at the configuration for occlusion-aware removal when there is one and q is given,
// LUT-1 of the cell otherwise.
void remove_robot_from_views(const std::vector<CameraObservation>& observations,
                             const RobotAtExposure& where, const FusionSettings& settings,
                             const ViewsWithoutRobot& views);

}  // namespace safecell
