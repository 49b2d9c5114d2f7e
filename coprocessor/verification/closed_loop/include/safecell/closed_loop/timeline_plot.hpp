#pragma once
// The picture of a closed-loop run over time, four panels sharing the time axis (from the start,
// or a given time, to the last sample): the robot's speed (its fastest joint) and the commanded
// speed scale; a curve of the caller's (the demo: the person's distance to the robot; a replay: the
// share of C-space forbidden); the controller's state (moving, slowed, stopped, fault, waiting) as
// a coloured band; and the latency from exposure to the map in the controller. A span (the demo:
// the person's visit) is shaded.

#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <vector>

#include "safecell/closed_loop/closed_loop_record.hpp"

namespace safecell {

struct PlotSpan {
  double begin_s = 0.0;
  double end_s = 0.0;
};

// The second panel's curve: values at times (s, the record's); a value that is not finite
// breaks the line (the person out of the cell).
struct TimelineCurve {
  std::string title;
  std::string unit;
  std::vector<double> time_s;
  std::vector<double> values;
};

// axis_begin_s: where the time axis begins; by default at 0, the run's start.
cv::Mat timeline_plot(const ClosedLoopRecord& record, const TimelineCurve& curve,
                      const PlotSpan& shaded, std::optional<double> axis_begin_s = std::nullopt);

}  // namespace safecell
