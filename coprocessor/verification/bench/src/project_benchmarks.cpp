#include "safecell/bench/project_benchmarks.hpp"

#include <algorithm>
#include <stdexcept>

namespace safecell {

void register_feature_benchmarks();  // feature_benchmarks.cpp
void register_fusion_benchmarks();   // fusion_benchmarks.cpp
void register_link_benchmarks();     // link_benchmarks.cpp
void register_render_benchmarks();   // render_benchmarks.cpp

namespace {

double max_of(const std::vector<double>& values) {
  return *std::max_element(values.begin(), values.end());
}

double to_ms(double time, benchmark::TimeUnit unit) {
  switch (unit) {
    case benchmark::kNanosecond:
      return time * 1e-6;
    case benchmark::kMicrosecond:
      return time * 1e-3;
    case benchmark::kMillisecond:
      return time;
    case benchmark::kSecond:
      return time * 1e3;
  }
  return time;
}

// Keeps the median and max aggregates of every benchmark, and its counters.
class FigureCollector final : public benchmark::BenchmarkReporter {
 public:
  bool ReportContext(const Context& /*context*/) override { return true; }

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.error_occurred) {
        throw std::runtime_error("benchmark " + run.benchmark_name() +
                                 " failed: " + run.error_message);
      }
      if (run.run_type != Run::RT_Aggregate) continue;
      BenchmarkFigure& figure = figure_of(run.run_name.function_name);
      const double ms = to_ms(run.GetAdjustedRealTime(), run.time_unit);
      if (run.aggregate_name == "median") {
        figure.median_ms = ms;
        for (const auto& [name, counter] : run.counters) figure.counters[name] = counter.value;
      } else if (run.aggregate_name == "max") {
        figure.max_ms = ms;
      }
    }
  }

  std::vector<BenchmarkFigure> figures() const { return figures_; }

 private:
  BenchmarkFigure& figure_of(const std::string& name) {
    for (auto& figure : figures_) {
      if (figure.name == name) return figure;
    }
    figures_.push_back(BenchmarkFigure{name, 0.0, 0.0, {}});
    return figures_.back();
  }

  std::vector<BenchmarkFigure> figures_;
};

}  // namespace

void register_benchmark(const char* name, void (*function)(benchmark::State&),
                        benchmark::TimeUnit unit) {
  // Google Benchmark owns the registered benchmark for the life of the process.
  benchmark::RegisterBenchmark(name, function)  // NOLINT(clang-analyzer-cplusplus.NewDeleteLeaks)
      ->Unit(unit)
      ->ComputeStatistics("max", max_of);
}

void register_project_benchmarks() {
  static const bool registered = [] {
    register_feature_benchmarks();
    register_fusion_benchmarks();
    register_link_benchmarks();
    register_render_benchmarks();
    return true;
  }();
  static_cast<void>(registered);
}

std::vector<BenchmarkFigure> run_project_benchmarks(const BenchmarkRunOptions& options) {
  if (!(options.min_time_s > 0.0) || options.repetitions < 2) {
    throw std::invalid_argument(
        "benchmarks need a minimum time above 0 s and at least 2 repetitions");
  }
  register_project_benchmarks();
  std::vector<std::string> arguments{
      "safecell-bench", "--benchmark_filter=" + options.filter,
      "--benchmark_min_time=" + std::to_string(options.min_time_s),
      "--benchmark_repetitions=" + std::to_string(options.repetitions),
      "--benchmark_report_aggregates_only=true"};
  std::vector<char*> argv;
  argv.reserve(arguments.size());
  for (auto& argument : arguments) argv.push_back(argument.data());
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());
  FigureCollector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  return collector.figures();
}

}  // namespace safecell
