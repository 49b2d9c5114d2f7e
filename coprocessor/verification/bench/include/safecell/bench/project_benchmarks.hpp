#pragma once
// The project's benchmarks (Google Benchmark), shared by the bench_safecell program and
// `safecell bench`. Each reports its median and its worst repetition: benchmarks report the worst
// case, not just the mean (STYLE.md). Speed is measured here, never asserted in tests.

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace safecell {

// Registers one benchmark with the statistics every project benchmark reports (median, max).
void register_benchmark(const char* name, void (*function)(benchmark::State&),
                        benchmark::TimeUnit unit);

// Registers every benchmark of the project, once per process.
void register_project_benchmarks();

struct BenchmarkFigure {
  std::string name;
  double median_ms = 0.0;
  double max_ms = 0.0;  // the worst repetition
  std::map<std::string, double> counters;
};

struct BenchmarkRunOptions {
  std::string filter = ".";  // a regular expression over the names
  double min_time_s = 0.2;   // per repetition
  int repetitions = 5;
};

// Runs the matching benchmarks in this process and returns their figures in run order.
std::vector<BenchmarkFigure> run_project_benchmarks(const BenchmarkRunOptions& options);

}  // namespace safecell
