#pragma once
// Where people walk in a fenced cell: along the rectangle kFenceInset_m inside the walls, coming
// in and going out through the cell's entries (cell_config.hpp). Used by the closed-loop
// scenarios and the demo's person.

#include <Eigen/Core>
#include <vector>

#include "safecell/cell/cell_model.hpp"

namespace safecell {

inline constexpr double kFenceInset_m = 0.3;  // people walk this far inside the walls
inline constexpr double kOutside_m = 0.6;     // and start and end this far outside an entry

// The rectangle kFenceInset_m inside the walls, parameterised by the distance along it from its
// (-x, -y) corner: along -y, up +x, back along +y, down -x.
struct InsetRectangle {
  double hx = 0.0;
  double hy = 0.0;

  explicit InsetRectangle(const CellModel& cell);

  [[nodiscard]] double perimeter() const { return 4.0 * (hx + hy); }
  // The point `along` (in [0, perimeter)) from the (-x, -y) corner.
  [[nodiscard]] Eigen::Vector2d point(double along) const;
  // How far along the rectangle `p` lies. Throws std::logic_error unless `p` lies on it.
  [[nodiscard]] double along(const Eigen::Vector2d& p) const;
  // The shorter way round from `from` to `to` (both on the rectangle): the corners passed, then
  // `to`.
  [[nodiscard]] std::vector<Eigen::Vector2d> walk(const Eigen::Vector2d& from,
                                                  const Eigen::Vector2d& to) const;
};

// Where a person passes an entry: kOutside_m outside the wall and on the inset rectangle, at
// `along` in [0, 1] across the opening. An opening that reaches nearer a corner than
// kFenceInset_m is walked through where it meets the rectangle (the point is clamped onto it).
struct Doorway {
  Eigen::Vector2d outside_m;
  Eigen::Vector2d inside_m;
};
[[nodiscard]] Doorway fence_doorway(const CellModel& cell, const EntryConfig& entry, double along);

}  // namespace safecell
