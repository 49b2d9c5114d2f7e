// Exposures of a frame set checked against each other: a camera exposed too far from the others
// becomes an unknown view, named, with its offset.

#include "safecell/acquisition/exposure_sync.hpp"

#include <gtest/gtest.h>

namespace safecell {
namespace {

FrameSet set_with(const std::vector<double>& exposures_s) {
  FrameSet set;
  for (std::size_t c = 0; c < exposures_s.size(); ++c) {
    CameraFrame frame;
    frame.camera = "cam" + std::to_string(c);
    frame.exposure_s = exposures_s[c];
    set.frames.push_back(frame);
  }
  return set;
}

TEST(ExposureSync, ExposuresWithinTheSpreadStayKnown) {
  FrameSet set = set_with({10.000, 10.002, 10.001, 10.003});
  EXPECT_EQ(reject_out_of_sync_exposures(set, 0.005), 0u);
  EXPECT_EQ(set.known_count(), 4u);
}

TEST(ExposureSync, ALateCameraBecomesAnUnknownViewNamingItsOffset) {
  FrameSet set = set_with({10.000, 10.001, 10.040, 10.002});
  EXPECT_EQ(reject_out_of_sync_exposures(set, 0.010), 1u);
  EXPECT_EQ(set.known_count(), 3u);
  EXPECT_EQ(set.frames[2].view.fault, CameraFault::kOutOfSync);
  EXPECT_NE(set.frames[2].view.detail.find("cam2"), std::string::npos) << set.frames[2].view.detail;
  EXPECT_NE(set.frames[2].view.detail.find("ms from the set's median"), std::string::npos);
}

TEST(ExposureSync, UnknownViewsDoNotVoteAndStayUnknown) {
  FrameSet set = set_with({10.000, 99.0, 10.001, 10.002});
  set.frames[1].view = camera_fault_report("cam1", CameraFault::kStopped, "no frame");
  EXPECT_EQ(reject_out_of_sync_exposures(set, 0.010), 0u);
  EXPECT_EQ(set.frames[1].view.fault, CameraFault::kStopped);
  EXPECT_DOUBLE_EQ(median_exposure_s(set), 10.001);
}

TEST(ExposureSync, AbsurdLimitsAreRefused) {
  FrameSet set = set_with({1.0});
  EXPECT_THROW((void)reject_out_of_sync_exposures(set, 0.0), std::invalid_argument);
  EXPECT_THROW((void)reject_out_of_sync_exposures(set, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
