#include "tools/offline/estimate_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "tools/recording/recording.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

class EstimateCsvTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ =
        (fs::path(::testing::TempDir()) / (std::string("estimate_csv_") + info->name())).string();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (fs::path(dir_) / name).string(); }
  std::vector<std::string> lines(const std::string& name) const {
    std::ifstream in(path(name));
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
  }
  void writeFile(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
  }
  /// The message readFrameEstimates() throws for the folder (empty when it does not throw).
  std::string readError() const {
    try {
      readFrameEstimates(dir_);
    } catch (const RecordingError& e) {
      return e.what();
    }
    return "";
  }

  std::string dir_;
};

GaussianPose randomPose(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  GaussianPose g;
  g.mean = Pose2(u(rng), u(rng), u(rng));
  // Symmetric to the last bit, doubles with all their digits, variances positive.
  for (int r = 0; r < 3; ++r) {
    g.covariance(r, r) = 0.01 * std::abs(u(rng));
    for (int c = r + 1; c < 3; ++c) g.covariance(r, c) = g.covariance(c, r) = 1e-3 * u(rng);
  }
  g.weight = std::abs(u(rng)) / 7.0;
  return g;
}

TEST_F(EstimateCsvTest, EstimatesSharingATimeGiveOneRowSetTheLastOnes) {
  // Two cameras exposed together (t 100), then one camera alone (t 200).
  std::mt19937 rng(11);
  FrameEstimate top, bottom, later;
  top.t_us = bottom.t_us = 100;
  later.t_us = 200;
  top.status = "AMBIGUOUS";
  bottom.status = later.status = "TRACKING";
  for (int k = 0; k < 3; ++k) top.hypotheses.push_back(randomPose(rng));
  bottom.hypotheses.push_back(randomPose(rng));
  later.hypotheses.push_back(randomPose(rng));
  {
    EstimateCsvWriter writer(dir_);
    for (const FrameEstimate* e : {&top, &bottom, &later}) writer.write(*e);
    writer.close();
  }
  EXPECT_EQ(lines("poses.csv").size(), 3u);       // header + t 100 + t 200
  EXPECT_EQ(lines("hypotheses.csv").size(), 3u);  // bottom's one hypothesis, later's one
  const std::vector<FrameEstimate> read = readFrameEstimates(dir_);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].t_us, 100);
  EXPECT_EQ(read[0].status, "TRACKING");
  ASSERT_EQ(read[0].hypotheses.size(), 1u);
  EXPECT_EQ(read[0].hypotheses[0].mean.x, bottom.hypotheses[0].mean.x);
  EXPECT_EQ(read[1].t_us, 200);
}

TEST_F(EstimateCsvTest, RoundTripIsExactAndHeadersAreTheDesignOnes) {
  std::mt19937 rng(7);
  std::vector<FrameEstimate> written;
  const char* statuses[] = {"INITIALIZING", "TRACKING", "AMBIGUOUS", "LOST"};
  for (int i = 0; i < 40; ++i) {
    FrameEstimate e;
    e.t_us = 1000000000000LL + 33333LL * i;
    e.status = statuses[i % 4];
    const int n = i % 5 == 3 ? 0 : 1 + i % 4;
    for (int k = 0; k < n; ++k) e.hypotheses.push_back(randomPose(rng));
    written.push_back(e);
  }
  written[1].hypotheses[0].mean.x = 0.1;  // values without an exact short form
  written[1].hypotheses[0].weight = 1.0 / 3.0;
  written[2].hypotheses[0].covariance(0, 0) = 1e-300;
  {
    EstimateCsvWriter writer(dir_);
    for (const FrameEstimate& e : written) writer.write(e);
    writer.close();
  }
  const auto poses = lines("poses.csv");
  const auto hypotheses = lines("hypotheses.csv");
  EXPECT_EQ(poses.at(0),
            "t_us,x,y,theta,var_x,var_y,var_theta,weight,num_hypotheses,status,twin_weight");
  EXPECT_EQ(hypotheses.at(0),
            "t_us,rank,x,y,theta,var_x,var_y,var_theta,cov_xy,cov_xtheta,cov_ytheta,weight");
  EXPECT_EQ(poses.size(), 41u);
  // Frame 3 has no hypotheses: empty pose fields and num_hypotheses 0.
  EXPECT_EQ(poses.at(4), std::to_string(written[3].t_us) + ",,,,,,,,0,LOST,0");

  const std::vector<FrameEstimate> read = readFrameEstimates(dir_);
  ASSERT_EQ(read.size(), written.size());
  for (size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read[i].t_us, written[i].t_us);
    EXPECT_EQ(read[i].status, written[i].status);
    ASSERT_EQ(read[i].hypotheses.size(), written[i].hypotheses.size()) << i;
    for (size_t k = 0; k < read[i].hypotheses.size(); ++k) {
      const GaussianPose& a = read[i].hypotheses[k];
      const GaussianPose& b = written[i].hypotheses[k];
      EXPECT_EQ(a.mean.x, b.mean.x);  // exact, not near
      EXPECT_EQ(a.mean.y, b.mean.y);
      EXPECT_EQ(a.mean.theta, b.mean.theta);
      EXPECT_EQ(a.weight, b.weight);
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) EXPECT_EQ(a.covariance(r, c), b.covariance(r, c));
      }
    }
  }
}

TEST_F(EstimateCsvTest, BadRowsNameFileAndLine) {
  const std::string poses_header =
      "t_us,x,y,theta,var_x,var_y,var_theta,weight,num_hypotheses,status\n";
  const std::string hyp_header =
      "t_us,rank,x,y,theta,var_x,var_y,var_theta,cov_xy,cov_xtheta,cov_ytheta,weight\n";
  const std::string good_hyp = hyp_header + "100,0,1,2,0.5,0.01,0.01,0.001,0,0,0,1\n";
  const std::string good_pose = "100,1,2,0.5,0.01,0.01,0.001,1,1,TRACKING\n";

  writeFile("hypotheses.csv", good_hyp);
  writeFile("poses.csv", poses_header + good_pose);
  EXPECT_EQ(readError(), "");

  writeFile("poses.csv", poses_header + "# comment\n" + good_pose + "200,x,,,,,,,0,LOST\n");
  EXPECT_NE(readError().find(path("poses.csv") + ":4:"), std::string::npos) << readError();

  writeFile("poses.csv", poses_header + good_pose + "200,,,,,,,,0,LOS\n");
  EXPECT_NE(readError().find(path("poses.csv") + ":3: unknown status"), std::string::npos)
      << readError();

  writeFile("poses.csv", poses_header + "100,1,2,0.5,0.01,0.01,0.001,1,2,TRACKING\n");
  EXPECT_NE(readError().find(path("poses.csv") + ":2: num_hypotheses 2"), std::string::npos)
      << readError();

  writeFile("poses.csv", poses_header + good_pose + "100,,,,,,,,0,LOST\n");
  EXPECT_NE(readError().find(path("poses.csv") + ":3: t_us 100 repeats line 2"), std::string::npos)
      << readError();

  writeFile("poses.csv", poses_header + good_pose);
  writeFile("hypotheses.csv", good_hyp + "100,2,1,2,0.5,0.01,0.01,0.001,0,0,0,1\n");
  EXPECT_NE(readError().find(path("hypotheses.csv") + ":3: rank 2"), std::string::npos)
      << readError();

  writeFile("hypotheses.csv", good_hyp + "300,0,1,2,0.5,0.01,0.01,0.001,0,0,0,1\n");
  EXPECT_NE(readError().find(path("hypotheses.csv") + ":3: t_us 300 has no row"), std::string::npos)
      << readError();

  writeFile("hypotheses.csv", hyp_header + "100,0,1,2,0.5,-0.01,0.01,0.001,0,0,0,1\n");
  EXPECT_NE(readError().find(path("hypotheses.csv") + ":2: negative variance"), std::string::npos)
      << readError();

  writeFile("hypotheses.csv", "t_us,rank,x\n");
  EXPECT_NE(readError().find(path("hypotheses.csv") + ":1: missing column 'y'"), std::string::npos)
      << readError();

  fs::remove(path("poses.csv"));
  writeFile("hypotheses.csv", good_hyp);
  EXPECT_NE(readError().find(path("poses.csv")), std::string::npos) << readError();
}

TEST_F(EstimateCsvTest, UnwritableFolderNamesTheFile) {
  const std::string missing = (fs::path(dir_) / "no" / "such" / "dir").string();
  try {
    EstimateCsvWriter writer(missing);
    FAIL() << "no error";
  } catch (const RecordingError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace houghloc

namespace houghloc {
namespace {

TEST_F(EstimateCsvTest, TwinWeightColumnIsTheWeightAtTheBestPosesMirror) {
  FrameEstimate e;
  e.t_us = 100;
  e.status = "AMBIGUOUS";
  GaussianPose best, twin, other;
  best.mean = Pose2(1.0, 2.0, 0.5);
  best.weight = 0.6;
  twin.mean = Pose2(-1.1, -2.0, 0.5 + M_PI);  // 0.1 m from the mirror: counts
  twin.weight = 0.25;
  other.mean = Pose2(-1.0, -2.0, 0.5);  // mirrored position, same heading: not a twin
  other.weight = 0.15;
  e.hypotheses = {best, twin, other};
  EXPECT_DOUBLE_EQ(e.twinWeight(), 0.25);
  {
    EstimateCsvWriter writer(dir_);
    writer.write(e);
    writer.close();
  }
  const std::string row = lines("poses.csv").at(1);
  EXPECT_DOUBLE_EQ(std::stod(row.substr(row.rfind(',') + 1)), 0.25);
  EXPECT_DOUBLE_EQ(readFrameEstimates(dir_).at(0).twinWeight(), 0.25);
}

}  // namespace
}  // namespace houghloc
