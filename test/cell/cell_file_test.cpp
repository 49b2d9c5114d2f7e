#include "safecell/cell/cell_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cell_errors.hpp"
#include "safecell/cell/cell_error.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/cell/entry_zones.hpp"

namespace safecell {
namespace {

constexpr const char* kTwoJoints = R"(name: two joints
m_max_m: 0.2
joints:
  - name: a
    range_deg: [-90, 90]
    l_m: 1.0
  - name: b
    range_deg: [0, 45.5]
    l_m: 0.5
    discretised: false
)";

// The message of the CellError that parsing `text` raises.
std::string error_of(const std::string& text) {
  return test::cell_error_of([&] { static_cast<void>(parse_cell_yaml(text, "bad.yaml")); });
}

TEST(CellFile, ReadsEveryField) {
  const CellConfig cell = parse_cell_yaml(kTwoJoints, "two.yaml");
  EXPECT_EQ(cell.name, "two joints");
  EXPECT_EQ(cell.source, "two.yaml");
  EXPECT_EQ(cell.m_max_m, 0.2);
  ASSERT_EQ(cell.joints.size(), 2u);
  EXPECT_EQ(cell.joints[0].name, "a");
  EXPECT_EQ(cell.joints[0].range_deg.value()[0], -90.0);
  EXPECT_EQ(cell.joints[0].range_deg.value()[1], 90.0);
  EXPECT_EQ(cell.joints[0].l_m, 1.0);
  EXPECT_TRUE(cell.joints[0].discretised);
  EXPECT_EQ(cell.joints[1].range_deg.value()[1], 45.5);
  EXPECT_FALSE(cell.robot.has_value());
  EXPECT_FALSE(cell.joints[1].discretised);
  EXPECT_EQ(cell.joints[1].l_at.line, 9);
}

TEST(CellFile, TheDefaultCellIsTheShippedYaml) {
  const CellConfig cell = default_cell();
  EXPECT_EQ(cell.source, kDefaultCellSource);
  EXPECT_EQ(cell.m_max_m, 0.18);
  ASSERT_EQ(cell.joints.size(), 6u);
  ASSERT_TRUE(cell.robot.has_value());
  EXPECT_EQ(cell.robot->urdf, "builtin:rx130_class");
  EXPECT_TRUE(cell.joints[3].discretised);
  EXPECT_FALSE(cell.joints[4].discretised);
  EXPECT_NE(default_cell_yaml().find("RX130"), std::string_view::npos);
}

TEST(CellFile, BlindSpotsAreForbiddenUnlessTheCellAllowsThem) {
  EXPECT_TRUE(parse_cell_yaml(kTwoJoints, "two.yaml").forbid_blind_spots);
  EXPECT_TRUE(default_cell().forbid_blind_spots);
  EXPECT_FALSE(parse_cell_yaml(std::string(kTwoJoints) + "blind_spots: allow\n", "two.yaml")
                   .forbid_blind_spots);
  EXPECT_TRUE(parse_cell_yaml(std::string(kTwoJoints) + "blind_spots: forbid\n", "two.yaml")
                  .forbid_blind_spots);
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "blind_spots: ignore\n"),
            "bad.yaml:11: blind_spots: value 'ignore', expected forbid or allow");
}

TEST(CellFile, EntriesAndTheirSeparation) {
  const CellConfig open = parse_cell_yaml(kTwoJoints, "two.yaml");
  EXPECT_FALSE(open.entries.has_value());
  EXPECT_EQ(open.entry_separation.approach_speed_m_s, 1.6);
  const CellConfig fenced = parse_cell_yaml(std::string(kTwoJoints) +
                                                "entries:\n"
                                                "  - {name: door, wall: +y, span_m: [-1, 0.5]}\n"
                                                "entry_separation: {stopping_s: 0.5}\n",
                                            "two.yaml");
  ASSERT_TRUE(fenced.entries.has_value());
  ASSERT_EQ(fenced.entries->size(), 1U);
  EXPECT_EQ(fenced.entries->front().name, "door");
  EXPECT_EQ(fenced.entries->front().wall, CellWall::kPlusY);
  EXPECT_EQ(fenced.entries->front().span_m[1], 0.5);
  EXPECT_EQ(fenced.entry_separation.stopping_s, 0.5);
  EXPECT_EQ(fenced.entry_separation.response_s, 0.1);
  ASSERT_TRUE(default_cell().entries.has_value());

  const auto entry = [](const std::string& item) {
    return error_of(std::string(kTwoJoints) + "entries:\n  - " + item + "\n");
  };
  EXPECT_EQ(entry("{name: door, wall: up, span_m: [0, 1]}"),
            "bad.yaml:12: entries[0].wall: value 'up', expected -x, +x, -y or +y");
  EXPECT_EQ(entry("{name: door, wall: -x, span_m: [1, 0]}"),
            "bad.yaml:12: entries[0].span_m: value [1, 0], expected [from, to] with -2 <= from < "
            "to <= 2 (the wall's extent in metres)");
  EXPECT_EQ(entry("{name: door, wall: -x, span_m: [1, 2.5]}"),
            "bad.yaml:12: entries[0].span_m: value [1, 2.5], expected [from, to] with -2 <= from "
            "< to <= 2 (the wall's extent in metres)");
  EXPECT_EQ(entry("{name: door, span_m: [0, 1]}"),
            "bad.yaml:12: entries[0].wall: missing (required)");
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "entries: []\n"),
            "bad.yaml:11: entries: an empty list, expected at least one entry (leave the field "
            "out when the cell does not say where people come in)");
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "entry_separation: {response_s: -1}\n"),
            "bad.yaml:11: entry_separation.response_s: value -1, expected 0.01 .. 2 s");
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "entry_separation: {stopping_s: 0}\n"),
            "bad.yaml:11: entry_separation.stopping_s: value 0, expected 0.05 .. 5 s (measure it "
            "on the robot)");
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "entry_separation: {approach_speed_m_s: 1.2}\n"),
            "bad.yaml:11: entry_separation.approach_speed_m_s: value 1.2, expected 1.6 .. 3 m/s "
            "(ISO 13855: 1.6 m/s walking, 2 m/s reaching)");
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "entry_separation: {speed: 1}\n"),
            "bad.yaml:11: entry_separation.speed: unknown field (expected one of: "
            "approach_speed_m_s, response_s, stopping_s, intrusion_m)");
  // A key given twice would have its later line ignored.
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "camera_threshold: 1\ncamera_threshold: 2\n"),
            "bad.yaml:12: camera_threshold: given twice (first on line 11)");
  EXPECT_EQ(
      error_of(std::string(kTwoJoints) + "entry_separation: {response_s: 0.1, response_s: 0.2}\n"),
      "bad.yaml:11: entry_separation.response_s: given twice (first on line 11)");
}

TEST(CellFile, TheProtectiveSeparationIsOnUnlessTheCellTurnsItOff) {
  const CellConfig unset = parse_cell_yaml(kTwoJoints, "two.yaml");
  ASSERT_TRUE(unset.protective_separation.has_value());
  EXPECT_EQ(unset.protective_separation->intrusion_m, 0.0);
  EXPECT_NEAR(separation_distance_m(*unset.protective_separation), 1.6 * (0.1 + 0.3), 1e-12);
  ASSERT_TRUE(default_cell().protective_separation.has_value());
  EXPECT_FALSE(parse_cell_yaml(std::string(kTwoJoints) + "protective_separation: off\n", "two.yaml")
                   .protective_separation.has_value());
  const CellConfig slow = parse_cell_yaml(
      std::string(kTwoJoints) + "protective_separation: {stopping_s: 0.2}\n", "two.yaml");
  ASSERT_TRUE(slow.protective_separation.has_value());
  EXPECT_EQ(slow.protective_separation->stopping_s, 0.2);
  EXPECT_EQ(slow.protective_separation->intrusion_m, 0.0);

  EXPECT_EQ(error_of(std::string(kTwoJoints) + "protective_separation: on\n"),
            "bad.yaml:11: protective_separation: value 'on', expected off or a mapping of "
            "approach_speed_m_s, response_s, stopping_s, intrusion_m, reduced_speeds");
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "protective_separation: {stopping_s: 0.5}\n"),
            "bad.yaml:11: protective_separation: a separation distance of 0.96 m, expected at "
            "most 0.95 m (the robot would stop for anyone in most of the cell)");
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "protective_separation: {response_s: 0}\n"),
            "bad.yaml:11: protective_separation.response_s: value 0, expected 0.01 .. 2 s");
}

TEST(CellFile, TheProtectiveSeparationsReducedSpeeds) {
  EXPECT_EQ(parse_cell_yaml(kTwoJoints, "two.yaml").protective_reduced_speeds,
            (std::vector<double>{0.5, 0.25}));
  EXPECT_EQ(parse_cell_yaml(std::string(kTwoJoints) +
                                "protective_separation: {reduced_speeds: [0.6, 0.3, 0.1]}\n",
                            "two.yaml")
                .protective_reduced_speeds,
            (std::vector<double>{0.6, 0.3, 0.1}));
  EXPECT_TRUE(
      parse_cell_yaml(std::string(kTwoJoints) + "protective_separation: {reduced_speeds: []}\n",
                      "two.yaml")
          .protective_reduced_speeds.empty());
  EXPECT_EQ(
      error_of(std::string(kTwoJoints) + "protective_separation: {reduced_speeds: [0.3, 0.5]}\n"),
      "bad.yaml:11: protective_separation.reduced_speeds[1]: value 0.5, expected less than "
      "the speed before it");
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "protective_separation: {reduced_speeds: [1]}\n"),
            "bad.yaml:11: protective_separation.reduced_speeds[0]: value 1, expected 0.05 .. 0.95 "
            "(a fraction of the top speed)");
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "protective_separation: {reduced_speeds: 0.5}\n"),
            "bad.yaml:11: protective_separation.reduced_speeds: expected a list of at most 4 "
            "speeds (fractions of the top speed), got '0.5'");
  EXPECT_EQ(error_of(std::string(kTwoJoints) + "entry_separation: {reduced_speeds: [0.5]}\n"),
            "bad.yaml:11: entry_separation.reduced_speeds: unknown field (expected one of: "
            "approach_speed_m_s, response_s, stopping_s, intrusion_m)");
}

TEST(CellFile, CameraSources) {
  const auto camera = [](const std::string& source) {
    return std::string(kTwoJoints) +
           "cameras:\n  - name: cam0\n    calibration: cam0.yaml\n    source: " + source + "\n";
  };
  const auto source_of = [&](const std::string& source) {
    return parse_cell_yaml(camera(source), "/cells/two.yaml", "/cells")
        .cameras.at(0)
        .source.value();
  };
  using Kind = CameraSourceConfig::Kind;
  EXPECT_EQ(source_of("{device: 2}").kind, Kind::kDevice);
  EXPECT_EQ(source_of("{device: 2}").spec, "2");
  EXPECT_EQ(source_of("{video: runs/cam0.mp4}").spec, "/cells/runs/cam0.mp4");
  EXPECT_EQ(source_of("{folder: frames/cam0}").kind, Kind::kImageFolder);
  EXPECT_EQ(source_of("{folder: /data/cam0}").spec, "/data/cam0");
  EXPECT_EQ(source_of("{gstreamer: 'v4l2src ! videoconvert ! appsink'}").kind, Kind::kGstreamer);
  EXPECT_EQ(source_of("{url: 'rtsp://10.0.0.5/stream1'}").kind, Kind::kStream);
  EXPECT_EQ(source_of("{video: '0'}").kind, Kind::kVideoFile);
  EXPECT_EQ(source_of("{video: '0'}").spec, "/cells/0");

  EXPECT_EQ(error_of(camera("{device: 0, video: a.mp4}")),
            "bad.yaml:14: cameras[0].source: expected exactly one of device, video, folder, "
            "gstreamer, url");
  EXPECT_EQ(error_of(camera("{device: -1}")),
            "bad.yaml:14: cameras[0].source.device: value -1, expected a device index 0 .. 99999");
  EXPECT_EQ(error_of(camera("{gstreamer: v4l2src}")),
            "bad.yaml:14: cameras[0].source.gstreamer: value 'v4l2src', expected a GStreamer "
            "pipeline of elements joined by '!' ending in an appsink");
  EXPECT_EQ(error_of(camera("{url: camera-3}")),
            "bad.yaml:14: cameras[0].source.url: value 'camera-3', expected a URL such as "
            "rtsp://host/stream");
  EXPECT_EQ(error_of(camera("{usb: 0}")),
            "bad.yaml:14: cameras[0].source.usb: unknown field (expected one of: device, video, "
            "folder, gstreamer, url)");
}

TEST(CellFile, MissingFieldIsNamed) {
  std::string text = kTwoJoints;
  text.replace(text.find("m_max_m: 0.2\n"), 13, "");
  EXPECT_EQ(error_of(text), "bad.yaml:1: m_max_m: missing (required)");
  text = kTwoJoints;
  text.replace(text.find("  - name: b\n    range_deg"), 25, "  - range_deg");
  EXPECT_EQ(error_of(text), "bad.yaml:7: joints[1].name: missing (required)");
}

TEST(CellFile, UnknownFieldIsNamedWithTheExpectedOnes) {
  std::string text = kTwoJoints;
  text.replace(text.find("l_m: 1.0"), 8, "lm: 1.0");
  EXPECT_EQ(error_of(text),
            "bad.yaml:6: joints[0].lm: unknown field (expected one of: name, range_deg, l_m, "
            "discretised)");
}

TEST(CellFile, WrongTypesAreNamedWithTheValue) {
  std::string text = kTwoJoints;
  text.replace(text.find("0.2"), 3, "fast");
  EXPECT_EQ(error_of(text), "bad.yaml:2: m_max_m: expected a number, got 'fast'");
  text = kTwoJoints;
  text.replace(text.find("[-90, 90]"), 9, "[-90]");
  EXPECT_EQ(error_of(text),
            "bad.yaml:5: joints[0].range_deg: expected [lower, upper] in degrees, got a list");
  text = kTwoJoints;
  text.replace(text.find("false"), 5, "maybe");
  EXPECT_EQ(error_of(text),
            "bad.yaml:10: joints[1].discretised: expected true or false, got 'maybe'");
  EXPECT_EQ(error_of("- just\n- a list\n"),
            "bad.yaml:1: (file): expected a mapping of cell fields, got a list");
}

TEST(CellFile, MalformedYamlNamesTheLine) {
  const std::string message = error_of("name: x\nm_max_m: [0.2\njoints: []\n");
  EXPECT_EQ(message.rfind("bad.yaml:", 0), 0u) << message;
  EXPECT_NE(message.find("not valid YAML"), std::string::npos) << message;
}

TEST(CellFile, UnreadableFilesAreNamed) {
  const auto missing = std::filesystem::temp_directory_path() / "safecell-no-such-cell.yaml";
  try {
    static_cast<void>(load_cell_file(missing));
    FAIL() << "no error";
  } catch (const CellError& error) {
    EXPECT_EQ(std::string(error.what()),
              missing.string() + ": (file): cannot be opened for reading");
  }
  EXPECT_THROW(static_cast<void>(load_cell_file(std::filesystem::temp_directory_path())),
               CellError);
}

TEST(CellFile, RobotSectionAndRelativeUrdfPaths) {
  const CellConfig cell = parse_cell_yaml(
      "name: r\nm_max_m: 0.18\nrobot:\n  urdf: robots/arm.urdf\n  tool_link: tip\n"
      "  tool: {frame: flange, point_m: [0, 0, 0.2]}\njoints: []\n",
      "/cells/r.yaml", "/cells");
  ASSERT_TRUE(cell.robot.has_value());
  EXPECT_EQ(cell.robot->urdf, "/cells/robots/arm.urdf");
  EXPECT_EQ(cell.robot->tool_link, "tip");
  EXPECT_EQ(cell.robot->tool_frame, "flange");
  EXPECT_EQ(cell.robot->tool_point_m[2], 0.2);
  EXPECT_EQ(cell.robot->at.line, 4);
  EXPECT_EQ(error_of("name: r\nm_max_m: 0.18\nrobot: {urdf: a.urdf, tool: {point_m: [1, 2]}}\n"
                     "joints: []\n"),
            "bad.yaml:3: robot.tool.point_m: expected [x, y, z] in metres, got a list");
  EXPECT_EQ(error_of("name: r\nm_max_m: 0.18\nrobot: {path: a.urdf}\njoints: []\n"),
            "bad.yaml:3: robot.path: unknown field (expected one of: urdf, tool_link, tool, "
            "collision_stand_ins)");
}

TEST(CellFile, LoadsFromDisk) {
  const auto path = std::filesystem::temp_directory_path() / "safecell-cell-file-test.yaml";
  std::ofstream(path) << kTwoJoints;
  EXPECT_EQ(load_cell_file(path).joints.size(), 2u);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace safecell
