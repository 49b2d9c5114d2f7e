#include "safecell/cell/cell_model.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cell_errors.hpp"
#include "safecell/camera/default_cameras.hpp"
#include "safecell/cell/cell_error.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/cell/entry_zones.hpp"

namespace safecell {
namespace {

constexpr const char* kBuiltinCell = R"(name: built-in arm
m_max_m: 0.18
robot: {urdf: "builtin:rx130_class", tool: {frame: flange}}
joints:
  - {name: joint_1}
  - {name: joint_2}
  - {name: joint_3}
  - {name: joint_4, range_deg: [-240, 240]}
  - {name: joint_5, discretised: false}
  - {name: joint_6, discretised: false}
)";

std::string model_error_of(const std::string& text) {
  return test::cell_error_of(
      [&] { static_cast<void>(load_cell_model(parse_cell_yaml(text, "cell.yaml"))); });
}

using test::replaced;

TEST(CellModel, LeverArmsAndRangesComeFromTheRobot) {
  const CellModel model = load_cell_model(parse_cell_yaml(kBuiltinCell, "cell.yaml"));
  ASSERT_TRUE(model.robot.has_value());
  // l_1 of the built-in arm: 1.51 m to the flange, a little more to the collision shapes.
  EXPECT_GT(model.config.joints[0].l_m.value(), 1.51);
  EXPECT_LT(model.config.joints[0].l_m.value(), 1.56);
  EXPECT_EQ(model.config.joints[0].l_m.value(), model.lever_arms->envelope_m[0]);
  // Joint 1's range defaults to the arm's +-160 deg; joint 4 is narrowed by the cell.
  EXPECT_NEAR(model.config.joints[0].range_deg.value()[1], 160.0, 1e-4);
  EXPECT_EQ(model.config.joints[3].range_deg.value()[0], -240.0);
}

TEST(CellModel, TheDefaultCellHasThePapersSize) {
  const CspaceGrid grid = make_grid(load_cell_model(default_cell()).config);
  // The paper: 181,400 cells for its RX130 at m_max = 18 cm.
  EXPECT_GE(grid.cell_count(), 150000u);
  EXPECT_LE(grid.cell_count(), 200000u);
}

TEST(CellModel, TheDefaultCellHasFourCornerCamerasAndAWorkbench) {
  const CellModel model = load_cell_model(default_cell());
  ASSERT_EQ(model.cameras.size(), 4u);
  for (const auto& camera : model.cameras) {
    EXPECT_EQ(camera.intrinsics().width_px, 704);
    EXPECT_EQ(camera.intrinsics().height_px, 576);
    EXPECT_NEAR(camera.position_m().z(), 2.9, 1e-12);
    EXPECT_NEAR(std::abs(camera.position_m().x()), 1.95, 1e-12);
    // Every camera sees the robot base.
    const auto base = camera.project(Eigen::Vector3d::Zero());
    ASSERT_TRUE(base.has_value());
    EXPECT_TRUE(camera.in_image(*base)) << camera.name();
  }
  // The camera module's default_cameras() describes the same set-up: keep the two in step.
  const auto expected = default_cameras();
  ASSERT_EQ(expected.size(), model.cameras.size());
  for (std::size_t c = 0; c < expected.size(); ++c) {
    EXPECT_EQ(model.cameras[c].name(), expected[c].name());
    EXPECT_EQ(model.cameras[c].intrinsics(), expected[c].intrinsics());
    EXPECT_LT(
        (model.cameras[c].cell_to_camera().matrix() - expected[c].cell_to_camera().matrix()).norm(),
        1e-12);
  }
  EXPECT_EQ(model.feature_grid.cell_width_px(), 11);
  EXPECT_EQ(model.feature_grid.cell_height_px(), 9);
  ASSERT_EQ(model.obstacles.size(), 1u);
  EXPECT_EQ(model.camera_threshold, 3);
  EXPECT_EQ(model.occlusion_reach_cells, 4);
  EXPECT_EQ(model.envelope_subdivision, 3u);  // 0.06 m of 0.18 (docs/validation.md, "Sub-cells")
  EXPECT_EQ(model.robot_parts, PartSplit::kLinksAndWrist);
  EXPECT_EQ(model.ball_radius_m, 0.04);
  ASSERT_TRUE(model.config.protective_separation.has_value());
  EXPECT_NEAR(separation_distance_m(*model.config.protective_separation), 0.64, 1e-12);
  EXPECT_EQ(model.feature_weights.average, 2);
  EXPECT_EQ(model.blocked_threshold, 24);
}

// docs/examples/real_cameras: the README's walk-through for real cameras. Its calibrations are
// example values near the default cell's cameras, each with a source of another kind.
TEST(CellModel, TheRealCamerasExampleLoads) {
  const CellModel cell = load_cell_model(
      load_cell_file(std::filesystem::path(SAFECELL_EXAMPLES_DIR) / "real_cameras" / "cell.yaml"));
  ASSERT_EQ(cell.cameras.size(), 4U);
  using Kind = CameraSourceConfig::Kind;
  const Kind kinds[] = {Kind::kDevice, Kind::kGstreamer, Kind::kStream, Kind::kVideoFile};
  const auto defaults = default_cameras();
  for (std::size_t c = 0; c < 4; ++c) {
    ASSERT_TRUE(cell.config.cameras[c].source.has_value()) << c;
    EXPECT_EQ(cell.config.cameras[c].source->kind, kinds[c]) << c;
    EXPECT_LT((cell.cameras[c].position_m() - defaults[c].position_m()).norm(), 1e-9) << c;
    EXPECT_NE(cell.cameras[c].intrinsics().distortion.k1, 0.0) << c;
  }
  EXPECT_EQ(cell.config.entries->size(), 1U);
}

TEST(CellModel, UnusableCamerasObstaclesAndThresholdsAreNamed) {
  const std::string camera =
      "cameras:\n  - {name: a, look_at: {position_m: [2, 2, 3], target_m: [0, 0, 0], "
      "horizontal_fov_deg: 75, size_px: [704, 576]}}\n";
  const std::string cell = std::string(kBuiltinCell) + camera;
  EXPECT_EQ(load_cell_model(parse_cell_yaml(cell, "cell.yaml")).cameras.size(), 1u);

  const std::string twice = model_error_of(cell +
                                           "  - {name: a, look_at: {position_m: [2, -2, 3], "
                                           "target_m: [0, 0, 0], horizontal_fov_deg: 75, "
                                           "size_px: [704, 576]}}\n");
  EXPECT_EQ(twice,
            "cell.yaml:13: cameras[1].name: 'a' is used by an earlier camera; names must differ");
  const std::string wide =
      model_error_of(replaced(cell, "horizontal_fov_deg: 75", "horizontal_fov_deg: 190"));
  EXPECT_EQ(wide.rfind("cell.yaml:12: cameras[0].look_at: ", 0), 0u) << wide;
  const std::string missing = model_error_of(std::string(kBuiltinCell) +
                                             "cameras:\n  - {name: b, calibration: /no/b.yaml}\n");
  EXPECT_EQ(missing.rfind("cell.yaml:12: cameras[0].calibration: ", 0), 0u) << missing;
  EXPECT_NE(missing.find("/no/b.yaml"), std::string::npos) << missing;
  EXPECT_EQ(
      model_error_of(std::string(kBuiltinCell) + "cameras:\n  - {name: c}\n"),
      "cell.yaml:12: cameras[0]: expected exactly one of 'calibration' (a file) and 'look_at' "
      "(a placement)");

  const std::string grid = model_error_of(cell + "feature_grid: {columns: 50, rows: 64}\n");
  EXPECT_EQ(grid.rfind("cell.yaml:13: feature_grid: value [50 x 64] for camera 'a': ", 0), 0u)
      << grid;
  EXPECT_EQ(model_error_of(cell + "camera_threshold: 2\n"),
            "cell.yaml:13: camera_threshold: value 2, expected 1 to the number of cameras (1)");
  EXPECT_EQ(model_error_of(cell + "occlusion_reach_cells: -1\n"),
            "cell.yaml:13: occlusion_reach_cells: value -1, expected 0 to 64 feature cells (the "
            "feature grid's longer side)");
  EXPECT_EQ(model_error_of(cell + "occlusion_reach_cells: 65\n"),
            "cell.yaml:13: occlusion_reach_cells: value 65, expected 0 to 64 feature cells (the "
            "feature grid's longer side)");
  EXPECT_FALSE(load_cell_model(parse_cell_yaml(std::string(kBuiltinCell), "c.yaml"))
                   .occlusion_reach_cells.has_value());
  const auto sub_cells = [](const std::string& max_move) {
    return load_cell_model(
               parse_cell_yaml(
                   std::string(kBuiltinCell) + "envelope_max_move_m: " + max_move + "\n", "c.yaml"))
        .envelope_subdivision;
  };
  EXPECT_EQ(
      load_cell_model(parse_cell_yaml(std::string(kBuiltinCell), "c.yaml")).envelope_subdivision,
      1u);
  EXPECT_EQ(sub_cells("0.18"), 1u);
  EXPECT_EQ(sub_cells("0.5"), 1u);
  EXPECT_EQ(sub_cells("0.09"), 2u);
  EXPECT_EQ(sub_cells("0.06"), 3u);
  EXPECT_EQ(sub_cells("0.045"), 4u);
  EXPECT_EQ(sub_cells("0.001"), 4u);  // at most kMaxEnvelopeSubdivision
  EXPECT_EQ(model_error_of(std::string(kBuiltinCell) + "envelope_max_move_m: 0\n"),
            "cell.yaml:11: envelope_max_move_m: value 0.000000, expected a distance above 0 m");
  EXPECT_EQ(model_error_of(std::string(kBuiltinCell) + "envelope_max_move_m: -1\n"),
            "cell.yaml:11: envelope_max_move_m: value -1.000000, expected a distance above 0 m");
  const auto parts = [](const std::string& split) {
    return load_cell_model(
               parse_cell_yaml(std::string(kBuiltinCell) + "robot_parts: " + split + "\n",
                               "c.yaml"))
        .robot_parts;
  };
  EXPECT_EQ(load_cell_model(parse_cell_yaml(std::string(kBuiltinCell), "c.yaml")).robot_parts,
            PartSplit::kArmSegments);
  EXPECT_EQ(parts("per-link"), PartSplit::kPerLink);
  EXPECT_EQ(parts("arm-segments"), PartSplit::kArmSegments);
  EXPECT_EQ(parts("whole-robot"), PartSplit::kWholeRobot);
  EXPECT_EQ(parts("links-and-wrist"), PartSplit::kLinksAndWrist);
  EXPECT_EQ(load_cell_model(parse_cell_yaml(std::string(kBuiltinCell), "c.yaml")).ball_radius_m,
            kDefaultBallRadius_m);
  EXPECT_EQ(load_cell_model(
                parse_cell_yaml(std::string(kBuiltinCell) + "ball_radius_m: 0.04\n", "c.yaml"))
                .ball_radius_m,
            0.04);
  EXPECT_EQ(model_error_of(std::string(kBuiltinCell) + "ball_radius_m: 0.001\n"),
            "cell.yaml:11: ball_radius_m: value 0.001000, expected 0.005 to 0.5 m");
  EXPECT_NE(model_error_of(std::string(kBuiltinCell) + "ball_radius_m: .nan\n")
                .find("expected 0.005 to 0.5 m"),
            std::string::npos);
  EXPECT_EQ(model_error_of(std::string(kBuiltinCell) + "robot_parts: per-joint\n"),
            "cell.yaml:11: robot_parts: value 'per-joint', expected per-link, links-and-wrist, "
            "arm-segments or whole-robot");
  EXPECT_EQ(model_error_of(std::string(kBuiltinCell) +
                           "obstacles:\n  - {name: t, size_m: [1, -1, 1], centre_m: [0, 0, 0]}\n"),
            "cell.yaml:12: obstacles[0].size_m: value -1.000000, expected edge lengths above 0 m");
  const CellModel tuned = load_cell_model(parse_cell_yaml(
      std::string(kBuiltinCell) + "blocked_cells: {weights: {span: 3}, threshold: 10}\n",
      "c.yaml"));
  EXPECT_EQ(tuned.feature_weights.span, 3);
  EXPECT_EQ(tuned.feature_weights.average, 0);
  EXPECT_EQ(tuned.blocked_threshold, 10);
  EXPECT_EQ(model_error_of(std::string(kBuiltinCell) + "blocked_cells: {weights: {average: 0}}\n"),
            "cell.yaml:11: blocked_cells.weights: expected whole numbers 0 to 255, at least one "
            "above 0");
  EXPECT_EQ(model_error_of(std::string(kBuiltinCell) + "blocked_cells: {threshold: -1}\n"),
            "cell.yaml:11: blocked_cells.threshold: value -1, expected 0 or more");
  EXPECT_EQ(model_error_of(std::string(kBuiltinCell) + "blocked_cells: {weights: {colour: 1}}\n"),
            "cell.yaml:11: blocked_cells.weights.colour: unknown field (expected one of: average, "
            "variance, span, contrast, edge_count)");
  EXPECT_EQ(model_error_of(std::string(kBuiltinCell) + "size_m: [4, 0, 3]\n"),
            "cell.yaml:11: size_m: value 0.000000, expected inside dimensions above 0 m");
}

// Cells the programs could not serve or that protect nobody are refused when they load: cameras
// of different image sizes (the feature grid was the last camera's, and the table builds ended in
// exit 70), and a camera where none of this cell can hang (a pose file of camera-to-cell).
TEST(CellModel, CamerasOfTwoImageSizesOrOutsideTheCellAreRefused) {
  const std::string two = std::string(kBuiltinCell) +
                          "cameras:\n  - {name: a, look_at: {position_m: [2, 2, 3], target_m: [0, "
                          "0, 0], horizontal_fov_deg: 75, size_px: [704, 576]}}\n"
                          "  - {name: b, look_at: {position_m: [-2, 2, 3], target_m: [0, 0, 0], "
                          "horizontal_fov_deg: 75, size_px: [704, 576]}}\n";
  EXPECT_EQ(load_cell_model(parse_cell_yaml(two, "cell.yaml")).cameras.size(), 2u);
  EXPECT_EQ(model_error_of(replaced(two,
                                    "[-2, 2, 3], target_m: [0, 0, 0], horizontal_fov_deg: "
                                    "75, size_px: [704, 576]",
                                    "[-2, 2, 3], target_m: [0, 0, 0], horizontal_fov_deg: 75, "
                                    "size_px: [640, 480]")),
            "cell.yaml:13: cameras[1]: 'b' gives 640 x 480 px images, but 'a' gives 704 x 576 "
            "px; expected every camera of a cell to give images of one size");
  // The default cell is 4 x 4 x 3 m: 4.1 m up is above the ceiling by more than 1 m, and so is a
  // camera under the floor or 4.5 m beside the centre line.
  for (const char* place : {"[2, 2, 4.1]", "[2, 2, -0.5]", "[4.5, 0, 2]"}) {
    const std::string message = model_error_of(replaced(two, "[2, 2, 3]", place));
    EXPECT_EQ(message.rfind("cell.yaml:12: cameras[0]: 'a' has its optical centre at (", 0), 0u)
        << message;
    EXPECT_NE(message.find("camera-to-cell instead of cell-to-camera"), std::string::npos);
  }
  // Control: 0.9 m above the ceiling and 1.9 m outside a wall are places a camera may hang.
  EXPECT_EQ(
      load_cell_model(parse_cell_yaml(replaced(two, "[2, 2, 3]", "[3.9, 2, 3.9]"), "cell.yaml"))
          .cameras.size(),
      2u);
}

TEST(CellModel, ToolShapesJoinTheRobotAndItsLeverArms) {
  const std::string with_tool =
      replaced(kBuiltinCell, "tool: {frame: flange}",
               "tool: {frame: flange, point_m: [0, 0, 0.2], shapes: [{cylinder: {radius_m: 0.04, "
               "length_m: 0.2}, origin_m: [0, 0, 0.1]}]}");
  const CellModel plain = load_cell_model(parse_cell_yaml(kBuiltinCell, "cell.yaml"));
  const CellModel tooled = load_cell_model(parse_cell_yaml(with_tool, "cell.yaml"));
  // The tool tip 0.2 m past the flange: l_1 = 1.51 + 0.2 = 1.71 m (a little more for the
  // cylinder's radius and the conservative sampling).
  EXPECT_GE(tooled.lever_arms->tool_m[0], 1.71);
  EXPECT_LE(tooled.lever_arms->tool_m[0], 1.73);
  EXPECT_GT(tooled.config.joints[0].l_m.value(), plain.config.joints[0].l_m.value() + 0.18);
  EXPECT_EQ(tooled.robot->links[5].collision.size(), plain.robot->links[5].collision.size() + 1);

  EXPECT_EQ(model_error_of(
                replaced(kBuiltinCell, "tool: {frame: flange}",
                         "tool: {shapes: [{sphere: {radius_m: 0.1}, box: {size_m: [1, 1, 1]}}]}")),
            "cell.yaml:3: robot.tool.shapes[0]: expected exactly one of box, sphere, cylinder and "
            "capsule");
  EXPECT_EQ(model_error_of(replaced(kBuiltinCell, "tool: {frame: flange}",
                                    "tool: {shapes: [{sphere: {radius_m: -0.1}}]}")),
            "cell.yaml:3: robot.tool.shapes[0].sphere.radius_m: value -0.1, expected above 0");
}

TEST(CellModel, JointsMustMatchTheRobot) {
  EXPECT_EQ(model_error_of(replaced(kBuiltinCell, "  - {name: joint_6, discretised: false}\n", "")),
            "cell.yaml:5: joints: 5 joints listed, but robot 'rx130_class' has 6 movable joints "
            "(joint_1, joint_2, joint_3, joint_4, joint_5, joint_6)");
  EXPECT_EQ(model_error_of(replaced(kBuiltinCell, "{name: joint_3}", "{name: elbow}")),
            "cell.yaml:7: joints[2].name: 'elbow' is not the robot's joint 3 'joint_3' (list the "
            "joints in chain order)");
  EXPECT_EQ(
      model_error_of(replaced(kBuiltinCell, "{name: joint_2}", "{name: joint_2, l_m: 1.3}")),
      "cell.yaml:6: joints[1].l_m: given, but l_i is computed from the robot model; remove it");
  const std::string wide = model_error_of(replaced(kBuiltinCell, "[-240, 240]", "[-300, 240]"));
  EXPECT_EQ(wide.rfind("cell.yaml:8: joints[3].range_deg: value [-300", 0), 0u) << wide;
  EXPECT_NE(wide.find("outside the arm's limits"), std::string::npos) << wide;
}

TEST(CellModel, RobotsThatCannotBeLoadedAreNamed) {
  EXPECT_EQ(model_error_of(replaced(kBuiltinCell, "builtin:rx130_class", "builtin:ur5")),
            "cell.yaml:3: robot.urdf: unknown built-in robot 'builtin:ur5' (expected "
            "builtin:rx130_class)");
  const std::string missing =
      model_error_of(replaced(kBuiltinCell, "builtin:rx130_class", "/no/arm.urdf"));
  EXPECT_EQ(missing, "cell.yaml:3: robot.urdf: /no/arm.urdf: cannot be opened for reading");
  const std::string tool =
      model_error_of(replaced(kBuiltinCell, "frame: flange", "frame: gripper"));
  EXPECT_NE(tool.find("robot.tool: "), std::string::npos) << tool;
  EXPECT_NE(tool.find("'gripper'"), std::string::npos) << tool;
}

TEST(CellModel, WithoutARobotRangeAndLeverArmAreRequired) {
  EXPECT_EQ(model_error_of("name: x\nm_max_m: 0.18\njoints:\n  - {name: a, l_m: 1.0}\n"),
            "cell.yaml:4: joints[0].range_deg: missing (required without a robot)");
  EXPECT_EQ(model_error_of("name: x\nm_max_m: 0.18\njoints:\n  - {name: a, range_deg: [0, 1]}\n"),
            "cell.yaml:4: joints[0].l_m: missing (required without a robot)");
}

}  // namespace
}  // namespace safecell
