// An incident folder read back as the recorder wrote it: the setup, every cycle with each
// camera's exposure and view (a camera that delivered nothing, a health fault), the frames as a
// frame set, the maps bit for bit, the joint stream. And what a damaged folder gives: an error
// naming the file and the field, never a silent wrong answer.

#include "safecell/service/incident_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "safecell/files/atomic_write.hpp"
#include "safecell/service/incident_recorder.hpp"
#include "safecell/test/scratch_folder.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

constexpr double kPeriod_s = 0.05;

IncidentSetup test_setup() {
  IncidentSetup setup;
  setup.cell_file = "/cells/test.yaml";
  setup.cell_text = "cell: test\n";
  setup.grid_fingerprint = 0x1234abcdULL;
  setup.lut_fingerprint = 0xfeedULL;
  setup.sync_error_s = 0.004;
  setup.reference = {cv::Mat(12, 16, CV_8UC1, cv::Scalar(7)),
                     cv::Mat(12, 16, CV_8UC1, cv::Scalar(9))};
  return setup;
}

// Cycle k at k * period: cam0 exposed 1 ms early, cam1 1 ms late; cam1 delivers nothing in
// cycle 12 and is frozen in cycle 13; the map has cell k; the pose is unknown in cycle 14.
void feed(IncidentRecorder& recorder, int k) {
  const double time_s = k * kPeriod_s;
  FrameSet set;
  for (int c = 0; c < 2; ++c) {
    CameraFrame frame;
    frame.camera = c == 0 ? "cam0" : "cam1";
    frame.exposure_s = 100.0 + time_s + (c == 0 ? -0.001 : 0.001);  // another clock
    if (!(c == 1 && k == 12)) frame.image = cv::Mat(12, 16, CV_8UC1, cv::Scalar(k + c));
    if (c == 1 && k == 12) frame.view = camera_fault_report("cam1", CameraFault::kStopped, "none");
    if (c == 1 && k == 13) frame.view = camera_fault_report("cam1", CameraFault::kFrozen, "same");
    set.frames.push_back(frame);
  }
  ServiceCycle cycle;
  cycle.index = static_cast<std::uint64_t>(k);
  cycle.pose_known = k != 14;
  if (cycle.pose_known) cycle.q = {0.01 * k, -0.02 * k};
  cycle.all_forbidden = cycle.pose_known ? "" : "robot pose unknown: test";
  cycle.known_views = static_cast<std::uint32_t>(set.known_count());
  CellSet map(1000);
  map.set(static_cast<CellIndex>(k));
  cycle.forbidden_cells = map.count();
  recorder.add_cycle(time_s, set, cycle, map);
  recorder.add_joint_state(
      {time_s, k < 15 ? "moving" : "stopped", 0.5, {0.01 * k, 0.0}, {1.0, -2.0}});
}

fs::path record_incident(const fs::path& folder) {
  IncidentRecorder recorder({folder, 0.5, 0.2, 10, test_setup()});
  for (int k = 0; k <= 20; ++k) {
    feed(recorder, k);
    if (k == 15) recorder.trigger(k * kPeriod_s, "controller stopped");
  }
  // flush hands the incident over and waits for it (a poll could already return the outcome).
  const std::vector<IncidentOutcome> outcomes = recorder.flush();
  if (outcomes.size() != 1 || !outcomes[0].error.empty()) {
    throw std::logic_error("no incident written");
  }
  return outcomes[0].folder;
}

TEST(IncidentFolder, ReadsBackWhatTheRecorderWrote) {
  const test::ScratchFolder folder;
  const fs::path written = record_incident(folder.path());
  const Incident incident = read_incident(written);
  EXPECT_EQ(incident.causes, std::vector<std::string>{"controller stopped"});
  EXPECT_DOUBLE_EQ(incident.trigger_s, 15 * kPeriod_s);
  EXPECT_EQ(incident.setup.cell_file, fs::path("/cells/test.yaml"));
  EXPECT_EQ(incident.setup.cell_text, "cell: test\n");
  EXPECT_EQ(incident.setup.grid_fingerprint, 0x1234abcdULL);
  EXPECT_EQ(incident.setup.lut_fingerprint, 0xfeedULL);
  EXPECT_DOUBLE_EQ(incident.setup.sync_error_s, 0.004);
  EXPECT_EQ(incident.cameras, (std::vector<std::string>{"cam0", "cam1"}));
  // 0.5 s before the trigger (cycle 5) to 0.2 s after it (cycle 19; polled at 20 after adding).
  ASSERT_FALSE(incident.cycles.empty());
  EXPECT_EQ(incident.cycles.front().index, 5U);
  EXPECT_EQ(incident.cycles.back().index, 20U);
  for (const IncidentCycle& cycle : incident.cycles) {
    const auto k = static_cast<int>(cycle.index);
    SCOPED_TRACE("cycle " + std::to_string(k));
    EXPECT_NEAR(cycle.exposure_s, k * kPeriod_s, 1e-12);
    EXPECT_EQ(cycle.pose_known, k != 14);
    if (k != 14) {
      EXPECT_EQ(cycle.q, (std::vector<double>{0.01 * k, -0.02 * k}));
    } else {
      EXPECT_EQ(cycle.all_forbidden, "robot pose unknown: test");
    }
    ASSERT_EQ(cycle.views.size(), 2U);
    // Each camera's exposure on the incident's seconds, its offset from the median of the known
    // views kept (with cam1 unknown in cycles 12 and 13, cam0 is the median).
    const bool cam1_known = k != 12 && k != 13;
    EXPECT_NEAR(*cycle.views[0].exposure_s, k * kPeriod_s - (cam1_known ? 0.001 : 0.0), 1e-9);
    if (k == 13) {
      EXPECT_NEAR(*cycle.views[1].exposure_s, k * kPeriod_s + 0.002, 1e-9);
    }
    EXPECT_EQ(cycle.views[1].exposure_s.has_value(), k != 12);
    EXPECT_EQ(cycle.views[1].fault, k == 12   ? CameraFault::kStopped
                                    : k == 13 ? CameraFault::kFrozen
                                              : CameraFault::kNone);

    const FrameSet frames = incident_frame_set(written, incident, cycle);
    ASSERT_EQ(frames.frames.size(), 2U);
    EXPECT_EQ(frames.frames[0].image.at<std::uint8_t>(3, 3), k);
    EXPECT_EQ(frames.known_count(), k == 12 || k == 13 ? 1U : 2U);
    if (k == 13) {
      EXPECT_EQ(frames.frames[1].image.at<std::uint8_t>(3, 3), k + 1);  // kept
    }
    if (k == 12) {
      EXPECT_TRUE(frames.frames[1].image.empty());
    }

    const CellSet map = read_incident_map(written, cycle, 1000);
    EXPECT_EQ(map.count(), 1U);
    EXPECT_TRUE(map.test(static_cast<CellIndex>(k)));
  }
  ASSERT_FALSE(incident.joints.empty());
  EXPECT_EQ(incident.joints.back().state, "stopped");
  EXPECT_EQ(incident.joints.back().velocity, (std::vector<double>{1.0, -2.0}));
  EXPECT_TRUE(fs::exists(written / "reference" / "cam1.png"));
}

std::string read_all(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs read_incident on a copy of `written` with `damage` done to it; the error's text.
std::string damaged(const fs::path& written, const std::function<void(const fs::path&)>& damage) {
  const fs::path copy = written.parent_path() / "damaged";
  fs::remove_all(copy);
  fs::copy(written, copy, fs::copy_options::recursive);
  damage(copy);
  try {
    const Incident incident = read_incident(copy);
    for (const IncidentCycle& cycle : incident.cycles) {
      (void)incident_frame_set(copy, incident, cycle);
      (void)read_incident_map(copy, cycle, 1000);
    }
  } catch (const FileError& error) {
    return error.what();
  }
  return "no error";
}

void edit_json(const fs::path& folder, const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json incident = nlohmann::json::parse(read_all(folder / "incident.json"));
  edit(incident);
  std::ofstream(folder / "incident.json") << incident.dump();
}

TEST(IncidentFolder, DamageIsNamedByFileAndField) {
  const test::ScratchFolder folder;
  const fs::path written = record_incident(folder.path());
  EXPECT_EQ(damaged(written, [](const fs::path&) {}), "no error");  // the control

  EXPECT_NE(damaged(written, [](const fs::path& f) { fs::remove(f / "incident.json"); })
                .find("incident.json: cannot be read"),
            std::string::npos);
  EXPECT_NE(damaged(written,
                    [](const fs::path& f) { std::ofstream(f / "incident.json") << "{\"format\":"; })
                .find("is not JSON"),
            std::string::npos);
  EXPECT_NE(damaged(written,
                    [](const fs::path& f) {
                      edit_json(f, [](nlohmann::json& j) { j["format"] = "safecell incident 9"; });
                    })
                .find("field 'format' is \"safecell incident 9\""),
            std::string::npos);
  EXPECT_NE(damaged(written,
                    [](const fs::path& f) {
                      edit_json(f, [](nlohmann::json& j) { j["cycles"][3]["q_rad"] = "north"; });
                    })
                .find("field 'cycles[3].q_rad' is not a list"),
            std::string::npos);
  EXPECT_NE(damaged(written,
                    [](const fs::path& f) {
                      edit_json(f, [](nlohmann::json& j) {
                        j["cycles"][2]["views"][1]["fault"] = "odd";
                      });
                    })
                .find("field 'cycles[2].views[1].fault' is \"odd\""),
            std::string::npos);
  EXPECT_NE(damaged(written,
                    [](const fs::path& f) {
                      edit_json(f,
                                [](nlohmann::json& j) { j["setup"]["lut_fingerprint"] = "xyz"; });
                    })
                .find("field 'setup.lut_fingerprint' is \"xyz\""),
            std::string::npos);
  EXPECT_NE(damaged(written, [](const fs::path& f) { fs::remove(f / "frames" / "cam0" / "9.png"); })
                .find("9.png: missing"),
            std::string::npos);
  EXPECT_NE(
      damaged(written, [](const fs::path& f) { std::ofstream(f / "maps" / "7.bits") << "short"; })
          .find("7.bits: 5 bytes, expected 128"),
      std::string::npos);
  EXPECT_NE(damaged(written,
                    [](const fs::path& f) {
                      std::ofstream(f / "joints.csv", std::ios::app) << "1.5,moving,one,0 0\n";
                    })
                .find("\"one\" is not a number"),
            std::string::npos);
}

}  // namespace
}  // namespace safecell
