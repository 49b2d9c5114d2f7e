#include "safecell/robot/urdf_loader.hpp"

#include <console_bridge/console.h>

#include <urdf_parser/urdf_parser.h>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <sstream>

#include "safecell/robot/mesh_loader.hpp"
#include "safecell/robot/robot_error.hpp"
#include "urdf_xml_check.hpp"

namespace safecell {
namespace {

// Collects urdfdom's error messages (it reports through console_bridge) for the duration of one
// parse, so they can go into the exception instead of onto stderr. Not thread-safe: console
// bridge's handler is global.
class CapturedConsole final : public console_bridge::OutputHandler {
 public:
  CapturedConsole() { console_bridge::useOutputHandler(this); }
  ~CapturedConsole() override { console_bridge::restorePreviousOutputHandler(); }
  CapturedConsole(const CapturedConsole&) = delete;
  CapturedConsole& operator=(const CapturedConsole&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char* /*filename*/,
           int /*line*/) override {
    if (level < console_bridge::CONSOLE_BRIDGE_LOG_ERROR) return;
    messages_ += (messages_.empty() ? "" : "; ") + text;
  }
  const std::string& messages() const { return messages_; }

 private:
  std::string messages_;
};

Eigen::Isometry3d to_isometry(const urdf::Pose& pose) {
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  result.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  return result;
}

class ChainBuilder {
 public:
  static constexpr std::size_t kMaxLinks = 10000;

  ChainBuilder(const urdf::ModelInterface& urdf, std::string source,
               std::filesystem::path mesh_directory, const UrdfOptions& options)
      : urdf_(urdf),
        source_(std::move(source)),
        mesh_directory_(std::move(mesh_directory)),
        options_(options) {}

  RobotModel build(const std::string& tool_link) {
    const auto path = path_to(tool_link.empty() ? deepest_leaf() : tool_link);
    model_.name = urdf_.getName();
    model_.source = source_;
    model_.base.name = path.front()->name;
    for (std::size_t k = 0; k < path.size(); ++k) {
      const urdf::LinkConstSharedPtr& link = path[k];
      const std::string next = k + 1 < path.size() ? path[k + 1]->name : "";
      add_link_geometry(*link);
      // Side branches first: they hang from this link's pose, which stepping on changes.
      const urdf::Joint* onward = nullptr;
      for (const auto& joint : link->child_joints) {
        if (joint->child_link_name == next) {
          onward = joint.get();
        } else {
          fold_side_branch(*joint, link->name, pose_);
        }
      }
      if (onward != nullptr) step_through(*onward);
    }
    if (model_.joints.empty()) {
      fail("no movable joint between the root link '" + path.front()->name +
           "' and the tool link '" + path.back()->name + "'");
    }
    check_every_moving_link_has_collision();
    return std::move(model_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    throw RobotError(source_ + ": " + problem);
  }

  static bool movable(const urdf::Joint& joint) { return joint.type != urdf::Joint::FIXED; }

  int movable_joints_to_root(urdf::LinkConstSharedPtr link, const std::string& name) const {
    int count = 0;
    std::size_t steps = 0;
    for (; link->parent_joint; link = urdf_.getLink(link->parent_joint->parent_link_name)) {
      if (movable(*link->parent_joint)) ++count;
      if (++steps > kMaxLinks) fail("the joints above link '" + name + "' form a loop");
    }
    return count;
  }

  std::string deepest_leaf() const {
    std::vector<urdf::LinkSharedPtr> links;
    urdf_.getLinks(links);
    std::string best;
    int best_count = -1;
    std::map<std::string, urdf::LinkSharedPtr> by_name;  // sorted: ties go to the first name
    for (const auto& link : links) by_name[link->name] = link;
    for (const auto& [name, link] : by_name) {
      if (!link->child_links.empty()) continue;
      const int count = movable_joints_to_root(link, name);
      if (count > best_count) {
        best_count = count;
        best = name;
      }
    }
    if (best.empty()) fail("no link without children: the joints form a loop");
    return best;
  }

  std::vector<urdf::LinkConstSharedPtr> path_to(const std::string& tool_link) const {
    urdf::LinkConstSharedPtr link = urdf_.getLink(tool_link);
    if (!link) fail("no link named '" + tool_link + "' (the tool link)");
    std::vector<urdf::LinkConstSharedPtr> path;
    for (; link; link = link->parent_joint ? urdf_.getLink(link->parent_joint->parent_link_name)
                                           : nullptr) {
      path.insert(path.begin(), link);
      if (path.size() > kMaxLinks) fail("the joints above link '" + tool_link + "' form a loop");
    }
    if (path.size() == 1) {
      fail("the tool link '" + tool_link + "' is the root link: no movable joint to follow");
    }
    return path;
  }

  // A length of a shape: finite and above 0 (urdfdom reads numbers strictly, not their range).
  double length_of(double value, const std::string& link_name, const char* what) const {
    if (!(std::isfinite(value) && value > 0.0)) {
      fail("link '" + link_name + "': " + what + " is " + std::to_string(value) +
           ", expected a length above 0 m");
    }
    return value;
  }

  Shape shape_of(const urdf::Geometry& geometry, const std::string& link_name) const {
    switch (geometry.type) {
      case urdf::Geometry::BOX: {
        const auto& box = static_cast<const urdf::Box&>(geometry);
        return Box{{length_of(box.dim.x, link_name, "<box size> x"),
                    length_of(box.dim.y, link_name, "<box size> y"),
                    length_of(box.dim.z, link_name, "<box size> z")}};
      }
      case urdf::Geometry::SPHERE:
        return Sphere{length_of(static_cast<const urdf::Sphere&>(geometry).radius, link_name,
                                "<sphere radius>")};
      case urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
        return Cylinder{length_of(cylinder.radius, link_name, "<cylinder radius>"),
                        length_of(cylinder.length, link_name, "<cylinder length>")};
      }
      case urdf::Geometry::MESH: {
        const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
        const Eigen::Vector3d scale(mesh.scale.x, mesh.scale.y, mesh.scale.z);
        if (!(scale.allFinite() && scale.cwiseAbs().minCoeff() > 0.0)) {
          fail("link '" + link_name + "': <mesh scale> of '" + mesh.filename +
               "' is not three finite factors other than 0");
        }
        return load_mesh(mesh_path(mesh.filename, link_name), scale);
      }
    }
    fail("link '" + link_name + "' has collision geometry of an unknown type");
  }

  std::filesystem::path mesh_path(const std::string& filename, const std::string& link_name) const {
    constexpr std::string_view kFileScheme = "file://";
    if (filename.rfind("package://", 0) == 0) {
      fail("link '" + link_name + "': mesh '" + filename +
           "' uses a ROS package URI; give a path relative to the URDF file instead");
    }
    std::filesystem::path path = filename.rfind(kFileScheme, 0) == 0
                                     ? std::filesystem::path(filename.substr(kFileScheme.size()))
                                     : std::filesystem::path(filename);
    if (path.is_relative()) path = mesh_directory_ / path;
    if (!std::filesystem::is_regular_file(path)) {
      fail("link '" + link_name + "': mesh file '" + path.string() + "' not found");
    }
    return path;
  }

  // Adds a link's collision and visual geometry to the movable link it is folded into.
  void add_link_geometry(const urdf::Link& link) {
    model_.frames.push_back(NamedFrame{link.name, current_, pose_});
    RobotLink& target =
        current_ < 0 ? model_.base : model_.links[static_cast<std::size_t>(current_)];
    for (const auto& collision : link.collision_array) {
      if (!collision || !collision->geometry)
        fail("link '" + link.name + "': a <collision> with no geometry");
      target.collision.push_back(PlacedShape{shape_of(*collision->geometry, link.name),
                                             pose_ * to_isometry(collision->origin)});
    }
    add_stand_in(link, target);
    for (const auto& visual : link.visual_array) {
      if (!visual || !visual->geometry)
        fail("link '" + link.name + "': a <visual> with no geometry");
      target.visual.push_back(
          PlacedShape{shape_of(*visual->geometry, link.name), pose_ * to_isometry(visual->origin)});
    }
  }

  // The cell's geometry for a link the URDF gives none (UrdfOptions::collision_stand_ins).
  void add_stand_in(const urdf::Link& link, RobotLink& target) {
    const auto stand_in = options_.collision_stand_ins.find(link.name);
    if (stand_in == options_.collision_stand_ins.end()) return;
    if (!link.collision_array.empty()) {
      fail("link '" + link.name +
           "' has <collision> geometry, yet a stand-in is given for it; stand-ins are for links "
           "without");
    }
    for (const PlacedShape& shape : stand_in->second) {
      target.collision.push_back(PlacedShape{shape.shape, pose_ * shape.pose});
    }
    stood_in_.push_back(link.name);
  }

  void check_every_moving_link_has_collision() const {
    for (const auto& [name, shapes] : options_.collision_stand_ins) {
      if (std::find(stood_in_.begin(), stood_in_.end(), name) == stood_in_.end()) {
        fail("a collision stand-in is given for link '" + name +
             "', which is not on the chain from the root to the tool link");
      }
    }
    for (const RobotLink& link : model_.links) {
      if (link.collision.empty()) {
        fail("link '" + link.name +
             "' moves but has no <collision> geometry (nor has any fixed link on it): the tables "
             "would never forbid touching it. Add its geometry to the URDF, or name the shapes "
             "that stand in for it in the cell file (robot.collision_stand_ins)");
      }
    }
  }

  void fold_side_branch(const urdf::Joint& joint, const std::string& parent_name,
                        const Eigen::Isometry3d& parent_pose) {
    if (movable(joint)) {
      fail("joint '" + joint.name + "' moves a side branch off the chain at link '" + parent_name +
           "'; only serial chains are supported");
    }
    const Eigen::Isometry3d saved = pose_;
    pose_ = parent_pose * to_isometry(joint.parent_to_joint_origin_transform);
    const urdf::LinkConstSharedPtr child = urdf_.getLink(joint.child_link_name);
    add_link_geometry(*child);
    const Eigen::Isometry3d child_pose = pose_;
    for (const auto& grandchild : child->child_joints) {
      fold_side_branch(*grandchild, child->name, child_pose);
    }
    pose_ = saved;
  }

  void step_through(const urdf::Joint& joint) {
    const Eigen::Isometry3d origin = pose_ * to_isometry(joint.parent_to_joint_origin_transform);
    if (!movable(joint)) {
      pose_ = origin;
      return;
    }
    RobotJoint robot_joint;
    robot_joint.name = joint.name;
    robot_joint.origin = origin;
    switch (joint.type) {
      case urdf::Joint::REVOLUTE:
        robot_joint.type = JointType::kRevolute;
        break;
      case urdf::Joint::CONTINUOUS:
        robot_joint.type = JointType::kContinuous;
        break;
      case urdf::Joint::PRISMATIC:
        robot_joint.type = JointType::kPrismatic;
        break;
      default:
        fail("joint '" + joint.name +
             "' is neither revolute, continuous, prismatic nor fixed (floating and planar joints "
             "are not supported)");
    }
    const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
    if (!(axis.norm() > 1e-9)) fail("joint '" + joint.name + "' has a zero axis");
    robot_joint.axis = axis.normalized();
    if (robot_joint.type == JointType::kContinuous) {
      robot_joint.lower = -std::numbers::pi;
      robot_joint.upper = std::numbers::pi;
    } else if (joint.limits) {
      robot_joint.lower = joint.limits->lower;
      robot_joint.upper = joint.limits->upper;
    }
    if (!(robot_joint.lower < robot_joint.upper)) {
      fail("joint '" + joint.name + "' has limits [" + std::to_string(robot_joint.lower) + ", " +
           std::to_string(robot_joint.upper) + "], expected lower < upper");
    }
    if (joint.limits) robot_joint.max_speed = joint.limits->velocity;
    model_.joints.push_back(robot_joint);
    model_.links.push_back(RobotLink{joint.child_link_name, {}, {}});
    current_ = static_cast<int>(model_.joints.size()) - 1;
    pose_ = Eigen::Isometry3d::Identity();
  }

  const urdf::ModelInterface& urdf_;
  std::string source_;
  std::filesystem::path mesh_directory_;
  const UrdfOptions& options_;
  std::vector<std::string> stood_in_;  // links given their stand-in shapes
  RobotModel model_;
  int current_ = -1;                                        // movable link being filled; -1 = base
  Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();  // path link in that link's frame
};

}  // namespace

RobotModel parse_urdf(const std::string& xml, const std::string& source,
                      const std::filesystem::path& mesh_directory, const UrdfOptions& options) {
  check_urdf_xml(xml, source);
  urdf::ModelInterfaceSharedPtr urdf;
  {
    // urdfdom reports what it could not read as an error and leaves it out of the model (a
    // collision with a malformed origin vanishes): any error it reports refuses the file.
    CapturedConsole console;
    urdf = urdf::parseURDF(xml);
    if (!urdf || !console.messages().empty()) {
      throw RobotError(
          source + ": not a valid URDF: " +
          (console.messages().empty() ? std::string("urdfdom refused it") : console.messages()));
    }
  }
  return ChainBuilder(*urdf, source, mesh_directory, options).build(options.tool_link);
}

RobotModel load_urdf_file(const std::filesystem::path& path, const UrdfOptions& options) {
  std::ifstream file(path, std::ios::binary);
  if (!file || std::filesystem::is_directory(path)) {
    throw RobotError(path.string() + ": cannot be opened for reading");
  }
  std::error_code error;
  if (const auto bytes = std::filesystem::file_size(path, error); !error && bytes > kMaxUrdfBytes) {
    throw RobotError(path.string() + ": " + std::to_string(bytes) + " bytes, expected at most " +
                     std::to_string(kMaxUrdfBytes) + " for a robot description");
  }
  std::ostringstream text;
  text << file.rdbuf();
  return parse_urdf(text.str(), path.string(), path.parent_path(), options);
}

}  // namespace safecell
