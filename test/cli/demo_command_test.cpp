// `safecell demo`: the closed loop of two processes on loopback UDP, in real time, on the coarse
// cell. The report must be whole (every picture index.html names exists), the controller must
// have run the real protocol (its joint stream arrived, carrying the maps it applied), and the
// ground truth's figures must be the safe ones. index.html is loaded in headless Chromium: every
// picture must load (and one taken away must be named).

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "coarse_cell.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every value that follows `opening` up to the next quote (the page's own markup: no regex, which
// GCC 12 warns about under the sanitizers).
std::vector<std::string> attribute_values(const std::string& page, const std::string& opening) {
  std::vector<std::string> values;
  for (std::size_t at = page.find(opening); at != std::string::npos;
       at = page.find(opening, at + 1)) {
    const std::size_t begin = at + opening.size();
    const std::size_t end = page.find('"', begin);
    if (end != std::string::npos) values.push_back(page.substr(begin, end - begin));
  }
  return values;
}

// The page as headless Chromium renders it once loaded (its DOM), or "" without Chromium.
std::string rendered_in_chromium(const fs::path& page) {
#ifdef SAFECELL_CHROMIUM
  const std::string command = std::string("\"") + SAFECELL_CHROMIUM +
                              "\" --headless --no-sandbox --disable-gpu "
                              "--allow-file-access-from-files --virtual-time-budget=10000 "
                              "--dump-dom \"file://" +
                              fs::absolute(page).string() + "\" 2>/dev/null";
  std::string dom;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    char chunk[4096];
    for (std::size_t n; (n = std::fread(chunk, 1, sizeof chunk, pipe)) > 0;) dom.append(chunk, n);
    (void)::pclose(pipe);
  }
  return dom;
#else
  (void)page;
  return "";
#endif
}

// What the page's own script found: "N of M" pictures loaded.
std::string pictures_loaded(const std::string& dom) {
  const std::vector<std::string> values = attribute_values(dom, "data-pictures-loaded=\"");
  return values.empty() ? "(not marked)" : values.front();
}

// index.html in a browser: every picture loads. The negative control: the same folder with one
// picture taken away must be marked, and the page must name it.
void expect_pictures_load_in_chromium(const fs::path& report, const fs::path& scratch,
                                      std::size_t pictures) {
#ifndef SAFECELL_CHROMIUM
  GTEST_SKIP() << "Chromium not found at configure time (.ci/install-deps installs it)";
#endif
  const std::string dom = rendered_in_chromium(report / "index.html");
  const std::string all = std::to_string(pictures) + " of " + std::to_string(pictures);
  EXPECT_EQ(pictures_loaded(dom), all) << dom.substr(0, 2000);
  const fs::path copy = scratch / "report-without-a-picture";
  fs::copy(report, copy, fs::copy_options::recursive);
  const std::string first = attribute_values(read_text(copy / "index.html"), "<img src=\"").front();
  fs::remove(copy / first);
  const std::string broken = rendered_in_chromium(copy / "index.html");
  EXPECT_EQ(pictures_loaded(broken),
            std::to_string(pictures - 1) + " of " + std::to_string(pictures));
  EXPECT_NE(broken.find("Pictures that did not load: " + first), std::string::npos)
      << broken.substr(0, 2000);
}

TEST(DemoCommand, TheClosedLoopRunsAndWritesTheReport) {
  const test::ScratchFolder scratch("safecell-demo");
  const fs::path cell = test::write_coarse_cell(scratch.path());
  const fs::path out = scratch.path() / "report";
  const auto run = test::safecell_cli({"demo", "--cell", cell.string(), "--seconds", "15", "--fps",
                                       "10", "--out", out.string(), "--lut-cache",
                                       (scratch.path() / "cache").string(), "--views-every", "3"});
  ASSERT_EQ(run.exit_code, 0) << run.err << "\n" << read_text(out / "controller.log");
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  for (const char* field :
       {"cycles", "stops", "slowdowns", "min_human_distance_m", "contacts_while_moving",
        "contacts_with_stopped_robot", "task_completed", "task_time_s",
        "task_time_without_people_s", "e2e_latency_p50_ms", "e2e_latency_p99_ms", "fusion_ms_p99",
        "missed", "frames_skipped", "faults", "faults_acknowledged"}) {
    EXPECT_TRUE(summary.contains(field)) << field;
  }
  EXPECT_EQ(summary["contacts_while_moving"].get<int>(), 0);
  EXPECT_EQ(summary["missed"].get<int>(), 0);
  EXPECT_GT(summary["configs_checked"].get<int>(), 0);
  // The controller ran as its own process and spoke the protocol: its joint stream came back with
  // the versions of the maps it applied, and it exited cleanly on the stop request.
  EXPECT_GT(summary["controller_cycles"].get<int>(), 1000);
  EXPECT_GT(summary["e2e_latency_p50_ms"].get<double>(), 0.0);
  EXPECT_EQ(summary["controller_exit_code"].get<int>(), 0);
  EXPECT_NE(read_text(out / "controller.log").find("listening on 127.0.0.1"), std::string::npos);
  // The person came in and was noticed: the robot slowed or stopped at least once (or was held
  // by a fault: on a loaded machine a late cycle may come first).
  EXPECT_GE(
      summary["stops"].get<int>() + summary["slowdowns"].get<int>() + summary["faults"].get<int>(),
      1);
  EXPECT_LT(summary["min_human_distance_m"].get<double>(), 2.0);
  // With the person within 1 m of the arm, the share of the C-space the map left free, and the
  // share the maps sent left free (the protective separation forbids a map whole), both shares.
  for (const char* share : {"near_person_map_free_share", "near_person_sent_free_share"}) {
    ASSERT_TRUE(summary.contains(share)) << share;
    EXPECT_GE(summary[share].get<double>(), 0.0) << share;
    EXPECT_LE(summary[share].get<double>(), 1.0) << share;
  }
  EXPECT_LE(summary["near_person_sent_free_share"].get<double>(),
            summary["near_person_map_free_share"].get<double>());
  EXPECT_LE(summary["near_person_separation_frames"].get<int>(),
            summary["near_person_frames"].get<int>());
  // Every slow-down or stop for a forbidden cell in the robot's way was explained with the map the
  // controller held, and that map did forbid the cell: never "not forbidden" (controller and
  // coprocessor would disagree on the cell) nor "no longer kept" (the views were lost).
  // A slow-down may also be the protective separation's speed limit, which names no cell; on a
  // loaded machine (under the sanitizers) late maps make the controller fault for most of the
  // run and the slow-downs left are the separation's. Without faults the person's cells come in
  // the robot's way.
  const auto& explanations = summary["stop_explanations"];
  if (summary["slowdowns"].get<int>() > 0 && summary["faults"].get<int>() == 0) {
    EXPECT_GE(explanations.size(), 1U) << run.err;
  }
  for (const auto& stop : explanations) {
    const std::string text = stop["text"].get<std::string>();
    EXPECT_EQ(text.find("not forbidden"), std::string::npos) << text;
    EXPECT_EQ(text.find("no longer kept"), std::string::npos) << text;
    EXPECT_NE(text.find("cell "), std::string::npos) << text;
  }

  const std::string page = read_text(out / "index.html");
  const std::vector<std::string> images = attribute_values(page, "<img src=\"");
  for (const std::string& image : images) EXPECT_TRUE(fs::exists(out / image)) << image;
  EXPECT_GE(images.size(), 4U);
  expect_pictures_load_in_chromium(out, scratch.path(), images.size());
  // The film of the run, where this OpenCV can write one, is there and not empty.
  for (const std::string& film : attribute_values(page, "<video src=\"")) {
    EXPECT_GT(fs::file_size(out / film), 1000U) << film;
  }
  EXPECT_NE(page.find("timeline.png"), std::string::npos);
  EXPECT_NE(run.out.find("contacts while moving 0"), std::string::npos) << run.out;

  // The demo records incidents as safecell run does (the stop at the end at least), and each
  // replays offline to the maps the service sent, bit for bit.
  ASSERT_TRUE(fs::exists(out / "incidents")) << run.err;
  std::size_t incidents = 0;
  std::size_t ran_again = 0;  // cycles the pipeline ran on again (not sent all forbidden)
  for (const auto& entry : fs::directory_iterator(out / "incidents")) {
    SCOPED_TRACE(entry.path().string());
    ++incidents;
    const auto replay = test::safecell_cli(
        {"replay", entry.path().string(), "--lut-cache", (scratch.path() / "cache").string()});
    EXPECT_EQ(replay.exit_code, 0) << replay.out << replay.err;
    EXPECT_NE(replay.out.find("every map as sent"), std::string::npos) << replay.out;
    const auto replayed = nlohmann::json::parse(read_text(entry.path() / "replay" / "replay.json"));
    for (const auto& cycle : replayed["per_cycle"]) ran_again += cycle["outcome"] == "identical";
  }
  EXPECT_GE(incidents, 1U) << run.err;
  EXPECT_GT(ran_again, 0U) << "no recorded cycle went through the pipeline again";
}

// Evidence that could not be written fails the run (exit 3) and the summary says how much: here
// the incidents' folder is a file, as a full disk would refuse them.
TEST(DemoCommand, IncidentsThatCannotBeWrittenEndInExitThree) {
  const test::ScratchFolder scratch("safecell-demo-no-evidence");
  const fs::path cell = test::write_coarse_cell(scratch.path());
  const fs::path out = scratch.path() / "report";
  fs::create_directories(out);
  std::ofstream(out / "incidents") << "not a folder";
  const auto run =
      test::safecell_cli({"demo", "--cell", cell.string(), "--seconds", "5", "--fps", "10", "--out",
                          out.string(), "--lut-cache", (scratch.path() / "cache").string()});
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find("not written"), std::string::npos) << run.err;
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_GE(summary["incidents_not_written"].get<int>(), 1) << summary.dump(2);
}

TEST(DemoCommand, AbsurdSettingsAreRefused) {
  EXPECT_EQ(test::safecell_cli({"demo", "--seconds", "-1"}).exit_code, 2);
  EXPECT_EQ(test::safecell_cli({"demo", "--fps", "0"}).exit_code, 2);
  EXPECT_EQ(test::safecell_cli({"demo", "--acknowledge-after", "-3"}).exit_code, 2);
}

TEST(DemoCommand, AMissingControllerProgramIsNamed) {
  const test::ScratchFolder scratch("safecell-demo-missing");
  const fs::path cell = test::write_coarse_cell(scratch.path());
  const auto run = test::safecell_cli({"demo", "--cell", cell.string(), "--out",
                                       (scratch.path() / "report").string(), "--lut-cache",
                                       (scratch.path() / "cache").string(), "--controller-program",
                                       "/nonexistent/safecell-controller"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("/nonexistent/safecell-controller"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace safecell
