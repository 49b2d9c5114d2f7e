#include "safecell/robot/lever_arms.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "safecell/geometry/shape_bounds.hpp"

namespace safecell {
namespace {

constexpr double kBinWidth_m = 0.002;
constexpr std::size_t kCircleSamples = 1440;

// The points of a set, as seen from an axis through the origin: for each slice of axial
// position, the largest distance from the axis and the axial extent of the points in the slice.
class AxisProfile {
 public:
  struct Slice {
    bool used = false;
    double radius_m = 0.0;
    double h_min_m = 0.0;
    double h_max_m = 0.0;
  };

  explicit AxisProfile(const Eigen::Vector3d& axis) : axis_(axis) {}

  // Adds a point known only to within slack_m.
  void add(const Eigen::Vector3d& point, double slack_m) {
    const double h = axis_.dot(point);
    const double radius = (point - h * axis_).norm() + slack_m;
    const auto first = static_cast<long>(std::floor((h - slack_m) / kBinWidth_m));
    const auto last = static_cast<long>(std::floor((h + slack_m) / kBinWidth_m));
    cover(first, last);
    for (long bin = first; bin <= last; ++bin) {
      Slice& slice = slices_[static_cast<std::size_t>(bin - first_bin_)];
      if (!slice.used) {
        slice = Slice{true, radius, h - slack_m, h + slack_m};
        continue;
      }
      slice.radius_m = std::max(slice.radius_m, radius);
      slice.h_min_m = std::min(slice.h_min_m, h - slack_m);
      slice.h_max_m = std::max(slice.h_max_m, h + slack_m);
    }
  }

  double max_radius_m() const {
    double radius = 0.0;
    for (const auto& slice : slices_) radius = std::max(radius, slice.radius_m);
    return radius;
  }

  // Every slice, used or not (unused ones have used == false).
  const std::vector<Slice>& slices() const { return slices_; }
  const Eigen::Vector3d& axis() const { return axis_; }

 private:
  // Grows the slice array (bins first_bin_ ...) so that it holds bins first..last.
  void cover(long first, long last) {
    if (slices_.empty()) {
      first_bin_ = first;
      slices_.resize(static_cast<std::size_t>(last - first + 1));
      return;
    }
    if (first < first_bin_) {
      slices_.insert(slices_.begin(), static_cast<std::size_t>(first_bin_ - first), Slice{});
      first_bin_ = first;
    }
    const long end = first_bin_ + static_cast<long>(slices_.size());
    if (last >= end) slices_.resize(slices_.size() + static_cast<std::size_t>(last - end + 1));
  }

  Eigen::Vector3d axis_;
  long first_bin_ = 0;
  std::vector<Slice> slices_;
};

// cos and sin of the circle's sample angles, computed once.
struct CircleSamples {
  std::array<double, kCircleSamples> cos{};
  std::array<double, kCircleSamples> sin{};
};

const CircleSamples& circle_samples() {
  static const CircleSamples samples = [] {
    CircleSamples table;
    for (std::size_t k = 0; k < kCircleSamples; ++k) {
      const double angle = 2.0 * std::numbers::pi * static_cast<double>(k) / kCircleSamples;
      table.cos[k] = std::cos(angle);
      table.sin[k] = std::sin(angle);
    }
    return table;
  }();
  return samples;
}

// Adds to `parent` (an axis profile in the parent link's frame) everything a child profile
// covers when the child joint moves over its whole range.
void sweep_into(const AxisProfile& child, const RobotJoint& child_joint, AxisProfile& parent) {
  const Eigen::Isometry3d& origin = child_joint.origin;
  const Eigen::Vector3d axis = origin.linear() * child.axis();
  const Eigen::Vector3d u = axis.unitOrthogonal();
  const Eigen::Vector3d v = axis.cross(u);
  // A prismatic joint slides the (revolved) child set; a convex measure peaks at the ends.
  std::vector<double> shifts{0.0};
  if (child_joint.type == JointType::kPrismatic) shifts = {child_joint.lower, child_joint.upper};
  for (const auto& slice : child.slices()) {
    if (!slice.used) continue;
    // Largest gap between a point of the circle and the nearest sample.
    const double slack = 2.0 * slice.radius_m *
                         std::sin(std::numbers::pi / (2.0 * static_cast<double>(kCircleSamples)));
    for (const double h : {slice.h_min_m, slice.h_max_m}) {
      for (const double shift : shifts) {
        const Eigen::Vector3d centre = origin * (h * child.axis()) + shift * axis;
        if (slice.radius_m == 0.0) {
          parent.add(centre, 0.0);
          continue;
        }
        const CircleSamples& circle = circle_samples();
        for (std::size_t k = 0; k < kCircleSamples; ++k) {
          parent.add(centre + slice.radius_m * (circle.cos[k] * u + circle.sin[k] * v), slack);
        }
      }
    }
  }
}

// l_i for every joint, given the points each link carries (in that link's frame).
std::vector<double> lever_arms_of(const RobotModel& model,
                                  const std::vector<std::vector<Eigen::Vector3d>>& points) {
  std::vector<double> lever_arms(model.dof(), 0.0);
  std::unique_ptr<AxisProfile> later;
  for (std::size_t k = model.dof(); k-- > 0;) {
    auto profile = std::make_unique<AxisProfile>(model.joints[k].axis);
    for (const auto& point : points[k]) profile->add(point, 0.0);
    if (later) sweep_into(*later, model.joints[k + 1], *profile);
    lever_arms[k] = profile->max_radius_m();
    later = std::move(profile);
  }
  return lever_arms;
}

void append(std::vector<Eigen::Vector3d>& to, const std::vector<Eigen::Vector3d>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

}  // namespace

LeverArms compute_lever_arms(const RobotModel& model, const ToolSpec& tool) {
  const auto frame = tool_frame(model, tool);
  std::vector<Eigen::Vector3d> tool_points{frame.pose * tool.point_m};
  for (const auto& shape : tool.shapes) {
    append(tool_points, extreme_points(PlacedShape{shape.shape, frame.pose * shape.pose}));
  }

  std::vector<std::vector<Eigen::Vector3d>> tool_only(model.dof());
  tool_only[static_cast<std::size_t>(frame.link)] = tool_points;
  std::vector<std::vector<Eigen::Vector3d>> envelope = tool_only;
  for (std::size_t k = 0; k < model.dof(); ++k) {
    for (const auto& shape : model.links[k].collision) append(envelope[k], extreme_points(shape));
  }
  return LeverArms{lever_arms_of(model, tool_only), lever_arms_of(model, envelope)};
}

}  // namespace safecell
