// The Localizer on arbitrary ground points, odometry, camera poses and hints. The input is a
// sequence of steps; each step's first byte chooses a frame (points, odometry, camera pose,
// time step) or a hint. Coordinates are small numbers mostly and raw doubles (NaN, infinity,
// 1e308) sometimes. Every estimate must be finite, with at most max_hypotheses hypotheses whose
// weights sum to one.
#include <cmath>
#include <exception>

#include "field_models/standard_fields.h"
#include "localization/localizer.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using namespace houghloc;

void checkEstimate(const LocalizationEstimate& estimate, const LocalizerConfig& config) {
  if (static_cast<int>(estimate.hypotheses.size()) > config.tracker.set.max_hypotheses) {
    fuzz::fail("too many hypotheses: " + std::to_string(estimate.hypotheses.size()));
  }
  double weights = 0.0;
  for (const auto& h : estimate.hypotheses) {
    if (!h.pose.isFinite()) fuzz::fail("non-finite hypothesis");
    weights += h.pose.weight;
  }
  if (!estimate.hypotheses.empty() && std::abs(weights - 1.0) > 1e-6) {
    fuzz::fail("weights sum to " + std::to_string(weights));
  }
}

GaussianPose pose(fuzz::ByteReader& in) {
  GaussianPose p;
  p.mean = Pose2(in.smallDouble(6.0), in.smallDouble(4.0), in.smallDouble(4.0));
  const double sigma = in.smallDouble(1.0);
  p.covariance = Eigen::Matrix3d::Identity() * sigma * sigma;
  return p;
}

}  // namespace

namespace {
// One Localizer built once, before the fuzzing starts (tens of ms in Release, over 12 s with
// the sanitizers on a loaded machine: libFuzzer's per-input timeout fired on the first input
// when it was built there); each input runs on a copy, so inputs do not interact.
const Localizer* prototype = nullptr;
}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  static const Localizer localizer(makeStandardField("spl"));
  prototype = &localizer;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (prototype == nullptr) LLVMFuzzerInitialize(nullptr, nullptr);
  Localizer localizer = *prototype;
  fuzz::ByteReader in(data, size);
  std::int64_t t_us = 0;
  Pose2 odometry;
  for (int step = 0; step < 40 && in.remaining() > 0; ++step) {
    const std::uint8_t op = in.byte();
    if (op % 8 == 7) {
      LocalizationHint hint;
      hint.kind = static_cast<HintKind>((op / 8) % 5);
      hint.t_us = t_us;
      for (int i = in.byte() % 3; i > 0; --i) hint.poses.push_back(pose(in));
      localizer.applyHint(hint);
      checkEstimate(localizer.estimate(), localizer.config());
      continue;
    }
    t_us += static_cast<std::int64_t>(in.value<std::int16_t>()) * 100;  // may go backwards
    odometry = Pose2(odometry.x + in.smallDouble(0.2), odometry.y + in.smallDouble(0.2),
                     odometry.theta + in.smallDouble(0.5));
    std::optional<Pose2> odometry_in;
    if (op & 1) odometry_in = odometry;
    std::vector<Pose3> cameras;
    if (op & 2) {
      Pose3 camera;
      camera.z = 0.5 + in.smallDouble(0.5);
      camera.pitch = in.smallDouble(2.0);
      camera.roll = in.smallDouble(2.0);
      cameras.push_back(camera);
    }
    GroundPoints points;
    points.t_us = t_us;
    const int n = in.byte() % 64;
    for (int i = 0; i < n && in.remaining() > 0; ++i) {
      GroundPoint p;
      p.p_robot = Eigen::Vector2d(in.smallDouble(8.0), in.smallDouble(8.0));
      if (op & 4) p.weight = in.smallDouble(2.0);
      // How a camera tilt moves the point, m/rad (a far point 0.5 m below the camera: ~50).
      if (op & 32) {
        for (int k = 0; k < 4; ++k) p.tilt_jacobian(k / 2, k % 2) = in.smallDouble(60.0);
      }
      points.points.push_back(p);
    }
    if (op & 8) {
      GroundPolygon region;
      for (int i = 0; i < 4; ++i) region.emplace_back(in.smallDouble(5.0), in.smallDouble(5.0));
      points.visible_regions.push_back(region);
    }
    if (op & 16) {
      FieldEdgePoint edge;
      edge.p_robot = Eigen::Vector2d(in.smallDouble(8.0), in.smallDouble(8.0));
      edge.range_sigma_m = in.smallDouble(1.0);
      points.field_edge.push_back(edge);
    }
    checkEstimate(localizer.process(t_us, odometry_in, cameras, points), localizer.config());
  }
  return 0;
}
