#include "safecell/cspace/grid_spec.hpp"

namespace safecell {

const char* to_string(GridField field) noexcept {
  switch (field) {
    case GridField::kJointCount:
      return "joint count";
    case GridField::kMaxMove:
      return "m_max";
    case GridField::kRange:
      return "range";
    case GridField::kLeverArm:
      return "lever arm l";
    case GridField::kCellCount:
      return "cell count";
  }
  return "unknown field";
}

}  // namespace safecell
