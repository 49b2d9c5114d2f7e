#include "safecell/sim/cell_scenery.hpp"

#include <cmath>

namespace safecell {
namespace {

constexpr double kFloorTile_m = 0.25;
constexpr double kWallTile_m = 0.5;
constexpr std::uint8_t kBoxAlbedo = 150;
constexpr std::uint8_t kCeilingAlbedo = 200;

// A fixed pseudo-random brightness per tile, the same on every run.
std::uint8_t tile_albedo(int i, int j, int salt, int base, int spread) {
  // Unsigned arithmetic: the products wrap by definition (signed ones would overflow).
  auto hash = static_cast<std::uint32_t>(i) * 73856093u ^
              static_cast<std::uint32_t>(j) * 19349663u ^
              static_cast<std::uint32_t>(salt) * 83492791u;
  hash ^= hash >> 13;
  hash *= 0x5bd1e995u;
  hash ^= hash >> 15;
  return static_cast<std::uint8_t>(base +
                                   static_cast<int>(hash % static_cast<std::uint32_t>(spread)));
}

// A rectangle origin + s u + t v (s, t in [0, 1]) as two triangles.
TriangleMesh quad(const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                  const Eigen::Vector3d& v) {
  TriangleMesh mesh;
  mesh.vertices = {origin, origin + u, origin + u + v, origin + v};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

// A plane area tiled into squares of `tile` metres, each its own SurfaceMesh.
void add_tiled(std::vector<SurfaceMesh>& out, const Eigen::Vector3d& origin,
               const Eigen::Vector3d& u, const Eigen::Vector3d& v, double tile, int salt, int base,
               int spread) {
  const int nu = std::max(1, static_cast<int>(std::lround(u.norm() / tile)));
  const int nv = std::max(1, static_cast<int>(std::lround(v.norm() / tile)));
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      out.push_back(SurfaceMesh{quad(origin + u * i / nu + v * j / nv, u / nu, v / nv),
                                tile_albedo(i, j, salt, base, spread)});
    }
  }
}

}  // namespace

std::vector<SurfaceMesh> cell_scenery(const Eigen::Vector3d& size_m,
                                      const std::vector<PlacedShape>& boxes) {
  const double hx = size_m.x() / 2.0, hy = size_m.y() / 2.0, height = size_m.z();
  std::vector<SurfaceMesh> scenery;
  add_tiled(scenery, {-hx, -hy, 0.0}, {size_m.x(), 0.0, 0.0}, {0.0, size_m.y(), 0.0}, kFloorTile_m,
            1, 70, 90);
  add_tiled(scenery, {-hx, -hy, 0.0}, {size_m.x(), 0.0, 0.0}, {0.0, 0.0, height}, kWallTile_m, 2,
            100, 70);
  add_tiled(scenery, {-hx, hy, 0.0}, {size_m.x(), 0.0, 0.0}, {0.0, 0.0, height}, kWallTile_m, 3,
            100, 70);
  add_tiled(scenery, {-hx, -hy, 0.0}, {0.0, size_m.y(), 0.0}, {0.0, 0.0, height}, kWallTile_m, 4,
            100, 70);
  add_tiled(scenery, {hx, -hy, 0.0}, {0.0, size_m.y(), 0.0}, {0.0, 0.0, height}, kWallTile_m, 5,
            100, 70);
  scenery.push_back(SurfaceMesh{
      quad({-hx, -hy, height}, {size_m.x(), 0.0, 0.0}, {0.0, size_m.y(), 0.0}), kCeilingAlbedo});
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    scenery.push_back(surface_of({boxes[b]}, kBoxAlbedo, body_code(BodyKind::kStaticObstacle, b)));
  }
  return scenery;
}

}  // namespace safecell
