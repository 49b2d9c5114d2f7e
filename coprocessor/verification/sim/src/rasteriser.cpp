#include "safecell/sim/rasteriser.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace safecell {
namespace {

constexpr double kNearPlane_m = 0.02;

// Unit vector towards the light, in the cell frame: from above, a little to the side, so that
// the faces of boxes and the facets of limbs differ in brightness. (0.35, 0.25, 1) normalised.
constexpr double kLightNorm = 1.088577052853862;  // sqrt(0.35^2 + 0.25^2 + 1)
constexpr double kLightX = 0.35 / kLightNorm;
constexpr double kLightY = 0.25 / kLightNorm;
constexpr double kLightZ = 1.0 / kLightNorm;

std::uint8_t shade_of(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                      std::uint8_t albedo) {
  const Eigen::Vector3d normal = (b - a).cross(c - a);
  const double length = normal.norm();
  const double lambert =
      length > 0.0
          ? std::abs(normal.x() * kLightX + normal.y() * kLightY + normal.z() * kLightZ) / length
          : 0.0;
  return static_cast<std::uint8_t>(std::lround(albedo * (0.45 + 0.55 * lambert)));
}

// Clips a triangle (camera frame) against z >= near: up to four vertices remain.
int clip_near(const std::array<Eigen::Vector3d, 3>& in, std::array<Eigen::Vector3d, 4>& out) {
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& p = in[static_cast<std::size_t>(i)];
    const Eigen::Vector3d& q = in[static_cast<std::size_t>((i + 1) % 3)];
    const bool p_in = p.z() >= kNearPlane_m;
    const bool q_in = q.z() >= kNearPlane_m;
    if (p_in) out[static_cast<std::size_t>(count++)] = p;
    if (p_in != q_in) {
      const double t = (kNearPlane_m - p.z()) / (q.z() - p.z());
      out[static_cast<std::size_t>(count++)] = p + t * (q - p);
    }
  }
  return count;
}

}  // namespace

Rasteriser::Rasteriser(const CameraIntrinsics& intrinsics, const Eigen::Isometry3d& cell_to_camera)
    : intrinsics_(intrinsics),
      cell_to_camera_(cell_to_camera),
      gray_(intrinsics.height_px, intrinsics.width_px, CV_8UC1),
      depth_(intrinsics.height_px, intrinsics.width_px, CV_32FC1),
      ids_(intrinsics.height_px, intrinsics.width_px, CV_16UC1) {
  clear();
}

void Rasteriser::clear() {
  gray_.setTo(0);
  depth_.setTo(cv::Scalar(static_cast<double>(std::numeric_limits<float>::infinity())));
  ids_.setTo(0);
}

void Rasteriser::draw(const TriangleMesh& mesh, std::uint8_t albedo, BodyCode body) {
  for (const auto& triangle : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[triangle[0]];
    const Eigen::Vector3d& b = mesh.vertices[triangle[1]];
    const Eigen::Vector3d& c = mesh.vertices[triangle[2]];
    const std::uint8_t shade = shade_of(a, b, c, albedo);
    const std::array<Eigen::Vector3d, 3> in{cell_to_camera_ * a, cell_to_camera_ * b,
                                            cell_to_camera_ * c};
    if (in[0].z() >= kNearPlane_m && in[1].z() >= kNearPlane_m && in[2].z() >= kNearPlane_m) {
      draw_camera_triangle(in[0], in[1], in[2], shade, body);
      continue;
    }
    std::array<Eigen::Vector3d, 4> clipped;
    const int count = clip_near(in, clipped);
    for (int k = 1; k + 1 < count; ++k) {
      const auto second = static_cast<std::size_t>(k);
      draw_camera_triangle(clipped[0], clipped[second], clipped[second + 1], shade, body);
    }
  }
}

// Half-space rasterisation with perspective-correct depth (1/z is linear in screen space).
void Rasteriser::draw_camera_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                      const Eigen::Vector3d& c, std::uint8_t shade, BodyCode body) {
  const auto screen = [this](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(intrinsics_.fx_px * p.x() / p.z() + intrinsics_.cx_px,
                           intrinsics_.fy_px * p.y() / p.z() + intrinsics_.cy_px, 1.0 / p.z());
  };
  const Eigen::Vector3d s0 = screen(a), s1 = screen(b), s2 = screen(c);
  const double area = (s1.x() - s0.x()) * (s2.y() - s0.y()) - (s1.y() - s0.y()) * (s2.x() - s0.x());
  if (std::abs(area) < 1e-12) return;
  const int width = gray_.cols, height = gray_.rows;
  const int x0 = std::max(0, static_cast<int>(std::ceil(std::min({s0.x(), s1.x(), s2.x()}))));
  const int x1 =
      std::min(width - 1, static_cast<int>(std::floor(std::max({s0.x(), s1.x(), s2.x()}))));
  const int y0 = std::max(0, static_cast<int>(std::ceil(std::min({s0.y(), s1.y(), s2.y()}))));
  const int y1 =
      std::min(height - 1, static_cast<int>(std::floor(std::max({s0.y(), s1.y(), s2.y()}))));
  if (x0 > x1 || y0 > y1) return;

  // Edge function e_i(x, y) = A_i x + B_i y + C_i, positive inside for either winding after the
  // sign flip; barycentric weights are e_i / area.
  const double sign = area > 0.0 ? 1.0 : -1.0;
  const auto edge = [sign](const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
    return std::array<double, 3>{sign * (p.y() - q.y()), sign * (q.x() - p.x()),
                                 sign * (p.x() * q.y() - p.y() * q.x())};
  };
  const auto e0 = edge(s1, s2), e1 = edge(s2, s0), e2 = edge(s0, s1);
  const double inverse_area = 1.0 / std::abs(area);
  for (int y = y0; y <= y1; ++y) {
    auto* gray_row = gray_.ptr<std::uint8_t>(y);
    auto* depth_row = depth_.ptr<float>(y);
    auto* id_row = ids_.ptr<BodyCode>(y);
    double w0 = e0[0] * x0 + e0[1] * y + e0[2];
    double w1 = e1[0] * x0 + e1[1] * y + e1[2];
    double w2 = e2[0] * x0 + e2[1] * y + e2[2];
    for (int x = x0; x <= x1; ++x, w0 += e0[0], w1 += e1[0], w2 += e2[0]) {
      if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
      const double inverse_z = (w0 * s0.z() + w1 * s1.z() + w2 * s2.z()) * inverse_area;
      const auto z = static_cast<float>(1.0 / inverse_z);
      if (z < depth_row[x]) {
        depth_row[x] = z;
        gray_row[x] = shade;
        id_row[x] = body;
      }
    }
  }
}

}  // namespace safecell
