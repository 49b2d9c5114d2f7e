#pragma once
// A progress bar for long work, on the error stream: redrawn in place (at most ten times a
// second) on a terminal, one line per quarter in a log. Shows the stage, the share done and the
// time left at the current pace. Private to the CLI.
//
// A stage may come back (a build that works part by part alternates its stages, each reporting
// the share of all its work done): its clock and its last quarter printed are kept per stage, so
// the time left counts only the time spent in that stage.

#include <chrono>
#include <map>
#include <ostream>
#include <string>

namespace safecell {

class ProgressBar {
 public:
  // interactive: redraw in place (a terminal); otherwise print plain lines.
  ProgressBar(std::ostream& out, bool interactive);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void update(const std::string& stage, double fraction_done);
  // Ends the current line.
  void finish();

  // Whether the process's standard error is a terminal.
  static bool stderr_is_terminal();

 private:
  using Clock = std::chrono::steady_clock;

  std::ostream& out_;
  bool interactive_;
  struct StageClock {
    double spent_s = 0.0;   // time in the stage before it was entered this time
    int last_quarter = -1;  // the last quarter printed (plain lines)
  };

  std::string stage_;
  std::map<std::string, StageClock> stages_;
  Clock::time_point stage_start_;
  Clock::time_point last_draw_;
  bool line_open_ = false;
};

}  // namespace safecell
