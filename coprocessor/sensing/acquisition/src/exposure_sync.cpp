#include "safecell/acquisition/exposure_sync.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace safecell {

double median_exposure_s(const FrameSet& set) {
  std::vector<double> exposures;
  for (const CameraFrame& frame : set.frames) {
    if (frame.known()) exposures.push_back(frame.exposure_s);
  }
  if (exposures.empty()) return 0.0;
  std::sort(exposures.begin(), exposures.end());
  const std::size_t middle = exposures.size() / 2;
  return exposures.size() % 2 == 1 ? exposures[middle]
                                   : 0.5 * (exposures[middle - 1] + exposures[middle]);
}

std::size_t reject_out_of_sync_exposures(FrameSet& set, double max_spread_s) {
  if (!(max_spread_s > 0.0) || !std::isfinite(max_spread_s)) {
    throw std::invalid_argument("exposure sync: max_spread_s must be finite and > 0, not " +
                                std::to_string(max_spread_s));
  }
  const double median = median_exposure_s(set);
  std::size_t rejected = 0;
  for (CameraFrame& frame : set.frames) {
    if (!frame.known()) continue;
    const double offset = frame.exposure_s - median;
    if (std::abs(offset) <= max_spread_s / 2.0) continue;
    std::ostringstream detail;
    detail << "exposed " << offset * 1e3 << " ms from the set's median; the limit is +-"
           << max_spread_s / 2.0 * 1e3 << " ms";
    frame.view = camera_fault_report(frame.camera, CameraFault::kOutOfSync, detail.str());
    ++rejected;
  }
  return rejected;
}

}  // namespace safecell
