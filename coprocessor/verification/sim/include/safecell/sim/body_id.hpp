#pragma once
// Which body a pixel of the simulated cell shows: the codes of the renderer's object-id image
// (camera_renderer.hpp). The kind sits in the top four bits, the body's index within its kind
// (static obstacle b of the cell file, human n, object n of the scene) in the other twelve.
// Code 0 is the background: floor, walls and ceiling.

#include <cstddef>
#include <cstdint>
#include <string>

namespace safecell {

enum class BodyKind : std::uint8_t {
  kBackground = 0,
  kRobot = 1,
  kStaticObstacle = 2,
  kHuman = 3,
  kObject = 4,
};

using BodyCode = std::uint16_t;

inline constexpr std::size_t kMaxBodiesPerKind = 4096;

// Throws std::out_of_range for an index of kMaxBodiesPerKind or more.
[[nodiscard]] BodyCode body_code(BodyKind kind, std::size_t index = 0);
[[nodiscard]] constexpr BodyKind body_kind(BodyCode code) {
  return static_cast<BodyKind>(code >> 12);
}
[[nodiscard]] constexpr std::size_t body_index(BodyCode code) { return code & 0x0FFFu; }
// "human 2", "object 1", "static obstacle 0", "robot", "background" (indices from 1 for humans
// and objects, as reports count them).
[[nodiscard]] std::string body_name(BodyCode code);

}  // namespace safecell
