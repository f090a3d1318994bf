// The live viewer's model without a display: encoded messages, memq:// and a replayed log.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <lcm/lcm-cpp.hpp>
#include <string>
#include <vector>

#include "tools/fieldmap/viewer_model/lcm_feed.h"
#include "tools/fieldmap/viewer_model/viewer_state.h"

namespace houghloc::fieldmap {
namespace {

pose_hypotheses_t hypotheses(std::int64_t utime, std::vector<double> xs) {
  pose_hypotheses_t m{};
  m.utime = utime;
  m.status = pose_hypotheses_t::AMBIGUOUS;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    pose_hypothesis_t h{};
    h.id = static_cast<int>(i);
    h.x = xs[i];
    h.y = -1.0;
    h.theta = 0.5;
    h.covariance[0] = h.covariance[4] = 0.01;
    h.covariance[8] = 0.001;
    h.weight = 1.0 / xs.size();
    m.hypotheses.push_back(h);
  }
  m.num_hypotheses = static_cast<int>(xs.size());
  return m;
}

template <typename T>
std::vector<std::uint8_t> encode(const T& m) {
  std::vector<std::uint8_t> bytes(m.getEncodedSize());
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

TEST(ViewerState, KeepsTheNewestMessagesPerPrefix) {
  ViewerState state({"NAO3_", "NAO5_"});
  EXPECT_TRUE(state.empty());
  auto a = encode(hypotheses(1, {1.0, -1.0}));
  auto b = encode(hypotheses(2, {2.0}));
  EXPECT_TRUE(state.apply("NAO3_HYPOTHESES", a.data(), a.size()));
  EXPECT_TRUE(state.apply("NAO5_HYPOTHESES", b.data(), b.size()));
  EXPECT_FALSE(state.apply("NAO7_HYPOTHESES", b.data(), b.size()));  // not subscribed
  EXPECT_FALSE(state.apply("NAO3_IMAGE", b.data(), b.size()));       // not drawn
  ASSERT_TRUE(state.robot("NAO3_").hypotheses.has_value());
  EXPECT_EQ(state.robot("NAO3_").hypotheses->num_hypotheses, 2);
  EXPECT_DOUBLE_EQ(state.robot("NAO3_").hypotheses->hypotheses[1].x, -1.0);
  EXPECT_EQ(state.robot("NAO5_").hypotheses->utime, 2);
  EXPECT_FALSE(state.robot("NAO5_").status.has_value());

  localizer_status_t status{};
  status.state = pose_hypotheses_t::TRACKING;
  status.cycle_time_ms = 12.5;
  status.message = "ok";
  auto s = encode(status);
  EXPECT_TRUE(state.apply("NAO3_STATUS", s.data(), s.size()));
  EXPECT_DOUBLE_EQ(state.robot("NAO3_").status->cycle_time_ms, 12.5);
  line_points_t points{};
  points.num_points = 2;
  points.x = {1.0f, 2.0f};
  points.y = {0.0f, 0.5f};
  auto p = encode(points);
  EXPECT_TRUE(state.apply("NAO3_LINE_POINTS", p.data(), p.size()));
  EXPECT_FLOAT_EQ(state.robot("NAO3_").points->y[1], 0.5f);
  EXPECT_EQ(state.accepted(), 4);
}

TEST(ViewerState, IgnoresMalformedBytes) {
  ViewerState state({""});
  auto good = encode(hypotheses(1, {1.0}));
  ASSERT_TRUE(state.apply("HYPOTHESES", good.data(), good.size()));
  auto truncated = good;
  truncated.resize(truncated.size() - 3);
  EXPECT_FALSE(state.apply("HYPOTHESES", truncated.data(), truncated.size()));
  auto status = encode(localizer_status_t{});
  EXPECT_FALSE(state.apply("HYPOTHESES", status.data(), status.size()));  // wrong type hash
  auto nan = encode(hypotheses(9, {std::nan("")}));
  EXPECT_FALSE(state.apply("HYPOTHESES", nan.data(), nan.size()));
  EXPECT_FALSE(state.apply("HYPOTHESES", nullptr, 0));
  EXPECT_EQ(state.robot("").hypotheses->utime, 1);  // the good one is kept
  EXPECT_EQ(state.malformed(), 4);
}

TEST(ViewerState, FedOverMemq) {
  ViewerState state({"R1_"});
  LcmFeed feed("memq://", &state);
  EXPECT_EQ(feed.poll(), 0);  // nothing waiting: returns at once
  pose_hypotheses_t m = hypotheses(7, {0.5, -0.5, 3.0});
  feed.lcm().publish("R1_HYPOTHESES", &m);
  pose_hypotheses_t truth = hypotheses(7, {0.4});
  feed.lcm().publish("R1_GROUND_TRUTH", &truth);
  feed.lcm().publish("OTHER_HYPOTHESES", &m);
  EXPECT_EQ(feed.poll(), 2);
  ASSERT_TRUE(state.robot("R1_").hypotheses.has_value());
  EXPECT_EQ(state.robot("R1_").hypotheses->num_hypotheses, 3);
  EXPECT_DOUBLE_EQ(state.robot("R1_").hypotheses->hypotheses[2].x, 3.0);
  EXPECT_DOUBLE_EQ(state.robot("R1_").ground_truth->hypotheses[0].x, 0.4);
}

TEST(LogIndex, StateAtATimeIsTheReplayUpToIt) {
  const std::string path = ::testing::TempDir() + "/viewer_model_test.lcmlog";
  {
    lcm::LogFile log(path, "w");
    ASSERT_TRUE(log.good());
    // Written out of time order on purpose: the index sorts by time.
    for (std::int64_t t : {3'000'000, 1'000'000, 2'000'000}) {
      auto bytes = encode(hypotheses(t, std::vector<double>(t / 1'000'000, 0.1 * t / 1e6)));
      lcm::LogEvent e{};
      e.timestamp = t;
      e.channel = "HYPOTHESES";
      e.datalen = static_cast<int32_t>(bytes.size());
      e.data = bytes.data();
      ASSERT_EQ(log.writeEvent(&e), 0);
    }
  }
  const LogIndex index(path);
  ASSERT_EQ(index.messages().size(), 3u);
  EXPECT_EQ(index.startUs(), 1'000'000);
  EXPECT_EQ(index.endUs(), 3'000'000);
  EXPECT_FALSE(index.stateAt(999'999, {""}).robot("").hypotheses.has_value());
  EXPECT_EQ(index.stateAt(1'000'000, {""}).robot("").hypotheses->num_hypotheses, 1);
  EXPECT_EQ(index.stateAt(2'500'000, {""}).robot("").hypotheses->num_hypotheses, 2);
  EXPECT_EQ(index.stateAt(9'000'000, {""}).robot("").hypotheses->utime, 3'000'000);
  EXPECT_THROW(LogIndex("/nonexistent/x.lcmlog"), std::runtime_error);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace houghloc::fieldmap
