#include "safecell/cli/sim_render_command.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>

#include "safecell/cell/cell_error.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/files/atomic_write.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

[[noreturn]] void bad_option(const std::string& option, const std::string& value,
                             const std::string& expected) {
  throw std::invalid_argument(option + " '" + value + "': " + expected);
}

std::vector<double> numbers_in(const std::string& option, const std::string& text) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(value)) {
      bad_option(option, text, "expected comma-separated numbers, '" + item + "' is not one");
    }
    values.push_back(value);
  }
  return values;
}

// Joint values in radians, checked against the cell's ranges.
std::vector<double> joint_values(const SimRenderOptions& options, const CellModel& model) {
  const bool in_degrees = !options.q_deg.empty();
  if (in_degrees == !options.q_rad.empty()) {
    throw std::invalid_argument(
        "give the robot configuration with exactly one of --q (degrees) and --q-rad");
  }
  const std::string option = in_degrees ? "--q" : "--q-rad";
  const std::string& text = in_degrees ? options.q_deg : options.q_rad;
  std::vector<double> q = numbers_in(option, text);
  const auto& joints = model.config.joints;
  if (q.size() != joints.size()) {
    bad_option(
        option, text,
        std::to_string(joints.size()) + " joint values expected, got " + std::to_string(q.size()));
  }
  for (std::size_t j = 0; j < q.size(); ++j) {
    const double deg = in_degrees ? q[j] : q[j] / kRadPerDeg;
    const auto& range = joints[j].range_deg.value();
    if (deg < range[0] || deg > range[1]) {
      bad_option(option, text,
                 joints[j].name + " = " + fixed(deg, 2) + " deg lies outside the cell's range [" +
                     fixed(range[0], 2) + ", " + fixed(range[1], 2) + "] deg");
    }
    q[j] = deg * kRadPerDeg;
  }
  return q;
}

HumanPose human_of(const std::string& text) {
  const auto values = numbers_in("--human", text);
  if (values.size() != 2 && values.size() != 3) {
    bad_option("--human", text, "expected x,y or x,y,heading_deg (metres, degrees)");
  }
  HumanPose pose;
  pose.position_m = Eigen::Vector2d(values[0], values[1]);
  pose.heading_rad = values.size() == 3 ? values[2] * kRadPerDeg : 0.0;
  return pose;
}

void write_png(const std::filesystem::path& path, const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  if (!cv::imencode(".png", image, bytes)) {
    throw std::runtime_error(path.string() + ": the PNG encoder refused the image");
  }
  write_file_atomically(
      path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

// All camera views side by side in two columns, half size, each labelled with its name.
cv::Mat contact_sheet(const std::vector<cv::Mat>& frames, const SimulatedCell& sim) {
  std::vector<cv::Mat> tiles;
  for (std::size_t c = 0; c < frames.size(); ++c) {
    cv::Mat tile;
    cv::resize(frames[c], tile, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
    cv::putText(tile, sim.camera(c).name(), {8, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.7, 255, 2);
    tiles.push_back(tile);
  }
  if (tiles.size() % 2 == 1) tiles.push_back(cv::Mat::zeros(tiles.front().size(), CV_8UC1));
  std::vector<cv::Mat> rows;
  for (std::size_t i = 0; i < tiles.size(); i += 2) {
    cv::Mat row;
    cv::hconcat(tiles[i], tiles[i + 1], row);
    rows.push_back(row);
  }
  cv::Mat sheet;
  cv::vconcat(rows, sheet);
  return sheet;
}

}  // namespace

void run_sim_render(const SimRenderOptions& options, std::ostream& out) {
  const CellModel model = load_cell_model(
      options.cell_path.empty() ? default_cell() : load_cell_file(options.cell_path));
  if (!model.robot) {
    throw_cell_error(SourceLine{model.config.source, 0}, "robot",
                     "missing: the simulated cell needs the robot's URDF");
  }
  if (model.cameras.empty()) {
    throw_cell_error(SourceLine{model.config.source, 0}, "cameras",
                     "missing: the simulated cell needs at least one camera");
  }
  if (!(options.noise_sigma >= 0.0 && options.noise_sigma <= 50.0)) {
    bad_option("--noise", std::to_string(options.noise_sigma), "expected 0 to 50 gray levels");
  }
  SimScene scene{joint_values(options, model), {}};
  for (const auto& human : options.humans) scene.humans.push_back(human_of(human));

  SimulatedCell sim(
      *model.robot, model.cameras,
      Eigen::Vector3d(model.config.size_m[0], model.config.size_m[1], model.config.size_m[2]),
      model.obstacles, SensorSettings{options.noise_sigma, 0.0, 30.0, options.seed},
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
  write_png(sheet, contact_sheet(frames, sim));
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

}  // namespace safecell
