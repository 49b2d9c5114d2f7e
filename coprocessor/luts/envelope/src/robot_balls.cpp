#include "safecell/envelope/robot_balls.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include "safecell/geometry/tessellate.hpp"

namespace safecell {
namespace {

constexpr int kTessellationSegments = 24;

// Points on a triangle such that every point of the triangle lies within the returned gap of one
// of them: the triangle is split into n x n similar pieces with edges of at most max_edge_m, and
// the pieces' corners are returned. Within a triangle whose edges are all at most e, no point is
// farther than e / sqrt(3) from its nearest corner.
double sample_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                       double max_edge_m, std::vector<Eigen::Vector3d>& points) {
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  const int n = std::max(1, static_cast<int>(std::ceil(longest / max_edge_m)));
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const double s = static_cast<double>(i) / n;
      const double t = static_cast<double>(j) / n;
      points.push_back(a + s * (b - a) + t * (c - a));
    }
  }
  return longest / n / std::sqrt(3.0);
}

using VoxelKey = std::tuple<long, long, long>;

struct VoxelPoints {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> points;
};

}  // namespace

std::size_t RobotBalls::count() const {
  std::size_t total = base.size();
  for (const auto& link : links) total += link.size();
  return total;
}

std::vector<Ball> cover_shapes_with_balls(const std::vector<PlacedShape>& shapes,
                                          double target_radius_m) {
  if (!std::isfinite(target_radius_m) || target_radius_m <= 0.0) {
    throw std::invalid_argument("ball radius must be finite and > 0 m, got " +
                                std::to_string(target_radius_m));
  }
  // Surface samples, grouped by voxels whose circumscribed ball has the target radius; each
  // voxel's samples become one ball about their centroid, grown by the sampling gap.
  const double voxel_m = 2.0 * target_radius_m / std::sqrt(3.0);
  const double max_edge_m = target_radius_m / 4.0 * std::sqrt(3.0);
  std::map<VoxelKey, VoxelPoints> voxels;
  double gap_m = 0.0;
  std::vector<Eigen::Vector3d> samples;
  for (const auto& placed : shapes) {
    const TriangleMesh mesh = tessellate(placed, kTessellationSegments);
    if (mesh.triangles.empty()) throw std::invalid_argument("a robot shape has no surface");
    for (const auto& triangle : mesh.triangles) {
      samples.clear();
      gap_m = std::max(gap_m,
                       sample_triangle(mesh.vertices.at(triangle[0]), mesh.vertices.at(triangle[1]),
                                       mesh.vertices.at(triangle[2]), max_edge_m, samples));
      for (const auto& point : samples) {
        if (!point.allFinite()) throw std::invalid_argument("a robot shape is not finite");
        const VoxelKey key{static_cast<long>(std::floor(point.x() / voxel_m)),
                           static_cast<long>(std::floor(point.y() / voxel_m)),
                           static_cast<long>(std::floor(point.z() / voxel_m))};
        VoxelPoints& voxel = voxels[key];
        voxel.sum += point;
        voxel.points.push_back(point);
      }
    }
  }
  std::vector<Ball> balls;
  balls.reserve(voxels.size());
  for (const auto& [key, voxel] : voxels) {
    Ball ball;
    ball.centre_m = voxel.sum / static_cast<double>(voxel.points.size());
    for (const auto& point : voxel.points) {
      ball.radius_m = std::max(ball.radius_m, (point - ball.centre_m).norm());
    }
    ball.radius_m += gap_m;
    balls.push_back(ball);
  }
  return balls;
}

RobotBalls cover_with_balls(const RobotModel& model, double target_radius_m) {
  RobotBalls balls;
  balls.base = cover_shapes_with_balls(model.base.collision, target_radius_m);
  balls.links.reserve(model.links.size());
  for (const auto& link : model.links) {
    balls.links.push_back(cover_shapes_with_balls(link.collision, target_radius_m));
  }
  return balls;
}

}  // namespace safecell
