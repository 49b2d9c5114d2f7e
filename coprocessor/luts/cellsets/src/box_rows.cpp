#include "safecell/cellsets/box_rows.hpp"

namespace safecell {

BoxAxes BoxAxes::of(const CspaceGrid& grid) {
  BoxAxes axes;
  for (std::uint32_t joint = 0; joint < grid.joint_count(); ++joint) {
    if (joint != 0 && grid.cells_along(joint) == 1) continue;
    axes.joint[axes.count] = joint;
    axes.stride[axes.count] = grid.stride(joint);
    axes.cells[axes.count] = grid.cells_along(joint);
    ++axes.count;
  }
  return axes;
}

}  // namespace safecell
