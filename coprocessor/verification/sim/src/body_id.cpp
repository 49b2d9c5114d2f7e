#include "safecell/sim/body_id.hpp"

#include <stdexcept>

namespace safecell {

BodyCode body_code(BodyKind kind, std::size_t index) {
  if (index >= kMaxBodiesPerKind) {
    throw std::out_of_range("body index " + std::to_string(index) + " beyond the " +
                            std::to_string(kMaxBodiesPerKind) + " an object-id image can tell");
  }
  return static_cast<BodyCode>((static_cast<unsigned>(kind) << 12) | index);
}

std::string body_name(BodyCode code) {
  const std::size_t index = body_index(code);
  switch (body_kind(code)) {
    case BodyKind::kBackground:
      return "background";
    case BodyKind::kRobot:
      return "robot";
    case BodyKind::kStaticObstacle:
      return "static obstacle " + std::to_string(index);
    case BodyKind::kHuman:
      return "human " + std::to_string(index + 1);
    case BodyKind::kObject:
      return "object " + std::to_string(index + 1);
  }
  return "body " + std::to_string(code);
}

}  // namespace safecell
