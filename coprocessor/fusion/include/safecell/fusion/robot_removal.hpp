#pragma once
// Robot removal (paper §4): the robot's own pixels must not become obstacles. LUT-1 of the cell
// the robot was in when the frames were taken says which feature cells it can cover.
//
// kPlain is the paper's: blocked pixels inside the robot's silhouette are dropped. It also drops
// whatever stood in front of or behind the robot there, so a person next to the arm in the image
// can lose the part that overlaps it, or all of a thin limb.
//
// kOcclusionAware (the default) keeps every blocked region that reaches outside the silhouette
// whole, the part inside included: a person partly hidden by the robot is a connected blob, and
// its hidden part can be anywhere inside the silhouette next to the visible part. Only blocked
// regions wholly inside the silhouette (the robot itself) are dropped. Pixels of the silhouette
// that are not blocked are seen free and stay free. Connectivity is 8-neighbour.

#include "safecell/lut/feature_mask.hpp"

namespace safecell {

enum class RobotRemoval { kOcclusionAware, kPlain };

const char* to_string(RobotRemoval removal);

// obstacles = what of `blocked` remains once the robot (`silhouette`) is removed. `obstacles` is
// resized to the mask size when needed; it must not alias the inputs. Throws
// std::invalid_argument for masks of different sizes.
void remove_robot(const FeatureMask& blocked, const FeatureMask& silhouette, RobotRemoval removal,
                  FeatureMask& obstacles);

}  // namespace safecell
