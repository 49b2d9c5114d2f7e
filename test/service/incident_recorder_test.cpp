// The incident recorder: a stop at 2 s of a 3 s run is written as a folder holding keep_s before
// it and after_s after it, whole (no partial folder left), and what it holds reads back: the
// frames through an image folder source with their times, the maps bit for bit, the joint
// stream. Without a trigger (the control) nothing is written.

#include "safecell/service/incident_recorder.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "safecell/acquisition/image_folder_source.hpp"
#include "safecell/test/scratch_folder.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

constexpr double kPeriod_s = 0.05;
constexpr int kCycles = 60;  // 3 s

// Cycle k: both cameras' images filled with k, the robot at q = 0.01 k, cell k forbidden.
void feed(IncidentRecorder& recorder, int k) {
  const double time_s = k * kPeriod_s;
  FrameSet set;
  for (const char* camera : {"cam0", "cam1"}) {
    CameraFrame frame;
    frame.camera = camera;
    frame.image = cv::Mat(12, 16, CV_8UC1, cv::Scalar(k));
    set.frames.push_back(frame);
  }
  ServiceCycle cycle;
  cycle.index = static_cast<std::uint64_t>(k);
  cycle.pose_known = true;
  cycle.q = {0.01 * k};
  cycle.known_views = 2;
  cycle.forbidden_cells = 1;
  CellSet map(1000);
  map.set(static_cast<CellIndex>(k));
  recorder.add_cycle(time_s, set, cycle, map);
  for (int i = 0; i < 5; ++i) {
    recorder.add_joint_state(
        {time_s + 0.01 * i, k < 40 ? "moving" : "stopped", 1.0, {0.01 * k}, {}});
  }
}

std::string read_all(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Whatever poll hands back and then flush: a write that fails (or ends) at once is already in
// poll's answer, so dropping that answer would lose the outcome the test looks for.
std::vector<IncidentOutcome> poll_then_flush(IncidentRecorder& recorder, double now_s) {
  std::vector<IncidentOutcome> outcomes = recorder.poll(now_s);
  std::vector<IncidentOutcome> flushed = recorder.flush();
  outcomes.insert(outcomes.end(), flushed.begin(), flushed.end());
  return outcomes;
}

TEST(IncidentRecorder, AStopIsWrittenWholeWithTheSecondsAroundIt) {
  const test::ScratchFolder folder;
  IncidentRecorder recorder({folder.path(), 1.0, 0.5, 10, {}});
  std::vector<IncidentOutcome> outcomes;
  for (int k = 0; k < kCycles; ++k) {
    feed(recorder, k);
    if (k == 40) recorder.trigger(k * kPeriod_s, "controller stopped");
    if (k == 42) recorder.trigger(k * kPeriod_s, "controller fault");  // the same incident
    const std::vector<IncidentOutcome> polled = recorder.poll(k * kPeriod_s);
    if (k < 50) {
      EXPECT_TRUE(polled.empty()) << "written before after_s had passed, at cycle " << k;
    }
    outcomes.insert(outcomes.end(), polled.begin(), polled.end());
  }
  const std::vector<IncidentOutcome> flushed = recorder.flush();  // waits for the writer
  outcomes.insert(outcomes.end(), flushed.begin(), flushed.end());
  ASSERT_EQ(outcomes.size(), 1U);
  ASSERT_EQ(outcomes[0].error, "");
  const std::optional<fs::path> written = outcomes[0].folder;
  EXPECT_EQ(recorder.incidents_written(), 1U);
  // Whole: only the finished folder is there.
  std::size_t entries = 0;
  for (const auto& entry : fs::directory_iterator(folder.path())) {
    ++entries;
    EXPECT_EQ(entry.path(), *written);
  }
  EXPECT_EQ(entries, 1U);

  const auto incident = nlohmann::json::parse(read_all(*written / "incident.json"));
  EXPECT_EQ(incident["causes"], nlohmann::json({"controller stopped", "controller fault"}));
  EXPECT_DOUBLE_EQ(incident["trigger_s"].get<double>(), 2.0);
  const auto& cycles = incident["cycles"];
  // From keep_s (1 s) before the trigger to after_s (0.5 s) after it: cycles 20..50.
  ASSERT_EQ(cycles.size(), 31U) << incident.dump(1);
  EXPECT_EQ(cycles.front()["cycle"].get<int>(), 20);
  EXPECT_EQ(cycles.back()["cycle"].get<int>(), 50);

  // The frames read back as an image folder, each at its exposure with its content.
  ImageFolderSource cam1("cam1", {16, 12}, *written / "frames" / "cam1");
  ASSERT_TRUE(cam1.opened()) << cam1.open_problem();
  ASSERT_EQ(cam1.frame_count(), 31U);
  for (int k = 20; k <= 50; ++k) {
    ASSERT_TRUE(cam1.grab().healthy());
    SourceFrame frame;
    ASSERT_TRUE(cam1.retrieve(frame).healthy());
    EXPECT_NEAR(*frame.exposure_s, k * kPeriod_s, 1e-12);
    EXPECT_EQ(frame.image.at<std::uint8_t>(5, 5), k);
  }
  // The maps bit for bit: cycle 33's has cell 33 and nothing else.
  const std::string bits = read_all(*written / "maps" / "33.bits");
  ASSERT_EQ(bits.size(), 16U * 8U);  // 1000 cells in 16 words
  for (std::size_t byte = 0; byte < bits.size(); ++byte) {
    EXPECT_EQ(static_cast<std::uint8_t>(bits[byte]), byte == 4 ? 0x02 : 0x00) << byte;
  }
  // The joint stream over the same stretch, with the stop in it.
  const std::string joints = read_all(*written / "joints.csv");
  ASSERT_EQ(joints.rfind("time_s,state,speed_scale,q_rad,velocity_rad_s\n", 0), 0U) << joints;
  // keep_s before the newest sample when the trigger came (2.04 s), give or take a sample.
  const double first_s = std::stod(joints.substr(joints.find('\n') + 1));
  EXPECT_GE(first_s, 1.0);
  EXPECT_LE(first_s, 1.05);
  EXPECT_NE(joints.find(",stopped,"), std::string::npos);
}

TEST(IncidentRecorder, NothingIsWrittenWithoutATrigger) {
  const test::ScratchFolder folder;
  IncidentRecorder recorder({folder.path(), 1.0, 0.5, 10, {}});
  for (int k = 0; k < kCycles; ++k) {
    feed(recorder, k);
    EXPECT_TRUE(recorder.poll(k * kPeriod_s).empty());
  }
  EXPECT_TRUE(recorder.flush().empty());
  EXPECT_TRUE(fs::is_empty(folder.path()));
}

// A disk that refuses the folder: the incident is dropped with an error the service logs, no
// partial folder stays, and the next incident is written once the disk takes it again.
TEST(IncidentRecorder, AFolderThatCannotBeWrittenDropsTheIncidentOnly) {
  const test::ScratchFolder folder;
  const fs::path blocked = folder.path() / "incidents";
  std::ofstream(blocked) << "a file where the folder should be";
  IncidentRecorder recorder({blocked, 1.0, 0.2, 10, {}});
  for (int k = 0; k < 20; ++k) feed(recorder, k);
  recorder.trigger(19 * kPeriod_s, "controller stopped");
  std::vector<IncidentOutcome> outcomes = poll_then_flush(recorder, 2.0);
  ASSERT_EQ(outcomes.size(), 1U);
  EXPECT_TRUE(outcomes[0].folder.empty());
  EXPECT_NE(outcomes[0].error.find("not written"), std::string::npos) << outcomes[0].error;
  EXPECT_EQ(recorder.incidents_written(), 0U);
  EXPECT_EQ(recorder.incidents_not_written(), 1U) << "the run must be able to say so";
  EXPECT_TRUE(recorder.poll(2.0).empty()) << "the failed incident is dropped, not retried";
  EXPECT_TRUE(recorder.flush().empty());

  fs::remove(blocked);
  fs::create_directories(blocked);
  for (int k = 20; k < 40; ++k) feed(recorder, k);
  recorder.trigger(39 * kPeriod_s, "controller fault");
  outcomes = poll_then_flush(recorder, 3.0);
  ASSERT_EQ(outcomes.size(), 1U);
  ASSERT_EQ(outcomes[0].error, "");
  EXPECT_TRUE(fs::exists(outcomes[0].folder / "incident.json"));
  EXPECT_EQ(recorder.incidents_written(), 1U);
  EXPECT_EQ(recorder.incidents_not_written(), 1U);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(blocked)) ++entries;
  EXPECT_EQ(entries, 1U) << "a partial folder was left behind";
}

TEST(IncidentRecorder, AbsurdSettingsAreRefused) {
  EXPECT_THROW(IncidentRecorder({"", 1.0, 0.5, 10, {}}), std::invalid_argument);
  EXPECT_THROW(IncidentRecorder({"x", 0.0, 0.5, 10, {}}), std::invalid_argument);
  EXPECT_THROW(IncidentRecorder({"x", 1.0, -1.0, 10, {}}), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
