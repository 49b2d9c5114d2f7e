#include "safecell/closed_loop/timeline_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <string>

namespace safecell {
namespace {

constexpr int kWidth = 1200;
constexpr int kPanelHeight = 150;
constexpr int kLeft = 90;
constexpr int kRight = 20;
constexpr int kTop = 30;
constexpr int kGap = 30;
cv::Scalar ink() { return {40, 40, 40}; }
cv::Scalar grid_line() { return {215, 215, 215}; }
cv::Scalar visit_shade() { return {235, 225, 205}; }

cv::Scalar state_colour(v1::ControllerState state) {
  switch (state) {
    case v1::CONTROLLER_STATE_MOVING:
      return {80, 175, 76};  // green (BGR)
    case v1::CONTROLLER_STATE_SLOWED:
      return {0, 190, 250};  // amber
    case v1::CONTROLLER_STATE_STOPPED:
      return {40, 40, 220};  // red
    case v1::CONTROLLER_STATE_FAULT:
      return {160, 40, 160};  // purple
    default:
      return {170, 170, 170};  // grey: waiting
  }
}

struct Panel {
  cv::Mat& image;
  int top;
  double t_begin;
  double t_end;  // > t_begin
  double y_max;

  int x(double t) const {
    const double share = std::clamp((t - t_begin) / (t_end - t_begin), 0.0, 1.0);
    return kLeft + static_cast<int>(std::lround((kWidth - kLeft - kRight) * share));
  }
  int y(double value) const {
    const double share = std::clamp(value / y_max, 0.0, 1.0);
    return top + kPanelHeight - static_cast<int>(std::lround(share * kPanelHeight));
  }
  void frame(const std::string& title, const PlotSpan& visit, const std::string& unit) const {
    cv::rectangle(image, {x(visit.begin_s), top}, {x(visit.end_s), top + kPanelHeight},
                  visit_shade(), cv::FILLED);
    for (int k = 0; k <= 4; ++k) {
      const int row = top + kPanelHeight * k / 4;
      cv::line(image, {kLeft, row}, {kWidth - kRight, row}, grid_line());
      char label[32];
      std::snprintf(label, sizeof label, "%.2g", y_max * (4 - k) / 4.0);
      cv::putText(image, label, {8, row + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.4, ink());
    }
    cv::rectangle(image, {kLeft, top}, {kWidth - kRight, top + kPanelHeight}, ink());
    cv::putText(image, title + " (" + unit + ")", {kLeft, top - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                ink(), 1, cv::LINE_AA);
  }
  void polyline(const std::vector<cv::Point>& points, const cv::Scalar& colour) const {
    if (points.size() > 1) cv::polylines(image, points, false, colour, 2, cv::LINE_AA);
  }
};

double nice_ceiling(double value) {
  if (!(value > 0.0) || !std::isfinite(value)) return 1.0;
  const double step = std::pow(10.0, std::floor(std::log10(value)));
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * step >= value) return m * step;
  }
  return 10.0 * step;
}

}  // namespace

cv::Mat timeline_plot(const ClosedLoopRecord& record, const TimelineCurve& curve,
                      const PlotSpan& shaded, std::optional<double> axis_begin_s) {
  const int height = kTop + 4 * (kPanelHeight + kGap) + 20;
  cv::Mat image(height, kWidth, CV_8UC3, cv::Scalar(255, 255, 255));
  const double t_begin = axis_begin_s.value_or(0.0);
  double t_end = t_begin + 1.0;
  double speed_max = 0.0;
  double latency_max = 0.0;
  for (const JointRecord& sample : record.joints) {
    t_end = std::max(t_end, sample.time_s);
    for (const double v : sample.velocity) speed_max = std::max(speed_max, std::abs(v));
  }
  const StateFigures states = state_figures(record);
  for (const double latency : states.latency_ms) latency_max = std::max(latency_max, latency);
  const auto panel = [&](int index, double y_max) {
    return Panel{image, kTop + index * (kPanelHeight + kGap), t_begin, t_end, y_max};
  };

  // 1: the fastest joint and the speed scale (scaled to the same axis's top).
  const Panel speed = panel(0, nice_ceiling(speed_max));
  speed.frame("robot speed: fastest joint (blue), speed scale x top (orange)", shaded, "rad/s");
  std::vector<cv::Point> fastest;
  std::vector<cv::Point> scale;
  for (const JointRecord& sample : record.joints) {
    double v = 0.0;
    for (const double joint : sample.velocity) v = std::max(v, std::abs(joint));
    fastest.emplace_back(speed.x(sample.time_s), speed.y(v));
    scale.emplace_back(speed.x(sample.time_s), speed.y(sample.speed_scale * speed.y_max));
  }
  speed.polyline(scale, {0, 140, 255});
  speed.polyline(fastest, {200, 90, 30});

  // 2: the caller's curve.
  double curve_max = 0.0;
  for (const double value : curve.values) {
    if (std::isfinite(value)) curve_max = std::max(curve_max, value);
  }
  const Panel second = panel(1, nice_ceiling(curve_max));
  second.frame(curve.title, shaded, curve.unit);
  std::vector<cv::Point> points;
  for (std::size_t i = 0; i < curve.time_s.size() && i < curve.values.size(); ++i) {
    if (!std::isfinite(curve.values[i])) {
      second.polyline(points, {60, 60, 200});
      points.clear();
      continue;
    }
    points.emplace_back(second.x(curve.time_s[i]), second.y(curve.values[i]));
  }
  second.polyline(points, {60, 60, 200});

  // 3: the state band.
  const Panel state = panel(2, 1.0);
  state.frame("state: moving green, slowed amber, stopped red, fault purple, waiting grey", shaded,
              "-");
  for (std::size_t i = 0; i + 1 < record.joints.size(); ++i) {
    cv::rectangle(image, {state.x(record.joints[i].time_s), state.top + kPanelHeight / 4},
                  {state.x(record.joints[i + 1].time_s), state.top + 3 * kPanelHeight / 4},
                  state_colour(record.joints[i].state), cv::FILLED);
  }

  // 4: latency, exposure -> the map in the controller.
  const Panel latency = panel(3, nice_ceiling(latency_max));
  latency.frame("latency: exposure to the map held by the controller", shaded, "ms");
  std::vector<cv::Point> latencies;
  for (std::size_t k = 0; k < states.latency_ms.size(); ++k) {
    latencies.emplace_back(latency.x(states.latency_at_s[k]), latency.y(states.latency_ms[k]));
  }
  latency.polyline(latencies, {120, 60, 0});
  char axis[96];
  std::snprintf(axis, sizeof axis, "time since the start (s): %.1f .. %.1f", t_begin, t_end);
  cv::putText(image, axis, {kLeft, height - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.5, ink(), 1,
              cv::LINE_AA);
  return image;
}

}  // namespace safecell
