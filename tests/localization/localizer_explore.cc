#include <cstdio>
#include <cstring>
#include <random>
#include "field_models/standard_fields.h"
#include "tests/localization/localizer_test_support.h"
#include "localization/point_update.h"
#include "localization/feature_index.h"
using namespace houghloc;
int main(int argc, char** argv) {
  const char* mode = argc > 1 ? argv[1] : "fall";
  const FieldModel field = makeStandardField("spl");
  testing::ScenarioConfig config = testing::walkOn(field, 330, 13);
  const int fall = 120, up = 180;
  std::vector<testing::ScenarioFrame> walk = testing::makeScenario(field, config);
  const Pose2 lying = walk[fall].field_T_robot;
  config.kidnap_frame = up;
  config.kidnap_to = lying * Pose2(0.0, 0.0, 0.6);
  const auto after = testing::makeScenario(field, config);
  if (!strcmp(mode, "nan") || !strcmp(mode, "back")) { walk = testing::makeScenario(field, testing::walkOn(field, 360, 17)); }
  Localizer loc(field);
  LocalizationHint h; h.kind = HintKind::kResetTo; GaussianPose g; g.mean = walk[0].field_T_robot;
  g.covariance = Eigen::Vector3d(0.01, 0.01, 0.003).asDiagonal(); h.poses = {g}; loc.applyHint(h);
  Pose3 fc; fc.z = 0.1; fc.pitch = -1.4;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> garbage(-5.0, 5.0);
  for (int k = 0; k < (int)walk.size(); ++k) {
    bool lying_down = !strcmp(mode, "fall") && k >= fall && k < up;
    const auto& f = (!strcmp(mode, "fall") && k >= up) ? after[k] : walk[k];
    LocalizationEstimate e;
    std::optional<Pose2> odo = f.odometry;
    if (!strcmp(mode, "nan") && k >= 50 && k < 150) odo = Pose2(NAN, 0, 0);
    std::int64_t t = f.t_us;
    if (!strcmp(mode, "back") && k >= 100 && k < 110) t -= 2000000;
    if (!strcmp(mode, "back") && k >= 200) t -= 5000000;
    if (lying_down) {
      GroundPoints points;
      for (int i = 0; i < 50; ++i) points.points.push_back({{garbage(rng), garbage(rng)}});
      e = loc.process(f.t_us, Pose2(garbage(rng), garbage(rng), garbage(rng)), {fc}, points);
    } else e = loc.process(t, odo, {testing::uprightCamera()}, f.points);
    const auto b = e.best();
    if (b) fprintf(stderr, "DBG %d %d %zu %.9f %.9f\n", k, e.global_ran, e.hypotheses.size(), b->mean.x, b->mean.y);
    const bool two = testing::seesTwoDirections(field, f.field_T_robot, f.points);
    printf("%3d %s two=%d glob=%d n=%zu ok=%d", k, trackerStatusName(e.status), two,
           e.global_ran, e.hypotheses.size(), testing::estimateCorrect(e, f.field_T_robot));
    if (b) printf(" best=(%.2f %.2f %.2f) w=%.2f sd=%.2f,%.2f truth=(%.2f %.2f %.2f) used=%d/%d", b->mean.x, b->mean.y, b->mean.theta, b->weight,
                  std::sqrt(b->covariance(0,0)), std::sqrt(b->covariance(2,2)),
                  f.field_T_robot.x, f.field_T_robot.y, f.field_T_robot.theta, e.points_used, e.points_in);
    int any = -1; for (size_t i = 0; i < e.hypotheses.size(); ++i) if (any < 0 && testing::correctUpToSymmetry(e.hypotheses[i].pose.mean, f.field_T_robot)) any = i;
    printf(" any=%d", any);
    if (b && !testing::estimateCorrect(e, f.field_T_robot)) {
      static FeatureIndex index(field, FeatureIndexConfig{});
      GaussianPose t; t.mean = f.field_T_robot; t.covariance = Eigen::Vector3d(1e-4, 1e-4, 1e-5).asDiagonal();
      GaussianPose w = *b; w.covariance = t.covariance;
      const auto rt = updateWithGroundPoints(t, f.points.points, index, PointUpdateConfig{});
      const auto rw = updateWithGroundPoints(w, f.points.points, index, PointUpdateConfig{});
      printf(" llT=%.3f inT=%.2f llW=%.3f inW=%.2f", rt.mean_log_likelihood, rt.inlier_share, rw.mean_log_likelihood, rw.inlier_share);
    }
    if (any >= 0) printf(" w_any=%.3f", e.hypotheses[any].pose.weight);
    printf("\n");
  }
}
