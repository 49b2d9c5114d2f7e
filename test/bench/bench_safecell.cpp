// Every benchmark of the project as a Google Benchmark program, with all its usual flags
// (--benchmark_filter, --benchmark_repetitions, --benchmark_format=json, ...).
#include <benchmark/benchmark.h>

#include "safecell/bench/project_benchmarks.hpp"

int main(int argc, char** argv) {
  safecell::register_project_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
