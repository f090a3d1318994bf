#include "tools/figures/figures_report.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace houghloc::figures {
namespace {

using nlohmann::json;

json benchmarkRow(const std::string& run_name, const std::string& run_type,
                  const std::string& aggregate, double cpu_time) {
  json row = {{"name", run_name + (aggregate.empty() ? "" : "_" + aggregate)},
              {"run_name", run_name},
              {"run_type", run_type},
              {"iterations", 10},
              {"real_time", cpu_time * 1.1},
              {"cpu_time", cpu_time},
              {"time_unit", "us"},
              {"speedup", 20.5}};
  if (!aggregate.empty()) row["aggregate_name"] = aggregate;
  return row;
}

TEST(FiguresReport, KeepsTheMedianOfRepeatedBenchmarksAndTheirCounters) {
  const json document = {{"context", {{"num_cpus", 2}}},
                         {"benchmarks",
                          {benchmarkRow("Locate/300", "iteration", "", 1300.0),
                           benchmarkRow("Locate/300", "iteration", "", 1100.0),
                           benchmarkRow("Locate/300", "aggregate", "mean", 1200.0),
                           benchmarkRow("Locate/300", "aggregate", "median", 1150.0),
                           benchmarkRow("Locate/300", "aggregate", "stddev", 50.0)}}};
  const std::vector<BenchmarkFigure> figures = parseBenchmarks(document, "bench.json");
  ASSERT_EQ(figures.size(), 1u);
  EXPECT_EQ(figures[0].name, "Locate/300");
  EXPECT_DOUBLE_EQ(figures[0].cpu_time, 1150.0);
  EXPECT_EQ(figures[0].time_unit, "us");
  ASSERT_EQ(figures[0].counters.count("speedup"), 1u);
  EXPECT_DOUBLE_EQ(figures[0].counters.at("speedup"), 20.5);
  EXPECT_EQ(figures[0].counters.count("iterations"), 0u);
}

TEST(FiguresReport, KeepsEveryIterationRowWithoutRepetitions) {
  const json document = {{"benchmarks",
                          {benchmarkRow("Vision/640", "iteration", "", 1.0),
                           benchmarkRow("Baseline/640", "iteration", "", 15.0)}}};
  EXPECT_EQ(parseBenchmarks(document, "b.json").size(), 2u);
}

TEST(FiguresReport, ReadsTestResultsAndRecordedProperties) {
  const json document = {{"testsuites",
                          {{{"name", "Tracking"},
                            {"testsuite",
                             {{{"name", "Walk"},
                               {"status", "RUN"},
                               {"result", "COMPLETED"},
                               {"time", "1.2s"},
                               {"median_position_m", "0.004"}},
                              {{"name", "Kidnap"},
                               {"status", "RUN"},
                               {"result", "COMPLETED"},
                               {"failures", {{{"failure", "bound exceeded"}}}}},
                              {{"name", "Real"}, {"status", "RUN"}, {"result", "SKIPPED"}}}}}}}};
  const std::vector<TestFigure> figures = parseTests(document, "t.json");
  ASSERT_EQ(figures.size(), 3u);
  EXPECT_TRUE(figures[0].passed);
  EXPECT_EQ(figures[0].properties.at("median_position_m"), "0.004");
  EXPECT_EQ(figures[0].properties.count("time"), 0u);
  EXPECT_FALSE(figures[1].passed);
  EXPECT_TRUE(figures[2].skipped);

  const std::string page = formatReport(
      {"abc1234", "2026-12-01", "2 cores"},
      {{"houghloc-bench-global", {{"Locate/300", 1.0, 0.9, "ms", {{"speedup", 21.0}}}}}},
      {{"tracking_test", figures}});
  EXPECT_NE(page.find("`abc1234`"), std::string::npos);
  EXPECT_NE(page.find("| Locate/300 | 0.9 ms | 1 ms | speedup 21 |"), std::string::npos);
  EXPECT_NE(page.find("| tracking_test | 1 | 1 | 1 |"), std::string::npos);
  EXPECT_NE(page.find("| Tracking.Walk | passed | median_position_m 0.004 |"), std::string::npos);
}

TEST(FiguresReport, NamesTheFileWhenTheDocumentIsNotABenchmarkFile) {
  try {
    parseBenchmarks(json{{"tests", 1}}, "out/global.json");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("out/global.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("benchmarks"), std::string::npos);
  }
}

}  // namespace
}  // namespace houghloc::figures
