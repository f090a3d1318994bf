// houghloc-node's handlers on every LCM message type, as the node's LCM thread hands them over:
// bytes off the wire are decoded with the generated type's decode(), a failure counts as
// undecodable, a success goes to NodeCore's handler. The input is a sequence of messages; each
// starts with a byte choosing the channel and whether the message is built from fuzzed fields
// (then encoded, so the decoder sees a well-formed message with arbitrary values: NaN, huge
// sizes, unknown formats, times going backwards) or taken as raw bytes (the decoder sees
// anything). Every HYPOTHESES and STATUS the node produces must be finite and well formed.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "field_models/standard_fields.h"
#include "tests/fuzz/fuzz_camera.h"
#include "tests/fuzz/fuzz_support.h"
#include "tools/lcm/message_decoding.h"
#include "tools/node/node_core.h"
#include "vision/camera_presets.h"

namespace {

using namespace houghloc;

// The camera's size (the nao-top preset scaled), so that images cost little to fuzz.
constexpr int kWidth = 64;
constexpr int kHeight = 48;
const std::vector<std::string> kCameraIds = {"", "top", "unknown"};

std::string cameraId(fuzz::ByteReader& in) { return kCameraIds[in.byte() % kCameraIds.size()]; }

image_t fuzzedImage(fuzz::ByteReader& in, std::int64_t utime) {
  image_t msg;
  msg.utime = utime;
  msg.camera_id = cameraId(in);
  const std::uint8_t shape = in.byte();
  // Mostly the camera's size; sometimes another or a nonsense one.
  msg.width = (shape & 3) ? kWidth : in.value<std::int16_t>();
  msg.height = (shape & 3) ? kHeight : in.value<std::int16_t>();
  msg.pixel_format = static_cast<std::int8_t>((shape >> 2) % 5);  // 3 formats and 2 unknown
  const int bytes_per_pixel = msg.pixel_format == image_t::PIXEL_FORMAT_BGR8 ? 3 : 2;
  msg.row_stride = (shape & 32) ? in.value<std::int16_t>() : msg.width * bytes_per_pixel;
  const std::string pixels = in.rest().substr(0, 4096);
  const long long size = (shape & 64) ? static_cast<long long>(pixels.size())
                                      : static_cast<long long>(msg.row_stride) * msg.height;
  const long long capped = std::max(0LL, std::min(size, 1LL << 20));
  msg.data.resize(static_cast<std::size_t>(capped));
  for (std::size_t i = 0; i < msg.data.size(); ++i) {
    msg.data[i] = pixels.empty() ? 0 : static_cast<std::uint8_t>(pixels[i % pixels.size()]);
  }
  msg.size = static_cast<std::int32_t>(msg.data.size());
  return msg;
}

odometry_t fuzzedOdometry(fuzz::ByteReader& in, std::int64_t utime) {
  odometry_t msg;
  msg.utime = utime;
  msg.x = in.smallDouble(10.0);
  msg.y = in.smallDouble(10.0);
  msg.theta = in.smallDouble(10.0);
  for (double& c : msg.covariance) c = (in.byte() & 1) ? in.smallDouble(1.0) : 0.0;
  return msg;
}

camera_pose_t fuzzedCameraPose(fuzz::ByteReader& in, std::int64_t utime) {
  const Pose3 nominal = cameraPreset("nao-top").robot_T_camera;
  camera_pose_t msg;
  msg.utime = utime;
  msg.camera_id = cameraId(in);
  msg.x = nominal.x + in.smallDouble(0.1);
  msg.y = nominal.y + in.smallDouble(0.1);
  msg.z = nominal.z + in.smallDouble(0.5);
  msg.roll = nominal.roll + in.smallDouble(0.5);
  msg.pitch = nominal.pitch + in.smallDouble(1.0);
  msg.yaw = nominal.yaw + in.smallDouble(1.0);
  return msg;
}

localization_hint_t fuzzedHint(fuzz::ByteReader& in, std::int64_t utime) {
  localization_hint_t msg;
  msg.utime = utime;
  msg.kind = static_cast<std::int8_t>(in.byte() % 7);  // 5 kinds and 2 unknown
  msg.num_poses = in.byte() % 4;
  msg.poses.resize(msg.num_poses);
  for (auto& pose : msg.poses) {
    pose.x = in.smallDouble(6.0);
    pose.y = in.smallDouble(4.0);
    pose.theta = in.smallDouble(4.0);
    const double sigma = in.smallDouble(1.0);
    for (double& c : pose.covariance) c = 0.0;
    pose.covariance[0] = pose.covariance[4] = pose.covariance[8] = sigma * sigma;
  }
  return msg;
}

/// Encodes a message to bytes, as its publisher would.
template <typename Message>
std::vector<std::uint8_t> encoded(const Message& msg) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(msg.getEncodedSize()));
  if (msg.encode(bytes.data(), 0, static_cast<int>(bytes.size())) < 0) bytes.clear();
  return bytes;
}

/// Decodes bytes as the node's LCM thread does: a failure is counted, a success handled.
template <typename Message, typename Handler>
void deliver(const std::vector<std::uint8_t>& bytes, NodeCore& node, Handler handle) {
  Message msg;
  if (!decodeMessage(bytes.data(), bytes.size(), msg)) {
    node.onUndecodable();
    return;
  }
  handle(msg);
}

void checkHypotheses(const pose_hypotheses_t& msg) {
  if (msg.num_hypotheses != static_cast<int>(msg.hypotheses.size())) {
    fuzz::fail("num_hypotheses differs from the array");
  }
  for (const auto& h : msg.hypotheses) {
    bool finite = std::isfinite(h.x) && std::isfinite(h.y) && std::isfinite(h.theta) &&
                  std::isfinite(h.weight);
    for (double c : h.covariance) finite = finite && std::isfinite(c);
    if (!finite) fuzz::fail("non-finite hypothesis published");
  }
}

void checkStatus(const localizer_status_t& msg) {
  if (!std::isfinite(msg.cycle_time_ms)) fuzz::fail("non-finite cycle time in the status");
  if (encoded(msg).empty()) fuzz::fail("status does not encode");
}

NodeCore* node_under_test = nullptr;

}  // namespace

// One NodeCore for the whole run, as on a robot that receives one endless stream: building one
// takes seconds under the sanitizers and it cannot be copied, so state carries over from input
// to input (a finding reproduces by replaying the corpus in order, as fuzz_replay_node does).
extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  static NodeCore node(std::make_shared<const FieldModel>(makeStandardField("spl")),
                       PipelineConfig{},
                       {{"", fuzz::scaledCamera("nao-top", kWidth, kHeight)},
                        {"top", fuzz::scaledCamera("nao-top", kWidth, kHeight)}});
  node_under_test = &node;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (node_under_test == nullptr) LLVMFuzzerInitialize(nullptr, nullptr);
  NodeCore& node = *node_under_test;
  fuzz::ByteReader in(data, size);
  static std::int64_t utime = 1'000'000;  // the stream's clock goes on across inputs
  for (int step = 0; step < 24 && in.remaining() > 0; ++step) {
    const std::uint8_t op = in.byte();
    utime += static_cast<std::int64_t>(in.value<std::int16_t>()) * 100;  // may go backwards
    const int channel = op % 4;
    std::vector<std::uint8_t> bytes;
    if (op & 4) {  // raw bytes off the wire
      const std::size_t length = in.byte();
      for (std::size_t i = 0; i < length && in.remaining() > 0; ++i) bytes.push_back(in.byte());
    } else if (channel == 0) {
      bytes = encoded(fuzzedImage(in, utime));
    } else if (channel == 1) {
      bytes = encoded(fuzzedOdometry(in, utime));
    } else if (channel == 2) {
      bytes = encoded(fuzzedCameraPose(in, utime));
    } else {
      bytes = encoded(fuzzedHint(in, utime));
    }
    if (op & 8 && !bytes.empty()) bytes[in.byte() % bytes.size()] ^= in.byte();  // a bit error
    switch (channel) {
      case 0:
        deliver<image_t>(bytes, node, [&](const image_t& msg) {
          if (const auto out = node.onImage(msg)) checkHypotheses(out->hypotheses);
        });
        break;
      case 1:
        deliver<odometry_t>(bytes, node, [&](const odometry_t& msg) { node.onOdometry(msg); });
        break;
      case 2:
        deliver<camera_pose_t>(bytes, node,
                               [&](const camera_pose_t& msg) { node.onCameraPose(msg); });
        break;
      default:
        deliver<localization_hint_t>(bytes, node,
                                     [&](const localization_hint_t& msg) { node.onHint(msg); });
    }
    checkStatus(node.status());
  }
  return 0;
}
