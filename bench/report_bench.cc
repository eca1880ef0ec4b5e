// What `scout report` and `scout compare` spend on a long run: reading
// frontier.csv (one row per strategy and optimisation round) and drawing a
// per-round line chart. A museum-sized replay has thousands of rounds; a
// long exploration hundreds of thousands.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "scout/report/run_data.h"
#include "scout/report/svg_plot.h"

namespace {

// Writes a seeded frontier.csv of 'rounds' rounds of five strategies.
std::filesystem::path WriteFrontierCsv(int rounds) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("scout_report_bench_" + std::to_string(rounds) + ".csv");
  std::ofstream out(path);
  out << "round,strategy,queried_points,queried_submaps,time_us,tp,fp,tn,fn,local_points\n";
  std::mt19937 rng(1);
  std::uniform_int_distribution<int> points(0, 300000), submaps(0, 500), time(10, 90000);
  for (int r = 0; r < rounds; ++r) {
    for (const char* s : {"full", "dfd", "bfs", "direct", "exact"}) {
      out << r << ',' << s << ',' << points(rng) << ',' << submaps(rng) << ',' << time(rng) << ','
          << points(rng) << ",0," << points(rng) << ",0," << points(rng) << '\n';
    }
  }
  return path;
}

void BM_ReadFrontierCsv(benchmark::State& state) {
  const std::filesystem::path path = WriteFrontierCsv(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const std::vector<scout::report::FrontierRound> rounds = scout::report::ReadFrontierCsv(path);
    benchmark::DoNotOptimize(rounds.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0) * 5);
  state.SetBytesProcessed(state.iterations() *
                          static_cast<int64_t>(std::filesystem::file_size(path)));
  std::filesystem::remove(path);
}
BENCHMARK(BM_ReadFrontierCsv)
    ->ArgName("rounds")
    ->Arg(10000)
    ->Arg(200000)
    ->Unit(benchmark::kMillisecond);

// One series per strategy, as the per-round figures draw them; the SVG's
// size is reported as a counter (it is embedded in report.html).
void BM_RenderLineChart(benchmark::State& state) {
  scout::report::LineChart chart;
  chart.title = "points re-queried per round";
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> value(0.0, 3e5);
  for (const char* s : {"dfd", "bfs", "direct", "exact"}) {
    scout::report::Series series{s, {}, {}};
    for (int64_t r = 0; r < state.range(0); ++r) {
      series.x.push_back(static_cast<double>(r));
      series.y.push_back(value(rng));
    }
    chart.series.push_back(std::move(series));
  }
  size_t bytes = 0;
  for (auto _ : state) bytes = scout::report::RenderLineChart(chart).size();
  state.counters["svg_kB"] = static_cast<double>(bytes) / 1000.0;
  state.SetItemsProcessed(state.iterations() * state.range(0) * 4);
}
BENCHMARK(BM_RenderLineChart)
    ->ArgName("rounds")
    ->Arg(1000)
    ->Arg(200000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
