#include "safecell/cli/sim_render_command.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "command_line.hpp"
#include "png_output.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "scene_options.hpp"

namespace safecell {

void run_sim_render(const SimRenderOptions& options, std::ostream& out) {
  const CellModel model = load_cell_model(load_cell_file_or_default(options.cell_path));
  if (!(options.noise_sigma >= 0.0 && options.noise_sigma <= 50.0)) {
    bad_option("--noise", std::to_string(options.noise_sigma), "expected 0 to 50 gray levels");
  }
  const bool in_degrees = !options.q_deg.empty();
  if (in_degrees == !options.q_rad.empty()) {
    throw InputError("give the robot configuration with exactly one of --q (degrees) and --q-rad");
  }
  SimScene scene{joint_values_rad(in_degrees ? "--q" : "--q-rad",
                                  in_degrees ? options.q_deg : options.q_rad, in_degrees, model),
                 {}};
  for (const auto& human : options.humans) scene.humans.push_back(human_of(human));

  SimulatedCell sim =
      simulate_cell(model, SensorSettings{options.noise_sigma, 0.0, 30.0, options.seed},
                    options.visual ? RobotAppearance::kVisual : RobotAppearance::kCollision);
  const std::vector<cv::Mat> frames = sim.render(scene, 0, 0.0);

  const std::filesystem::path directory(options.out_dir);
  std::filesystem::create_directories(directory);
  for (std::size_t c = 0; c < frames.size(); ++c) {
    const auto path = directory / (sim.camera(c).name() + ".png");
    write_png(path, frames[c]);
    out << "wrote " << path.string() << '\n';
  }
  const auto sheet = directory / "cameras.png";
  std::vector<cv::Mat> tiles;
  for (std::size_t c = 0; c < frames.size(); ++c) {
    tiles.push_back(labelled(frames[c], 0.5, sim.camera(c).name()));
  }
  write_png(sheet, contact_sheet(tiles, 2));
  out << "wrote " << sheet.string() << "  (all cameras)\n";

  // The exact answer for this moment: does the robot touch a human or a box?
  std::vector<PlacedShape> obstacles = model.obstacles;
  for (const auto& human : scene.humans) {
    const auto body = human_shapes(human);
    obstacles.insert(obstacles.end(), body.begin(), body.end());
  }
  if (!obstacles.empty()) {
    const GroundTruth truth(obstacles);
    const auto robot = collision_shapes_at(*model.robot, scene.q);
    out << "ground truth: robot " << (truth.collides(robot) ? "COLLIDES with" : "clear of")
        << " the obstacles; minimum distance " << fixed(truth.min_distance_m(robot), 3) << " m\n";
  }
}

void add_sim_render_command(CLI::App& sim, CommandLine& line) {
  const auto render = std::make_shared<SimRenderOptions>();
  CLI::App* render_command = sim.add_subcommand(
      "render", "Write what every camera sees (PNG) for one robot configuration and some humans");
  render_command->add_option("--cell", render->cell_path,
                             "Cell file (YAML); without it the built-in default cell");
  render_command->add_option("--q", render->q_deg,
                             "Joint values in degrees, comma-separated, e.g. 0,30,60,0,45,0");
  render_command->add_option("--q-rad", render->q_rad, "Joint values in radians instead");
  render_command->add_option("--human", render->humans,
                             "A human standing at x,y (metres, on the floor), optionally facing "
                             "x,y,heading_deg; repeat for more");
  render_command->add_option("--out", render->out_dir, "Folder for the PNG files")->required();
  render_command->add_option("--seed", render->seed, "Seed of the sensor noise")
      ->capture_default_str();
  render_command->add_option("--noise", render->noise_sigma, "Sensor noise sigma in gray levels")
      ->capture_default_str();
  render_command->add_flag("--visual", render->visual,
                           "Show the robot's visual geometry (meshes) instead of its collision "
                           "geometry");
  render_command->callback(
      [=, &line] { line.action = [=, &line] { run_sim_render(*render, line.out); }; });
}

}  // namespace safecell
