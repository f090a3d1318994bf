#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace houghloc::figures {

/// One benchmark row of a Google Benchmark JSON file (`--benchmark_out_format=json`). With
/// repetitions only the median aggregate is kept: it is what the README quotes.
struct BenchmarkFigure {
  std::string name;  ///< without the `_median` suffix
  double real_time = 0.0;
  double cpu_time = 0.0;
  std::string time_unit;                   ///< ns, us, ms or s, as the benchmark set it
  std::map<std::string, double> counters;  ///< user counters (ratios, points, success rates)
};

/// One GoogleTest case of a `--gtest_output=json` file, with what it recorded through
/// RecordProperty (the figures a test asserts against its bounds).
struct TestFigure {
  std::string suite;
  std::string name;
  bool passed = false;
  bool skipped = false;
  std::map<std::string, std::string> properties;
};

/// Reads a benchmark JSON document. Throws std::runtime_error naming `source` and the key at
/// fault when it is not one.
std::vector<BenchmarkFigure> parseBenchmarks(const nlohmann::json& document,
                                             const std::string& source);

/// Reads a GoogleTest JSON report. Throws std::runtime_error naming `source` when it is not one.
std::vector<TestFigure> parseTests(const nlohmann::json& document, const std::string& source);

/// What the generated page says about where its figures come from.
struct ReportHeader {
  std::string commit;   ///< git commit the binaries were built from
  std::string date;     ///< when the figures were measured
  std::string machine;  ///< CPU model and cores
};

/// docs/figures.md: a table per benchmark binary and a table of the test cases that recorded
/// figures, plus pass / fail / skip counts per test binary. `benchmarks` and `tests` are keyed
/// by the binary's name.
std::string formatReport(const ReportHeader& header,
                         const std::map<std::string, std::vector<BenchmarkFigure>>& benchmarks,
                         const std::map<std::string, std::vector<TestFigure>>& tests);

}  // namespace houghloc::figures
