#include "localization/point_update.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <random>

#include "field_models/field_distance.h"
#include "field_models/standard_fields.h"
#include "localization/feature_index.h"
#include "localization/frame_tilt.h"

namespace houghloc {
namespace {

/// A map with one straight line y = 1 along x.
FieldModel oneLine() {
  FieldModel field;
  field.field_length = 10.0;
  field.field_width = 4.0;
  field.segments.push_back({Eigen::Vector2d(-5.0, 1.0), Eigen::Vector2d(5.0, 1.0)});
  return field;
}

GroundPoints pointsAt(const std::vector<Eigen::Vector2d>& ps) {
  GroundPoints out;
  for (const auto& p : ps) out.points.push_back(GroundPoint{p});
  return out;
}

PointUpdateConfig linearConfig() {
  PointUpdateConfig config;
  config.kernel = PointUpdateConfig::Kernel::kHuber;
  config.kernel_sigmas = 1e9;  // plain least squares: the hand computation is a Kalman update
  return config;
}

TEST(PointUpdate, SingleLineConstraintMatchesKalmanUpdate) {
  const FeatureIndex index(oneLine());
  GaussianPose prior;
  prior.covariance = Eigen::Vector3d(0.04, 0.04, 0.01).asDiagonal();
  // The robot is really at y = -0.1: it sees the line 1.1 m to its left, 5 points at x = -2..2.
  const GroundPoints points = pointsAt({{-2, 1.1}, {-1, 1.1}, {0, 1.1}, {1, 1.1}, {2, 1.1}});
  const PointUpdateConfig config = linearConfig();
  const PointUpdateResult r = updateWithGroundPoints(prior, points.points, index, config);
  ASSERT_TRUE(r.corrected);
  // Residual 0.1 m on each point, J = [0, 1, x_i]. y: Kalman with P = 0.04 against 5 points of
  // variance s^2: y = -0.1 * P / (P + s^2 / 5); theta: information 1/0.01 + sum x_i^2 / s^2.
  const double s2 = config.point_sigma_m * config.point_sigma_m;
  EXPECT_NEAR(r.posterior.mean.y, -0.1 * 0.04 / (0.04 + s2 / 5.0), 1e-9);
  EXPECT_NEAR(r.posterior.mean.x, 0.0, 1e-12);
  EXPECT_NEAR(r.posterior.mean.theta, 0.0, 1e-12);
  EXPECT_NEAR(r.posterior.covariance(1, 1), 1.0 / (1.0 / 0.04 + 5.0 / s2), 1e-12);
  EXPECT_NEAR(r.posterior.covariance(2, 2), 1.0 / (1.0 / 0.01 + 10.0 / s2), 1e-12);
  EXPECT_NEAR(r.posterior.covariance(0, 0), 0.04, 1e-12);  // along the line: prior only
  EXPECT_EQ(r.num_associated, 5);
}

TEST(PointUpdate, GateRejectsPointsThePriorCannotExplain) {
  const FeatureIndex index(oneLine());
  const GroundPoints points = pointsAt({{-2, 1.3}, {-1, 1.3}, {0, 1.3}, {1, 1.3}, {2, 1.3}});
  GaussianPose sharp;
  sharp.covariance = Eigen::Matrix3d::Identity() * 1e-4;  // 1 cm: 0.3 m is 9 sigma away
  const PointUpdateResult rejected =
      updateWithGroundPoints(sharp, points.points, index, linearConfig());
  EXPECT_EQ(rejected.num_associated, 0);
  EXPECT_FALSE(rejected.corrected);
  EXPECT_EQ(rejected.posterior.mean.y, 0.0);
  GaussianPose wide;
  wide.covariance = Eigen::Vector3d(0.04, 0.04, 0.01).asDiagonal();  // 0.3 m is 1.5 sigma
  const PointUpdateResult accepted =
      updateWithGroundPoints(wide, points.points, index, linearConfig());
  EXPECT_EQ(accepted.num_associated, 5);
  EXPECT_LT(accepted.posterior.mean.y, -0.25);
}

TEST(PointUpdate, IteratedUpdateCorrectsTwentyCentimetresInOneFrame) {
  const FieldModel field = makeStandardField("spl");
  const FeatureIndex index(field);
  // Truth at the penalty area corner region, looking at the goal: many directions in view.
  const Pose2 truth(-3.0, 1.0, M_PI);
  GroundPoints points;
  for (double t = 0.0; t <= 1.0; t += 0.01) {
    for (const Segment2& s : field.segments) {
      const Eigen::Vector2d p = truth.inverse().transform(s.a + t * (s.b - s.a));
      if (p.x() > 0.3 && p.norm() < 3.5) points.points.push_back(GroundPoint{p});
    }
  }
  ASSERT_GT(points.size(), 100u);
  GaussianPose prior;
  prior.mean = Pose2(truth.x + 0.14, truth.y - 0.14, truth.theta + 0.05);  // 20 cm, 3 deg off
  prior.covariance = Eigen::Vector3d(0.04, 0.04, 0.01).asDiagonal();
  const PointUpdateResult r = updateWithGroundPoints(prior, points.points, index, {});
  EXPECT_NEAR(r.posterior.mean.x, truth.x, 0.005);
  EXPECT_NEAR(r.posterior.mean.y, truth.y, 0.005);
  EXPECT_NEAR(angleDifference(r.posterior.mean.theta, truth.theta), 0.0, 0.003);
  EXPECT_GT(r.inlier_share, 0.95);
  EXPECT_TRUE(r.posterior.covariance.allFinite());
}

// A global line hypothesis: right line and heading, 1.2 m off along the touch line with a 1.5 m
// std there. Gauss-Newton from the mean cannot reach the crossing lines' fit (each point is
// associated with its nearest line); the start search along the wide axis can.
TEST(PointUpdate, WidePriorAlongALineFindsTheCrossingLines) {
  const FieldModel field = makeStandardField("spl");
  const FeatureIndex index(field);
  const Pose2 truth(-3.0, -2.5, M_PI);  // 0.5 m from the touch line, facing the own goal line
  GroundPoints points;
  for (double t = 0.0; t <= 1.0; t += 0.005) {
    for (const Segment2& s : field.segments) {
      const Eigen::Vector2d p = truth.inverse().transform(s.a + t * (s.b - s.a));
      if (p.x() > 0.3 && p.norm() < 3.5 && std::abs(std::atan2(p.y(), p.x())) < 0.5) {
        points.points.push_back(GroundPoint{p});
      }
    }
  }
  ASSERT_GT(points.size(), 50u);
  GaussianPose prior;
  prior.mean = Pose2(truth.x + 1.2, truth.y, truth.theta);
  prior.covariance = Eigen::Vector3d(1.5 * 1.5, 0.01 * 0.01, 0.01 * 0.01).asDiagonal();
  const PointUpdateResult searched = updateWithGroundPoints(prior, points.points, index, {});
  EXPECT_NEAR(searched.posterior.mean.x, truth.x, 0.01);
  EXPECT_NEAR(searched.posterior.mean.y, truth.y, 0.01);
  EXPECT_LT(std::sqrt(searched.posterior.covariance(0, 0)), 0.05);
  PointUpdateConfig no_search;
  no_search.search_max_starts = 0;
  const PointUpdateResult local = updateWithGroundPoints(prior, points.points, index, no_search);
  EXPECT_GT(std::abs(local.posterior.mean.x - truth.x), 0.3);
  // A prior narrower than search_min_sigma_m does not search: the same as without the search.
  prior.covariance(0, 0) = 0.2 * 0.2;
  const PointUpdateResult narrow = updateWithGroundPoints(prior, points.points, index, {});
  const PointUpdateResult narrow_off =
      updateWithGroundPoints(prior, points.points, index, no_search);
  EXPECT_EQ(narrow.posterior.mean.x, narrow_off.posterior.mean.x);
}

/// Where a camera-frame ray (x forward, y left, z up) meets the ground for a camera 0.5 m up,
/// rolled and pitched down by the given angles (Pose3's Ry(pitch) Rx(roll), yaw 0).
Eigen::Vector2d groundOfRay(const Eigen::Vector3d& ray_camera, double roll, double pitch) {
  const double height = 0.5;
  const Eigen::Vector3d ray = Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                              (Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()) * ray_camera);
  return (height / -ray.z()) * ray.head<2>();
}

/// The SPL lines seen from `truth` by that camera, truly pitched 20 deg down, as a recorded
/// pose pitched `pitch_error` further projects them, each point with its tilt Jacobian under
/// the recorded pose (central differences).
std::vector<GroundPoint> tiltedView(const FieldModel& field, const Pose2& truth,
                                    double pitch_error) {
  const double pitch = 20.0 * M_PI / 180.0, h = 1e-6;
  std::vector<GroundPoint> points;
  for (double t = 0.0; t <= 1.0; t += 0.01) {
    for (const Segment2& s : field.segments) {
      const Eigen::Vector2d g = truth.inverse().transform(s.a + t * (s.b - s.a));
      if (g.x() < 0.4 || g.norm() > 4.0 || std::abs(std::atan2(g.y(), g.x())) > 0.5) continue;
      const Eigen::Vector3d ray_camera =
          Eigen::AngleAxisd(-pitch, Eigen::Vector3d::UnitY()) * Eigen::Vector3d(g.x(), g.y(), -0.5);
      const double recorded = pitch + pitch_error;
      GroundPoint point;
      point.p_robot = groundOfRay(ray_camera, 0.0, recorded);
      point.tilt_jacobian.col(0) =
          (groundOfRay(ray_camera, h, recorded) - groundOfRay(ray_camera, -h, recorded)) / (2 * h);
      point.tilt_jacobian.col(1) = (groundOfRay(ray_camera, 0.0, recorded + h) -
                                    groundOfRay(ray_camera, 0.0, recorded - h)) /
                                   (2 * h);
      points.push_back(point);
    }
  }
  return points;
}

// A camera pitched 2 deg off its recorded pose moves points 2-4 m away by 0.3-0.8 m. The pose
// that odometry holds to a few centimetres must stay there: the fitted tilt explains the points.
TEST(PointUpdate, TiltedCameraIsFittedAsTiltNotAsAMovedRobot) {
  const FieldModel field = makeStandardField("spl");
  const FeatureIndex index(field);
  const Pose2 truth(-2.0, -1.0, M_PI);  // facing the own goal: goal area and penalty area
  const double pitch_error = 2.0 * M_PI / 180.0;
  const std::vector<GroundPoint> tilted = tiltedView(field, truth, pitch_error);
  const std::vector<GroundPoint> exact = tiltedView(field, truth, 0.0);
  ASSERT_GT(tilted.size(), 100u);
  GaussianPose prior;
  prior.mean = truth;
  prior.covariance = Eigen::Vector3d(0.03 * 0.03, 0.03 * 0.03, 0.02 * 0.02).asDiagonal();

  PointUpdateConfig tilt;
  tilt.pitch_sigma_rad = 2.0 * M_PI / 180.0;
  const PointUpdateResult fitted = updateWithGroundPoints(prior, tilted, index, tilt);
  EXPECT_LT((fitted.posterior.mean.translation() - truth.translation()).norm(), 0.01);
  EXPECT_LT(std::abs(angleDifference(fitted.posterior.mean.theta, truth.theta)), 0.003);
  // The recorded pitch is 2 deg too far down: the fit pitches it back up (by 2.4 deg: the
  // points move linearly with the tilt in the model, and a 4 m point's true shift is smaller).
  EXPECT_NEAR(fitted.tilt.y(), -pitch_error, 0.25 * pitch_error);
  EXPECT_NEAR(fitted.tilt.x(), 0.0, 0.1 * pitch_error);
  const PointUpdateResult clean = updateWithGroundPoints(prior, exact, index, tilt);
  EXPECT_GT(fitted.mean_log_likelihood, clean.mean_log_likelihood - 0.05);
  EXPECT_NEAR(clean.tilt.norm(), 0.0, 1e-3);

  PointUpdateConfig held;
  held.pitch_sigma_rad = 0.0;  // the recorded pitch taken as exact
  const PointUpdateResult rigid = updateWithGroundPoints(prior, tilted, index, held);
  EXPECT_EQ(rigid.tilt, Eigen::Vector2d::Zero());
  EXPECT_LT(rigid.mean_log_likelihood, fitted.mean_log_likelihood - 0.3);
  std::printf(
      "tilted camera: pose off by %.4f m, %.3f deg; fitted pitch %.2f deg; mean "
      "log-likelihood %.3f (exact camera %.3f, without the tilt %.3f)\n",
      (fitted.posterior.mean.translation() - truth.translation()).norm(),
      angleDifference(fitted.posterior.mean.theta, truth.theta) * 180.0 / M_PI,
      fitted.tilt.y() * 180.0 / M_PI, fitted.mean_log_likelihood, clean.mean_log_likelihood,
      rigid.mean_log_likelihood);
}

// The first-order move of pointsWithTilt against the projection itself: a 2 deg pitch error
// moves these points (0.4-4 m ahead) by up to 0.44 m; undone by the tilt Jacobian, the farthest
// stay 6.5 cm off where the exact camera puts them (the move grows faster than linearly with
// the angle there), the rest less.
TEST(FrameTilt, PointsWithTiltUndoAPitchError) {
  const FieldModel field = makeStandardField("spl");
  const Pose2 truth(-2.0, -1.0, M_PI);
  const double pitch_error = 2.0 * M_PI / 180.0;
  const std::vector<GroundPoint> tilted = tiltedView(field, truth, pitch_error);
  const std::vector<GroundPoint> exact = tiltedView(field, truth, 0.0);
  ASSERT_EQ(tilted.size(), exact.size());
  const std::vector<GroundPoint> undone =
      pointsWithTilt(tilted, Eigen::Vector2d(0.0, -pitch_error));
  double largest_move = 0.0, largest_error = 0.0;
  for (size_t i = 0; i < exact.size(); ++i) {
    largest_move = std::max(largest_move, (tilted[i].p_robot - exact[i].p_robot).norm());
    largest_error = std::max(largest_error, (undone[i].p_robot - exact[i].p_robot).norm());
  }
  std::printf("2 deg pitch error: points moved by up to %.3f m, %.3f m after pointsWithTilt\n",
              largest_move, largest_error);
  EXPECT_GT(largest_move, 0.3);
  EXPECT_LT(largest_error, 0.2 * largest_move);
}

GaussianPose hypothesisAt(const Pose2& mean, double weight) {
  GaussianPose pose;
  pose.mean = mean;
  pose.covariance = Eigen::Vector3d(0.03 * 0.03, 0.03 * 0.03, 0.02 * 0.02).asDiagonal();
  pose.weight = weight;
  return pose;
}

// The camera_pitch_error fault (docs/reliability.md): the track's camera is 2 deg off, and a
// hypothesis elsewhere must be judged by the same camera, not by a tilt of its own.
TEST(FrameTilt, TheMostProbableHypothesisSetsTheTiltForAll) {
  const FieldModel field = makeStandardField("spl");
  const FeatureIndex index(field);
  const Pose2 truth(-2.0, -1.0, M_PI);
  const std::vector<GroundPoint> tilted = tiltedView(field, truth, 2.0 * M_PI / 180.0);
  const std::vector<GaussianPose> priors = {hypothesisAt(truth, 0.9),
                                            hypothesisAt(Pose2(-2.2, -0.85, M_PI), 0.1)};
  PointUpdateConfig config;
  config.pitch_sigma_rad = 2.0 * M_PI / 180.0;
  const std::vector<PointUpdateResult> frame =
      updateWithOneFrameTilt(priors, tilted, index, config, 8.0);
  ASSERT_EQ(frame.size(), 2u);
  const PointUpdateResult own_track = updateWithGroundPoints(priors[0], tilted, index, config);
  const PointUpdateResult own_other = updateWithGroundPoints(priors[1], tilted, index, config);
  std::printf(
      "own fits: track pitch %.2f deg, mean log-lik %.3f; other %.2f deg, %.3f; other at "
      "the track's tilt %.3f\n",
      own_track.tilt.y() * 180.0 / M_PI, own_track.mean_log_likelihood,
      own_other.tilt.y() * 180.0 / M_PI, own_other.mean_log_likelihood,
      frame[1].mean_log_likelihood);
  // Not vacuous: the other hypothesis would fit a tilt of its own.
  ASSERT_GT((own_other.tilt - own_track.tilt).norm(), 0.1 * M_PI / 180.0);
  EXPECT_EQ(frame[0].tilt, own_track.tilt);
  EXPECT_EQ(frame[0].posterior.mean.translation(), own_track.posterior.mean.translation());
  EXPECT_EQ(frame[1].tilt, own_track.tilt);
  EXPECT_LE(frame[1].mean_log_likelihood, own_other.mean_log_likelihood);
}

// The other way round: a view the exact camera explains at the truth; a more probable-looking
// hypothesis elsewhere that only a tilt makes fit must not lend the frame that tilt.
TEST(FrameTilt, AWrongPlaceGetsNoTiltThatTheTruthDoesNotNeed) {
  const FieldModel field = makeStandardField("spl");
  const FeatureIndex index(field);
  const Pose2 truth(-2.0, -1.0, M_PI);
  const std::vector<GroundPoint> exact = tiltedView(field, truth, 0.0);
  const std::vector<GaussianPose> priors = {hypothesisAt(Pose2(-2.25, -1.0, M_PI), 0.6),
                                            hypothesisAt(truth, 0.4)};
  PointUpdateConfig config;
  config.pitch_sigma_rad = 2.0 * M_PI / 180.0;
  const PointUpdateResult own_wrong = updateWithGroundPoints(priors[0], exact, index, config);
  std::printf("wrong place: own pitch %.2f deg, mean log-lik %.3f\n",
              own_wrong.tilt.y() * 180.0 / M_PI, own_wrong.mean_log_likelihood);
  ASSERT_FALSE(own_wrong.tilt.isZero());  // not vacuous: alone it would take a tilt
  const std::vector<PointUpdateResult> frame =
      updateWithOneFrameTilt(priors, exact, index, config, 8.0);
  PointUpdateConfig held = config;
  held.pitch_sigma_rad = 0.0;
  const PointUpdateResult rigid_wrong = updateWithGroundPoints(priors[0], exact, index, held);
  EXPECT_EQ(frame[1].tilt, Eigen::Vector2d::Zero());
  EXPECT_EQ(frame[0].tilt, Eigen::Vector2d::Zero());
  EXPECT_EQ(frame[0].mean_log_likelihood, rigid_wrong.mean_log_likelihood);
  EXPECT_LT(frame[0].mean_log_likelihood, own_wrong.mean_log_likelihood);
  EXPECT_GT(frame[1].mean_log_likelihood, frame[0].mean_log_likelihood + 0.5);
}

// Points from another team's vision may carry a broken Jacobian: they still count as points,
// but say nothing about the tilt, and nothing turns NaN.
TEST(FrameTilt, NonFiniteTiltJacobiansAreIgnored) {
  const FieldModel field = makeStandardField("spl");
  const FeatureIndex index(field);
  const Pose2 truth(-2.0, -1.0, M_PI);
  std::vector<GroundPoint> points = tiltedView(field, truth, 2.0 * M_PI / 180.0);
  for (size_t i = 0; i < points.size(); i += 3) {
    points[i].tilt_jacobian(i % 2, 1) = i % 2 ? std::nan("") : INFINITY;
  }
  PointUpdateConfig config;
  config.pitch_sigma_rad = 2.0 * M_PI / 180.0;
  const std::vector<PointUpdateResult> frame = updateWithOneFrameTilt(
      {hypothesisAt(truth, 0.7), hypothesisAt(Pose2(-2.2, -0.85, M_PI), 0.3)}, points, index,
      config, 8.0);
  for (const PointUpdateResult& r : frame) {
    EXPECT_TRUE(r.posterior.isFinite());
    EXPECT_TRUE(r.tilt.allFinite());
    EXPECT_TRUE(std::isfinite(r.mean_log_likelihood));
    EXPECT_EQ(r.num_points, static_cast<int>(points.size()));
  }
  // The other two thirds still show the tilt; the third whose Jacobian is broken stays 2 deg
  // off and pulls the fit to about half of it (measured -1.06 deg, 8 cm off the truth).
  EXPECT_LT(frame[0].tilt.y(), -0.5 * M_PI / 180.0);
  EXPECT_GT(frame[0].tilt.y(), -3.0 * M_PI / 180.0);
  for (const GroundPoint& p : pointsWithTilt(points, frame[0].tilt)) {
    EXPECT_TRUE(p.p_robot.allFinite());
  }
}

class FeatureIndexExact : public ::testing::TestWithParam<const char*> {};

TEST_P(FeatureIndexExact, MatchesBruteForceNearestFeature) {
  const FieldModel field = makeStandardField(GetParam());
  const FeatureIndex index(field);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(-field.outerHalfLength(), field.outerHalfLength());
  std::uniform_real_distribution<double> uy(-field.outerHalfWidth(), field.outerHalfWidth());
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector2d p(ux(rng), uy(rng));
    Association a;
    ASSERT_TRUE(index.associate(p, &a));
    EXPECT_NEAR(a.distance_m, nearestFeature(field, p).distance_m, 1e-9) << p.transpose();
  }
  Association a;
  EXPECT_FALSE(index.associate(Eigen::Vector2d(100.0, 0.0), &a));
  EXPECT_FALSE(index.associate(Eigen::Vector2d(std::nan(""), 0.0), &a));
}

INSTANTIATE_TEST_SUITE_P(Fields, FeatureIndexExact,
                         ::testing::Values("spl", "spl2019", "kid", "adult", "msl"));

}  // namespace
}  // namespace houghloc
