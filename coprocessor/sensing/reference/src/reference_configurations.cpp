#include "safecell/reference/reference_configurations.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace safecell {
namespace {

void check(const std::vector<std::vector<cv::Mat>>& coverage, std::size_t count) {
  if (count == 0 || count > coverage.size()) {
    throw std::invalid_argument("choose_reference_configurations: count " + std::to_string(count) +
                                ", expected 1 to the number of candidates (" +
                                std::to_string(coverage.size()) + ")");
  }
  for (std::size_t k = 0; k < coverage.size(); ++k) {
    if (coverage[k].size() != coverage.front().size()) {
      throw std::invalid_argument("choose_reference_configurations: candidate " +
                                  std::to_string(k) + " has masks for " +
                                  std::to_string(coverage[k].size()) + " cameras, expected " +
                                  std::to_string(coverage.front().size()));
    }
    for (std::size_t c = 0; c < coverage[k].size(); ++c) {
      const cv::Mat& mask = coverage[k][c];
      if (mask.type() != CV_8UC1 || mask.size() != coverage.front()[c].size()) {
        throw std::invalid_argument("choose_reference_configurations: candidate " +
                                    std::to_string(k) + ", camera " + std::to_string(c) +
                                    ": expected a CV_8UC1 mask of the camera's size");
      }
    }
  }
}

}  // namespace

std::vector<cv::Mat> coverage_counts(const std::vector<std::vector<cv::Mat>>& coverage,
                                     const std::vector<std::size_t>& chosen) {
  std::vector<cv::Mat> counts;
  if (coverage.empty()) return counts;
  for (const cv::Mat& mask : coverage.front())
    counts.push_back(cv::Mat::zeros(mask.size(), CV_16UC1));
  for (const std::size_t k : chosen) {
    for (std::size_t c = 0; c < counts.size(); ++c) {
      cv::add(counts[c], 1, counts[c], coverage[k][c]);
    }
  }
  return counts;
}

std::vector<std::size_t> choose_reference_configurations(
    const std::vector<std::vector<cv::Mat>>& coverage, std::size_t count) {
  check(coverage, count);
  std::vector<std::size_t> chosen;
  std::vector<bool> taken(coverage.size(), false);
  std::vector<cv::Mat> counts = coverage_counts(coverage, chosen);  // all zero
  while (chosen.size() < count) {
    std::size_t best = coverage.size();
    double best_cost = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < coverage.size(); ++k) {
      if (taken[k]) continue;
      // Adding k raises sum(n^2) by sum over its pixels of (2 n + 1).
      double cost = 0.0;
      for (std::size_t c = 0; c < counts.size(); ++c) {
        const int covered = cv::countNonZero(coverage[k][c]);
        if (covered == 0) continue;
        cost += covered * (2.0 * cv::mean(counts[c], coverage[k][c])[0] + 1.0);
      }
      if (cost < best_cost) {
        best = k;
        best_cost = cost;
      }
    }
    taken[best] = true;
    chosen.push_back(best);
    for (std::size_t c = 0; c < counts.size(); ++c) {
      cv::add(counts[c], 1, counts[c], coverage[best][c]);
    }
  }
  return chosen;
}

}  // namespace safecell
