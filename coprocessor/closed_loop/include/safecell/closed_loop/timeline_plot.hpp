#pragma once
// The picture of a closed-loop run over time, four panels sharing the time axis: the robot's
// speed (its fastest joint) and the commanded speed scale; the person's distance to the robot;
// the controller's state (moving, slowed, stopped, fault, waiting) as a coloured band; and the
// latency from exposure to the map in the controller. The person's visit is shaded.

#include <opencv2/core/mat.hpp>
#include <vector>

#include "safecell/closed_loop/closed_loop_record.hpp"

namespace safecell {

struct PlotSpan {
  double begin_s = 0.0;
  double end_s = 0.0;
};

cv::Mat timeline_plot(const ClosedLoopRecord& record, const std::vector<double>& distance_m,
                      const PlotSpan& person_visit);

}  // namespace safecell
