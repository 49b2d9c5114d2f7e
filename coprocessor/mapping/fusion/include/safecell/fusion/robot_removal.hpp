#pragma once
// Robot removal (paper §4): the robot's own pixels must not become obstacles. LUT-1 of the cell
// the robot was in when the frames were taken says which feature cells it can cover.
//
// kPlain is the paper's: blocked pixels inside the robot's silhouette are dropped. It also drops
// whatever stood in front of or behind the robot there, so a person next to the arm in the image
// can lose the part that overlaps it, or all of a thin limb.
//
// kOcclusionAware (the default) treats the blocked pixels inside the silhouette as unknown rather
// than free: a person partly hidden by the robot is one blob with its visible part, so every
// blocked silhouette pixel within `reach` feature cells (8-neighbour steps through blocked
// silhouette pixels) of a blocked pixel outside the silhouette is kept as an obstacle. Blocked
// regions wholly inside the silhouette (the robot itself) are dropped; silhouette pixels that
// are not blocked are seen free. The reach is bounded because a fill without bound would run
// along the whole arm and mark the robot's own configuration as an obstacle whenever a person
// touches its image; a person wholly hidden in one camera is left to the other cameras.

#include "safecell/features/feature_mask.hpp"

namespace safecell {

enum class RobotRemoval { kOcclusionAware, kPlain };

const char* to_string(RobotRemoval removal);

// The default reach of the occlusion-aware fill, in feature cells (about 20 cm at 3 m).
inline constexpr int kDefaultOcclusionReach = 3;

// obstacles = what of `blocked` remains once the robot (`silhouette`) is removed. `obstacles` is
// resized to the mask size when needed; it must not alias the inputs. Throws
// std::invalid_argument for masks of different sizes or a negative reach.
void remove_robot(const FeatureMask& blocked, const FeatureMask& silhouette, RobotRemoval removal,
                  FeatureMask& obstacles, int reach = kDefaultOcclusionReach);

}  // namespace safecell
