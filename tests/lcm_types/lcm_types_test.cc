// Round trip of every houghloc LCM type through encode/decode, and the decoder's refusal of
// truncated or foreign bytes (the node counts those as malformed).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "houghloc/camera_pose_t.hpp"
#include "houghloc/image_t.hpp"
#include "houghloc/line_points_t.hpp"
#include "houghloc/localization_hint_t.hpp"
#include "houghloc/localizer_status_t.hpp"
#include "houghloc/odometry_t.hpp"
#include "houghloc/pose_hypotheses_t.hpp"

namespace houghloc {
namespace {

template <typename T>
std::vector<std::uint8_t> encode(const T& msg) {
  std::vector<std::uint8_t> buf(msg.getEncodedSize());
  EXPECT_EQ(msg.encode(buf.data(), 0, static_cast<int>(buf.size())), static_cast<int>(buf.size()));
  return buf;
}

template <typename T>
T decode(const std::vector<std::uint8_t>& buf) {
  T out;
  EXPECT_EQ(out.decode(buf.data(), 0, static_cast<int>(buf.size())), static_cast<int>(buf.size()));
  return out;
}

pose_hypothesis_t hypothesis(int id, double x) {
  pose_hypothesis_t h;
  h.id = id;
  h.x = x;
  h.y = -1.25;
  h.theta = 0.5;
  for (int i = 0; i < 9; ++i) h.covariance[i] = 0.01 * (i + 1);
  h.weight = 0.75;
  h.age = 35;
  return h;
}

TEST(LcmTypes, ImageRoundTrip) {
  image_t img;
  img.utime = 1234567890123;
  img.camera_id = "top";
  img.width = 4;
  img.height = 2;
  img.pixel_format = image_t::PIXEL_FORMAT_YUYV;
  img.row_stride = 8;
  std::mt19937 rng(7);
  for (int i = 0; i < 16; ++i) img.data.push_back(static_cast<std::uint8_t>(rng()));
  img.size = static_cast<std::int32_t>(img.data.size());
  const image_t out = decode<image_t>(encode(img));
  EXPECT_EQ(out.utime, img.utime);
  EXPECT_EQ(out.camera_id, "top");
  EXPECT_EQ(out.width, 4);
  EXPECT_EQ(out.pixel_format, int{image_t::PIXEL_FORMAT_YUYV});
  EXPECT_EQ(out.row_stride, 8);
  EXPECT_EQ(out.data, img.data);
}

TEST(LcmTypes, PoseHypothesesRoundTrip) {
  pose_hypotheses_t msg;
  msg.utime = 42;
  msg.status = pose_hypotheses_t::AMBIGUOUS;
  msg.hypotheses = {hypothesis(3, 1.5), hypothesis(9, -1.5)};
  msg.num_hypotheses = 2;
  const pose_hypotheses_t out = decode<pose_hypotheses_t>(encode(msg));
  EXPECT_EQ(out.status, int{pose_hypotheses_t::AMBIGUOUS});
  ASSERT_EQ(out.num_hypotheses, 2);
  EXPECT_EQ(out.hypotheses[1].id, 9);
  EXPECT_EQ(out.hypotheses[1].x, -1.5);
  EXPECT_EQ(out.hypotheses[0].covariance[8], 0.09);
  EXPECT_EQ(out.hypotheses[0].age, 35);
}

TEST(LcmTypes, InputsRoundTrip) {
  odometry_t odo;
  odo.utime = 5;
  odo.x = 1.0;
  odo.y = 2.0;
  odo.theta = -3.0;
  for (int i = 0; i < 9; ++i) odo.covariance[i] = i == 0 ? 1e-4 : 0.0;
  const odometry_t odo_out = decode<odometry_t>(encode(odo));
  EXPECT_EQ(odo_out.theta, -3.0);
  EXPECT_EQ(odo_out.covariance[0], 1e-4);

  camera_pose_t cam;
  cam.utime = 6;
  cam.camera_id = "bottom";
  cam.x = 0.05;
  cam.y = 0.0;
  cam.z = 0.45;
  cam.roll = 0.01;
  cam.pitch = 0.7;
  cam.yaw = -0.2;
  const camera_pose_t cam_out = decode<camera_pose_t>(encode(cam));
  EXPECT_EQ(cam_out.camera_id, "bottom");
  EXPECT_EQ(cam_out.pitch, 0.7);

  localization_hint_t hint;
  hint.utime = 7;
  hint.kind = localization_hint_t::ADD;
  hint.poses = {hypothesis(0, -3.0), hypothesis(1, -3.0)};
  hint.num_poses = 2;
  const localization_hint_t hint_out = decode<localization_hint_t>(encode(hint));
  EXPECT_EQ(hint_out.kind, int{localization_hint_t::ADD});
  ASSERT_EQ(hint_out.num_poses, 2);
  EXPECT_EQ(hint_out.poses[1].x, -3.0);
}

TEST(LcmTypes, OutputsRoundTrip) {
  line_points_t pts;
  pts.utime = 8;
  pts.camera_id = "";
  pts.x = {0.5f, 1.5f, 2.5f};
  pts.y = {-0.5f, 0.0f, 0.5f};
  pts.num_points = 3;
  const line_points_t pts_out = decode<line_points_t>(encode(pts));
  EXPECT_EQ(pts_out.x, pts.x);
  EXPECT_EQ(pts_out.y, pts.y);

  localizer_status_t st{};
  st.utime = 9;
  st.state = pose_hypotheses_t::TRACKING;
  st.cycle_time_ms = 1.25;
  st.points_in = 300;
  st.points_used = 250;
  st.frames_processed = 100;
  st.dropped_old_image = 1;
  st.dropped_no_camera_pose = 2;
  st.dropped_bad_size = 3;
  st.dropped_malformed = 4;
  st.dropped_queue_full = 5;
  st.message = "camera 'top': image 320x240, camera.yaml 640x480";
  const localizer_status_t st_out = decode<localizer_status_t>(encode(st));
  EXPECT_EQ(st_out.dropped_old_image, 1);
  EXPECT_EQ(st_out.dropped_no_camera_pose, 2);
  EXPECT_EQ(st_out.dropped_bad_size, 3);
  EXPECT_EQ(st_out.dropped_malformed, 4);
  EXPECT_EQ(st_out.dropped_queue_full, 5);
  EXPECT_EQ(st_out.message, st.message);
}

TEST(LcmTypes, TruncatedAndForeignBytesDoNotDecode) {
  pose_hypotheses_t msg;
  msg.utime = 1;
  msg.status = pose_hypotheses_t::TRACKING;
  msg.hypotheses = {hypothesis(1, 0.0)};
  msg.num_hypotheses = 1;
  std::vector<std::uint8_t> buf = encode(msg);
  pose_hypotheses_t out;
  EXPECT_LT(out.decode(buf.data(), 0, static_cast<int>(buf.size()) - 1), 0);
  // A different type's bytes fail the fingerprint check.
  odometry_t odo{};
  const std::vector<std::uint8_t> odo_buf = encode(odo);
  EXPECT_LT(out.decode(odo_buf.data(), 0, static_cast<int>(odo_buf.size())), 0);
}

}  // namespace
}  // namespace houghloc
