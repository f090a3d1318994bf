// houghloc-figures: turns the JSON outputs of the benchmarks and the GoogleTest binaries into
// docs/figures.md (tools/figures.sh runs them and then this).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <stdexcept>

#include "tools/figures/figures_report.h"

namespace {

namespace fs = std::filesystem;
using houghloc::figures::BenchmarkFigure;
using houghloc::figures::TestFigure;

nlohmann::json readJson(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": not JSON (" + e.what() + ")");
  }
}

std::vector<fs::path> jsonFiles(const std::string& dir) {
  if (!fs::is_directory(dir)) throw std::runtime_error(dir + ": not a folder");
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// GoogleTest names a report after its binary and adds _1, _2, ... when the file exists (one
/// report per ctest case): strip that to group the cases by binary.
std::string binaryName(const fs::path& file) {
  static const std::regex kCopySuffix("_[0-9]+$");
  return std::regex_replace(file.stem().string(), kCopySuffix, "");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "houghloc-figures: writes a Markdown page of measured figures from Google Benchmark JSON "
      "files (--benchmark_out_format=json) and GoogleTest JSON reports (--gtest_output=json). "
      "tools/figures.sh runs everything and calls it.",
      "houghloc-figures"};
  std::string bench_dir, test_dir, out_file;
  houghloc::figures::ReportHeader header;
  app.add_option("--bench-dir", bench_dir, "folder of benchmark JSON files, one per binary");
  app.add_option("--test-dir", test_dir, "folder of GoogleTest JSON reports");
  app.add_option("--commit", header.commit, "commit the figures were measured at")->required();
  app.add_option("--date", header.date, "when they were measured")->required();
  app.add_option("--machine", header.machine, "what they were measured on")->required();
  app.add_option("-o,--out", out_file, "the Markdown file to write")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    std::map<std::string, std::vector<BenchmarkFigure>> benchmarks;
    std::map<std::string, std::vector<TestFigure>> tests;
    if (!bench_dir.empty()) {
      for (const fs::path& file : jsonFiles(bench_dir)) {
        benchmarks[file.stem().string()] =
            houghloc::figures::parseBenchmarks(readJson(file), file.string());
      }
    }
    if (!test_dir.empty()) {
      for (const fs::path& file : jsonFiles(test_dir)) {
        std::vector<TestFigure> found =
            houghloc::figures::parseTests(readJson(file), file.string());
        std::vector<TestFigure>& all = tests[binaryName(file)];
        all.insert(all.end(), found.begin(), found.end());
      }
    }
    std::ofstream out(out_file);
    out << houghloc::figures::formatReport(header, benchmarks, tests);
    if (!out.flush()) throw std::runtime_error(out_file + ": cannot be written");
    std::cerr << "houghloc-figures: wrote " << out_file << " (" << benchmarks.size()
              << " benchmark binaries, " << tests.size() << " test binaries)\n";
  } catch (const std::exception& e) {
    std::cerr << "houghloc-figures: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
