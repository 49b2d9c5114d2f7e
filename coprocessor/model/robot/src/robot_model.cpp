#include "safecell/robot/robot_model.hpp"

namespace safecell {

std::optional<NamedFrame> RobotModel::frame(const std::string& link_name) const {
  for (const auto& named : frames) {
    if (named.name == link_name) return named;
  }
  return std::nullopt;
}

}  // namespace safecell
