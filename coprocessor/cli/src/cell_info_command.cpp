#include "safecell/cli/cell_info_command.hpp"

#include <CLI/CLI.hpp>
#include <memory>
#include <nlohmann/json.hpp>

#include "command_line.hpp"
#include "safecell/base/freestanding_math.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/pipeline/cell_fusion_settings.hpp"
#include "safecell/robot/link_geometry.hpp"

namespace safecell {
namespace {

double degrees(double radians) { return radians * 180.0 / kPi; }

// A joint whose farthest point stays within m_max of its axis moves the robot little: sweeping it
// inside every cell costs less than discretising it.
std::string advice(const CspaceGrid& grid, std::uint32_t joint) {
  return grid.joint(joint).l_m > grid.m_max_m() ? "discretise" : "sweep";
}

// "x -0.210..0.210  y ...": the box that bounds a link's shapes, in its frame.
std::string bounds_text(const LinkGeometry& link) {
  if (link.bounds_m.isEmpty()) return "-";
  std::string text;
  for (int axis = 0; axis < 3; ++axis) {
    text += std::string(axis == 0 ? "" : "  ") + "xyz"[axis] + " " +
            fixed(link.bounds_m.min()[axis], 3) + ".." + fixed(link.bounds_m.max()[axis], 3);
  }
  return text;
}

nlohmann::ordered_json links_json(const RobotModel& robot) {
  nlohmann::ordered_json links = nlohmann::ordered_json::array();
  for (const LinkGeometry& link : collision_geometry_of(robot)) {
    nlohmann::ordered_json entry;
    entry["link"] = link.link;
    entry["shapes"] = {{"meshes", link.meshes},
                       {"boxes", link.boxes},
                       {"spheres", link.spheres},
                       {"cylinders", link.cylinders},
                       {"capsules", link.capsules}};
    entry["triangles"] = link.triangles;
    if (link.bounds_m.isEmpty()) {
      entry["bounds_m"] = nullptr;
    } else {
      const Eigen::Vector3d& lo = link.bounds_m.min();
      const Eigen::Vector3d& hi = link.bounds_m.max();
      entry["bounds_m"] = {{"min", {lo.x(), lo.y(), lo.z()}}, {"max", {hi.x(), hi.y(), hi.z()}}};
    }
    links.push_back(std::move(entry));
  }
  return links;
}

void print_links(const RobotModel& robot, std::ostream& out) {
  using Align = TextTable::Align;
  TextTable table({{"link", Align::kLeft},
                   {"collision shapes", Align::kLeft},
                   {"triangles", Align::kRight},
                   {"bounds in the link's frame [m]", Align::kLeft}});
  for (const LinkGeometry& link : collision_geometry_of(robot)) {
    table.add_row({link.link, shape_list(link), grouped(link.triangles), bounds_text(link)});
  }
  table.print(out);
}

nlohmann::ordered_json to_json(const CellModel& model, const CspaceGrid& grid) {
  const CellConfig& cell = model.config;
  nlohmann::ordered_json joints = nlohmann::ordered_json::array();
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const JointSpec& spec = grid.joint(j);
    nlohmann::ordered_json joint;
    joint["name"] = cell.joints[j].name;
    joint["range_rad"] = {spec.lo_rad, spec.hi_rad};
    joint["l_m"] = spec.l_m;
    if (model.lever_arms) joint["l_tool_m"] = model.lever_arms->tool_m[j];
    joint["advice"] = advice(grid, j);
    joint["discretised"] = spec.discretised;
    joint["dq_rad"] = spec.discretised ? nlohmann::ordered_json(grid.max_move_step_rad(j))
                                       : nlohmann::ordered_json(nullptr);
    joint["cell_width_rad"] = grid.cell_width_rad(j);
    joint["cells"] = grid.cells_along(j);
    joint["stride"] = grid.stride(j);
    joints.push_back(std::move(joint));
  }
  nlohmann::ordered_json report;
  report["cell"] = cell.name;
  report["source"] = cell.source;
  if (model.robot) {
    report["robot"] = model.robot->name;
    report["links"] = links_json(*model.robot);
  }
  report["m_max_m"] = grid.m_max_m();
  report["joints"] = std::move(joints);
  report["cells"] = grid.cell_count();
  // A string: JSON numbers lose precision above 2^53.
  report["fingerprint"] = hex64(grid.fingerprint());
  report["warnings"] = nlohmann::ordered_json::array();
  if (const std::string warning = vote_warning(model); !warning.empty()) {
    report["warnings"].push_back(warning);
  }
  return report;
}

void print_text(const CellModel& model, const CspaceGrid& grid, std::ostream& out) {
  const CellConfig& cell = model.config;
  out << cell.name << "  (" << cell.source << ")\n";
  if (model.robot) {
    out << "robot: " << model.robot->name << " (" << model.robot->source
        << "); l is computed from its collision geometry, l tool from the tool point\n\n";
    print_links(*model.robot, out);
    out << '\n';
  }
  out << "max-move m_max = " << fixed(grid.m_max_m(), 3) << " m\n\n";
  using Align = TextTable::Align;
  TextTable table({{"joint", Align::kLeft},
                   {"range [deg]", Align::kRight},
                   {"l [m]", Align::kRight},
                   {"l tool [m]", Align::kRight},
                   {"dq [deg]", Align::kRight},
                   {"width [deg]", Align::kRight},
                   {"cells", Align::kRight},
                   {"advice", Align::kLeft}});
  std::string product;
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const JointSpec& spec = grid.joint(j);
    const bool swept = !spec.discretised;
    table.add_row({cell.joints[j].name,
                   fixed(degrees(spec.lo_rad), 1) + " .. " + fixed(degrees(spec.hi_rad), 1),
                   fixed(spec.l_m, 3),
                   model.lever_arms ? fixed(model.lever_arms->tool_m[j], 3) : "-",
                   swept ? "swept" : fixed(degrees(grid.max_move_step_rad(j)), 2),
                   fixed(degrees(grid.cell_width_rad(j)), 2), std::to_string(grid.cells_along(j)),
                   advice(grid, j)});
    if (!swept) product += (product.empty() ? "" : " x ") + std::to_string(grid.cells_along(j));
  }
  table.print(out);
  out << "\nC-space cells: " << grouped(grid.cell_count()) << "  (" << product << ")\n"
      << "fingerprint:   " << hex64(grid.fingerprint()) << '\n';
  if (const std::string warning = vote_warning(model); !warning.empty()) {
    out << "\nwarning: " << warning << '\n';
  }
}

}  // namespace

void run_cell_info(const CellInfoOptions& options, std::ostream& out) {
  const CellModel model = load_cell_model(load_cell_file_or_default(options.cell_path));
  const CspaceGrid grid = make_grid(model.config);
  if (options.json) {
    out << to_json(model, grid).dump(2) << '\n';
  } else {
    print_text(model, grid, out);
  }
}

void add_cell_info_command(CLI::App& cell, CommandLine& line) {
  const auto cell_info = std::make_shared<CellInfoOptions>();
  CLI::App* info = cell.add_subcommand(
      "info", "Show the C-space grid of a cell: per joint range, l_i, dq_i and cell count");
  info->add_option("--cell", cell_info->cell_path,
                   "Cell file (YAML); without it the built-in default cell of the paper");
  info->add_flag("--json", cell_info->json, "Print one JSON object instead of a table");
  info->callback([=, &line] { line.action = [=, &line] { run_cell_info(*cell_info, line.out); }; });
}

}  // namespace safecell
