#include "vision/camera_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <random>

#include "field_models/angles.h"
#include "vision/camera_presets.h"

namespace houghloc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

class PresetTest : public ::testing::TestWithParam<std::string> {
 protected:
  CameraModel camera() const {
    const CameraPreset preset = cameraPreset(GetParam());
    return CameraModel(preset.intrinsics, preset.robot_T_camera);
  }
};

/// OpenCV's rvec/tvec (robot frame -> optical frame), built independently of CameraModel from
/// DESIGN §3: p_cam = R^T (p_robot - t), optical = (-y_cam, -z_cam, x_cam).
void opencvExtrinsics(const Pose3& robot_T_camera, cv::Mat* rvec, cv::Mat* tvec) {
  const Eigen::Matrix3d optical_R_camera =
      (Eigen::Matrix3d() << 0, -1, 0, 0, 0, -1, 1, 0, 0).finished();
  const Eigen::Matrix3d optical_R_robot = optical_R_camera * robot_T_camera.rotation().transpose();
  const Eigen::Vector3d t = -optical_R_robot * robot_T_camera.translation();
  cv::Matx33d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = optical_R_robot(i, j);
  cv::Rodrigues(cv::Mat(r), *rvec);
  *tvec = (cv::Mat_<double>(3, 1) << t.x(), t.y(), t.z());
}

std::vector<cv::Point2d> opencvProject(const CameraModel& camera,
                                       const std::vector<cv::Point3d>& points) {
  cv::Mat rvec, tvec;
  opencvExtrinsics(camera.pose(), &rvec, &tvec);
  std::vector<cv::Point2d> pixels;
  const CameraIntrinsics& in = camera.intrinsics();
  if (in.model == DistortionModel::kFisheye) {
    cv::fisheye::projectPoints(points, pixels, rvec, tvec, in.camera_matrix, in.distortion);
  } else {
    cv::projectPoints(points, rvec, tvec, in.camera_matrix, in.distortion, pixels);
  }
  return pixels;
}

TEST_P(PresetTest, PixelGroundPixelRoundTripBelowOneHundredthPixel) {
  const CameraModel cam = camera();
  double worst = 0.0;
  int valid = 0, total = 0;
  for (int v = 0; v < cam.height(); v += 6) {
    for (int u = 0; u < cam.width(); u += 6) {
      ++total;
      const double pu = u + 0.37, pv = v + 0.61;  // off the integer grid
      const auto ground = cam.pixelToGround(pu, pv);
      if (!ground) continue;
      ++valid;
      const auto pixel = cam.project(Eigen::Vector3d(ground->x(), ground->y(), 0.0));
      ASSERT_TRUE(pixel) << pu << "," << pv;
      worst = std::max(worst, (*pixel - Eigen::Vector2d(pu, pv)).norm());
    }
  }
  std::cout << GetParam() << ": worst round trip " << worst << " px over " << valid << " of "
            << total << " pixels\n";
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(valid, total / 2);
}

TEST_P(PresetTest, ProjectionMatchesOpenCv) {
  const CameraModel cam = camera();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(-1.0, 8.0), y(-6.0, 6.0), z(-0.5, 2.5);
  std::vector<cv::Point3d> points;
  std::vector<Eigen::Vector2d> ours;
  while (points.size() < 500) {
    const Eigen::Vector3d p(x(rng), y(rng), z(rng));
    const auto pixel = cam.project(p);
    if (!pixel ||
        (*pixel - Eigen::Vector2d(cam.width() / 2.0, cam.height() / 2.0)).norm() > cam.width()) {
      continue;
    }
    points.emplace_back(p.x(), p.y(), p.z());
    ours.push_back(*pixel);
  }
  const std::vector<cv::Point2d> reference = opencvProject(cam, points);
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    worst = std::max(worst, std::hypot(ours[i].x() - reference[i].x, ours[i].y() - reference[i].y));
  }
  EXPECT_LT(worst, 1e-6);
}

TEST_P(PresetTest, PixelRayMatchesOpenCvUndistortion) {
  const CameraModel cam = camera();
  const CameraIntrinsics& in = cam.intrinsics();
  std::vector<cv::Point2d> pixels;
  for (int v = 0; v < cam.height(); v += 37)
    for (int u = 0; u < cam.width(); u += 41) pixels.emplace_back(u, v);
  std::vector<cv::Point2d> normalized;
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 200, 1e-15);
  if (in.model == DistortionModel::kFisheye) {
    cv::fisheye::undistortPoints(pixels, normalized, in.camera_matrix, in.distortion, cv::noArray(),
                                 cv::noArray(), criteria);
  } else {
    cv::undistortPoints(pixels, normalized, in.camera_matrix, in.distortion, cv::noArray(),
                        cv::noArray(), criteria);
  }
  cv::Mat rvec, tvec;
  opencvExtrinsics(cam.pose(), &rvec, &tvec);
  cv::Matx33d r;
  cv::Rodrigues(rvec, r);
  const double f = in.camera_matrix(0, 0);
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const Eigen::Vector3d ray = cam.pixelRay(pixels[i].x, pixels[i].y);
    ASSERT_NEAR(ray.norm(), 1.0, 1e-12);
    const cv::Vec3d ray_optical = r * cv::Vec3d(ray.x(), ray.y(), ray.z());
    EXPECT_NEAR(f * ray_optical[0] / ray_optical[2], f * normalized[i].x, 1e-4);
    EXPECT_NEAR(f * ray_optical[1] / ray_optical[2], f * normalized[i].y, 1e-4);
  }
}

TEST_P(PresetTest, HorizonSeparatesGroundFromSky) {
  const CameraModel cam = camera();
  ASSERT_EQ(static_cast<int>(cam.horizonRows().size()), cam.width());
  for (int u = 0; u < cam.width(); u += 3) {
    const double h = cam.horizonRows()[u];
    ASSERT_FALSE(std::isnan(h));
    if (std::isinf(h)) {
      // The whole column is on one side: check its ends.
      EXPECT_EQ(cam.pixelRay(u, 0).z() < 0.0, h < 0.0) << u;
      EXPECT_EQ(cam.pixelRay(u, cam.height() - 1).z() < 0.0, h < 0.0) << u;
      continue;
    }
    EXPECT_NEAR(cam.pixelRay(u, h).z(), 0.0, 1e-9) << u;
    EXPECT_LT(cam.pixelRay(u, h + 0.05).z(), 0.0) << u;
    EXPECT_GT(cam.pixelRay(u, h - 0.05).z(), 0.0) << u;
    EXPECT_FALSE(cam.pixelToGround(u, h - 0.05));
    EXPECT_FALSE(cam.pixelToGround(u, h - 20.0));
  }
}

TEST_P(PresetTest, RejectsPointsBehindTheCameraAndBadInput) {
  const CameraModel cam = camera();
  const Pose3& pose = cam.pose();
  const Eigen::Vector3d behind = pose.transform(Eigen::Vector3d(-1.0, 0.1, 0.2));
  EXPECT_FALSE(cam.project(behind));
  EXPECT_FALSE(cam.project(pose.transform(Eigen::Vector3d(0.0, 1.0, 0.0))));  // 90 deg off-axis
  EXPECT_FALSE(cam.project(pose.translation()));
  EXPECT_FALSE(cam.project(Eigen::Vector3d(kNaN, 0.0, 0.0)));
  EXPECT_FALSE(cam.pixelToGround(kNaN, 100.0));
  EXPECT_FALSE(cam.pixelToGround(100.0, std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(cam.pixelToGround(1e9, 1e9));
  EXPECT_FALSE(cam.pixelToGround(-1e6, 5e5));
  EXPECT_TRUE(cam.pixelRay(kNaN, 0.0).hasNaN());
  EXPECT_FALSE(cam.expectedLineWidthPx(kNaN, 1.0, 0.05));
  EXPECT_FALSE(cam.expectedLineWidthPx(cam.width() / 2.0, cam.height() - 1.0, kNaN));
  // Beyond the configured range: the ground point exists but is rejected.
  const double u = cam.width() / 2.0, v = cam.height() / 2.0;
  const auto centre = cam.pixelToGround(u, v);
  ASSERT_TRUE(centre);
  CameraModelConfig near;
  near.max_ground_range_m = 0.9 * centre->norm();
  EXPECT_FALSE(CameraModel(cam.intrinsics(), cam.pose(), near).pixelToGround(u, v));
}

TEST_P(PresetTest, ExpectedLineWidthMatchesTwoPointProjection) {
  const CameraModel cam = camera();
  const double width_m = 0.05;
  for (double fv : {0.55, 0.75, 0.95}) {
    for (double fu : {0.1, 0.5, 0.9}) {
      const double u = fu * cam.width(), v = fv * cam.height();
      const auto expected = cam.expectedLineWidthPx(u, v, width_m);
      const auto g = cam.pixelToGround(u, v);
      ASSERT_TRUE(expected && g) << u << "," << v;
      // Direct: ground direction of the row and column from neighbouring pixels, the line's
      // edges half a width either side, projected by OpenCV.
      for (int axis = 0; axis < 2; ++axis) {
        const auto a = cam.pixelToGround(u + (axis == 0), v + (axis == 1));
        const auto b = cam.pixelToGround(u - (axis == 0), v - (axis == 1));
        ASSERT_TRUE(a && b);
        const Eigen::Vector2d d = (*a - *b).normalized() * (width_m / 2.0);
        const std::vector<cv::Point3d> edges = {{g->x() + d.x(), g->y() + d.y(), 0.0},
                                                {g->x() - d.x(), g->y() - d.y(), 0.0}};
        const std::vector<cv::Point2d> px = opencvProject(cam, edges);
        const double direct = std::hypot(px[0].x - px[1].x, px[0].y - px[1].y);
        EXPECT_NEAR((*expected)[axis], direct, 1e-3 * direct + 1e-4)
            << GetParam() << " " << u << "," << v;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllPresets, PresetTest, ::testing::ValuesIn(cameraPresetNames()),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST(CameraModel, LineWidthOfUndistortedCameraMatchesPinholeFormula) {
  CameraIntrinsics in;  // 640x480, f = 500, no distortion
  in.camera_matrix = cv::Matx33d(500, 0, 320, 0, 500, 240, 0, 0, 1);
  Pose3 pose;
  pose.z = 0.5;
  pose.pitch = 0.4;
  const CameraModel cam(in, pose);
  // In the centre column the row runs along the robot's y axis: a line along x of width w at
  // optical depth z spans f w / z pixels.
  const double v = 400.0;
  const auto g = cam.pixelToGround(320.0, v);
  ASSERT_TRUE(g);
  const double depth = std::cos(pose.pitch) * g->x() + std::sin(pose.pitch) * pose.z;
  const auto width = cam.expectedLineWidthPx(320.0, v, 0.05);
  ASSERT_TRUE(width);
  EXPECT_NEAR(width->x(), 500.0 * 0.05 / depth, 1e-6);
  // Horizon of a level-rolled pinhole camera: row cy - f tan(pitch) in every column.
  for (double h : cam.horizonRows()) EXPECT_NEAR(h, 240.0 - 500.0 * std::tan(0.4), 1e-6);
}

TEST(CameraModel, HorizonOfRolledCameraIsSloped) {
  CameraPreset preset = cameraPreset("kid-wide");
  preset.robot_T_camera.roll = 0.15;
  preset.robot_T_camera.yaw = 0.3;
  const CameraModel cam(preset.intrinsics, preset.robot_T_camera);
  const std::vector<double>& h = cam.horizonRows();
  EXPECT_GT(std::abs(h.front() - h.back()), 50.0);
  for (int u = 0; u < cam.width(); u += 7) {
    if (!std::isfinite(h[u])) continue;
    EXPECT_LT(cam.pixelRay(u, h[u] + 0.05).z(), 0.0) << u;
    EXPECT_GT(cam.pixelRay(u, h[u] - 0.05).z(), 0.0) << u;
  }
}

// The presets use 5 coefficients; the rational (8) and thin-prism (12) terms are checked here
// against OpenCV in both directions.
TEST(CameraModel, RationalAndThinPrismModelsMatchOpenCv) {
  for (const std::vector<double>& distortion :
       {std::vector<double>{-0.3, 0.1, 0.001, -0.002, -0.01, 0.05, 0.01, 0.002},
        std::vector<double>{-0.2, 0.05, 0.0015, 0.001, 0.0, 0.02, 0.0, 0.0, 0.002, -0.001, 0.0015,
                            0.0005}}) {
    CameraIntrinsics in;
    in.image_width = 800;
    in.image_height = 600;
    in.camera_matrix = cv::Matx33d(520, 0, 401.3, 0, 515, 297.8, 0, 0, 1);
    in.distortion = distortion;
    Pose3 pose;
    pose.z = 0.7;
    pose.pitch = 0.45;
    pose.roll = 0.05;
    const CameraModel cam(in, pose);
    std::vector<cv::Point2d> pixels;
    for (int v = 0; v < 600; v += 23)
      for (int u = 0; u < 800; u += 29) pixels.emplace_back(u + 0.25, v + 0.75);
    std::vector<cv::Point2d> normalized;
    cv::undistortPoints(
        pixels, normalized, in.camera_matrix, in.distortion, cv::noArray(), cv::noArray(),
        cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 500, 1e-15));
    cv::Mat rvec, tvec;
    opencvExtrinsics(pose, &rvec, &tvec);
    cv::Matx33d r;
    cv::Rodrigues(rvec, r);
    std::vector<cv::Point3d> points;
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      const Eigen::Vector3d ray = cam.pixelRay(pixels[i].x, pixels[i].y);
      ASSERT_FALSE(ray.hasNaN());
      const cv::Vec3d o = r * cv::Vec3d(ray.x(), ray.y(), ray.z());
      EXPECT_NEAR(520.0 * o[0] / o[2], 520.0 * normalized[i].x, 1e-4);
      EXPECT_NEAR(515.0 * o[1] / o[2], 515.0 * normalized[i].y, 1e-4);
      const Eigen::Vector3d p = pose.translation() + 2.0 * ray;
      points.emplace_back(p.x(), p.y(), p.z());
    }
    // Points 2 m along each ray project back onto their pixel, by OpenCV and by CameraModel.
    const std::vector<cv::Point2d> reference = opencvProject(cam, points);
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      const auto pixel = cam.project(Eigen::Vector3d(points[i].x, points[i].y, points[i].z));
      ASSERT_TRUE(pixel);
      EXPECT_NEAR(reference[i].x, pixels[i].x, 1e-6);
      EXPECT_NEAR(reference[i].y, pixels[i].y, 1e-6);
      EXPECT_NEAR(pixel->x(), pixels[i].x, 1e-6);
      EXPECT_NEAR(pixel->y(), pixels[i].y, 1e-6);
    }
  }
}

TEST(CameraModel, ArbitraryPosesAndPixelsNeverCrashOrReturnNonFinite) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-4.0, 4.0), offset(-2.0, 2.0);
  const double specials[] = {kNaN, std::numeric_limits<double>::infinity(), -1e300, -5e3, 0.0, 5e3,
                             1e300};
  for (const std::string& name : cameraPresetNames()) {
    const CameraPreset preset = cameraPreset(name);
    for (int trial = 0; trial < 30; ++trial) {
      Pose3 pose{offset(rng), offset(rng), offset(rng), angle(rng), angle(rng), angle(rng)};
      if (trial == 0) pose.pitch = kNaN;
      const CameraModel cam(preset.intrinsics, pose);
      ASSERT_EQ(static_cast<int>(cam.horizonRows().size()), cam.width());
      for (double h : cam.horizonRows()) EXPECT_FALSE(std::isnan(h));
      for (double u : specials) {
        for (double v : specials) {
          const auto g = cam.pixelToGround(u, v);
          const auto w = cam.expectedLineWidthPx(u, v, 0.05);
          const auto p = cam.project(Eigen::Vector3d(u, v, 0.0));
          EXPECT_TRUE(!g || g->allFinite());
          EXPECT_TRUE(!w || w->allFinite());
          EXPECT_TRUE(!p || p->allFinite());
        }
      }
    }
  }
}

TEST(CameraModel, InvalidIntrinsicsThrow) {
  CameraIntrinsics in;
  in.distortion = {0.1, 0.2, 0.3};
  EXPECT_THROW(CameraModel(in, Pose3{}), std::invalid_argument);
  in.distortion = {};
  in.camera_matrix(0, 0) = -1.0;
  EXPECT_THROW(CameraModel(in, Pose3{}), std::invalid_argument);
  in.camera_matrix(0, 0) = 500.0;
  in.model = DistortionModel::kFisheye;
  in.distortion = {0.1, 0.2, 0.3, 0.4, 0.5};
  EXPECT_THROW(CameraModel(in, Pose3{}), std::invalid_argument);
}

TEST(CameraPresets, NumbersMatchTheDocumentedCameras) {
  auto horizontalFov = [](const CameraModel& cam) {
    // Angle between the rays of the left and right image borders in the central row.
    const double v = cam.intrinsics().camera_matrix(1, 2);
    return std::acos(cam.pixelRay(-0.5, v).dot(cam.pixelRay(cam.width() - 0.5, v))) * 180 / kPi;
  };
  auto make = [](const std::string& name) {
    const CameraPreset p = cameraPreset(name);
    return CameraModel(p.intrinsics, p.robot_T_camera);
  };
  const CameraModel top = make("nao-top"), bottom = make("nao-bottom");
  const CameraModel kid = make("kid-wide"), adult = make("adult");
  EXPECT_NEAR(horizontalFov(top), 56.0, 2.0);
  EXPECT_NEAR(top.pose().z, 0.5, 0.05);
  EXPECT_NEAR(bottom.pose().pitch - top.pose().pitch, 40.0 * kPi / 180, 4.0 * kPi / 180);
  EXPECT_GT(horizontalFov(kid), 100.0);
  EXPECT_EQ(kid.intrinsics().model, DistortionModel::kFisheye);
  EXPECT_EQ(kid.width(), 1280);
  EXPECT_EQ(adult.height(), 720);
  EXPECT_NEAR(kid.pose().z, 0.9, 0.05);
  EXPECT_NEAR(adult.pose().z, 1.4, 0.05);
  // The bottom camera sees the toes (x ~ 0.1 m) and hands over to the top camera near 0.55 m.
  const auto bottom_edge = bottom.pixelToGround(320.0, 479.0);
  ASSERT_TRUE(bottom_edge);
  EXPECT_LT(bottom_edge->x(), 0.09);
  const auto top_edge = top.pixelToGround(320.0, 479.0);
  const auto bottom_top_edge = bottom.pixelToGround(320.0, 0.0);
  ASSERT_TRUE(top_edge && bottom_top_edge);
  EXPECT_NEAR(top_edge->x(), 0.60, 0.02);
  EXPECT_NEAR(bottom_top_edge->x(), top_edge->x(), 0.1);
  // Horizon inside the image for the forward-looking cameras, above it for nao-bottom.
  EXPECT_GT(top.horizonRows()[320], 0.0);
  EXPECT_GT(kid.horizonRows()[640], 0.0);
  EXPECT_LT(bottom.horizonRows()[320], 0.0);
  EXPECT_THROW(cameraPreset("nao-middle"), std::invalid_argument);
  try {
    cameraPreset("nao-middle");
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("nao-middle"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("kid-wide"), std::string::npos);
  }
}

}  // namespace
}  // namespace houghloc
