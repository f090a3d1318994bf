#include "localization/hypothesis_tracker.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "localization/frame_tilt.h"
#include "localization/point_update.h"

namespace houghloc {

const char* trackerStatusName(TrackerStatus status) {
  switch (status) {
    case TrackerStatus::kInitializing:
      return "INITIALIZING";
    case TrackerStatus::kTracking:
      return "TRACKING";
    case TrackerStatus::kAmbiguous:
      return "AMBIGUOUS";
    case TrackerStatus::kLost:
      return "LOST";
  }
  return "LOST";
}

namespace {

/// CUSUM of the inlier share's drop below its running mean (TrackerConfig::share_drop_*).
void trackInlierShare(const TrackerConfig& config, double share, TrackedHypothesis* h) {
  if (h->expected_inlier_share < 0.0) {
    h->expected_inlier_share = share;
    return;
  }
  h->share_drop =
      std::max(0.0, h->share_drop + h->expected_inlier_share - share - config.share_drop_slack);
  h->expected_inlier_share +=
      std::clamp(config.expected_share_rate, 0.0, 1.0) * (share - h->expected_inlier_share);
}

}  // namespace

HypothesisTracker::HypothesisTracker(const FieldModel& field, const TrackerConfig& config)
    : HypothesisTracker(std::make_shared<const FeatureIndex>(field, config.index), config) {}

HypothesisTracker::HypothesisTracker(std::shared_ptr<const FeatureIndex> index,
                                     const TrackerConfig& config)
    : config_(config),
      index_(index ? std::move(index) : std::make_shared<const FeatureIndex>()),
      odometry_(config.odometry) {}

void HypothesisTracker::update(std::int64_t t_us, const std::optional<Pose2>& odometry,
                               const GroundPoints& points) {
  predict(t_us, odometry);
  correct(points);
}

void HypothesisTracker::predict(std::int64_t t_us, const std::optional<Pose2>& odometry) {
  const MotionStep step = odometry_.step(t_us, odometry);
  stats_.odometry_jump = step.jump;
  stats_.time_backwards = step.time_backwards;
  jump_since_injection_ = jump_since_injection_ || step.jump;
  seconds_since_injection_ += step.dt_s;
  stats_.seconds_without_points += step.dt_s;
  blind_since_injection_ =
      blind_since_injection_ || stats_.seconds_without_points > config_.lost_without_points_s;
  auto move = [&](GaussianPose* pose) {
    if (step.has_motion) predictWithMotion(step.motion, step.dt_s, config_.motion, pose);
    if (step.unknown_s > 0.0) inflateUnknownMotion(step.unknown_s, config_.motion, pose);
  };
  for (TrackedHypothesis& h : hypotheses_) {
    move(&h.pose);
    ++h.age_frames;
  }
  hint_prior_age_s_ += step.dt_s;
  if (hint_prior_age_s_ > config_.hint_prior_s) hint_prior_.clear();
  for (GaussianPose& p : hint_prior_) move(&p);
}

void HypothesisTracker::correct(const GroundPoints& points) {
  stats_.points_in = 0;
  for (const GroundPoint& p : points.points) stats_.points_in += p.p_robot.allFinite() ? 1 : 0;
  stats_.points_used = 0;
  stats_.best_inlier_share = 0.0;
  if (stats_.points_in > 0) stats_.seconds_without_points = 0.0;
  if (hypotheses_.empty() || stats_.points_in < config_.update.min_points) return;

  // The best hypothesis before this frame's evidence (weights are normalised, best first).
  const int best_id = hypotheses_.front().id;
  const double best_weight = hypotheses_.front().pose.weight;
  std::vector<double> log_likelihood(hypotheses_.size());
  const bool judge = stats_.points_in >= config_.min_points_to_judge;
  std::vector<GaussianPose> priors;
  priors.reserve(hypotheses_.size());
  for (const TrackedHypothesis& h : hypotheses_) priors.push_back(h.pose);
  const std::vector<PointUpdateResult> results = updateWithOneFrameTilt(
      priors, points.points, *index_, config_.update, config_.likelihood_points);
  for (size_t k = 0; k < hypotheses_.size(); ++k) {
    TrackedHypothesis& h = hypotheses_[k];
    const PointUpdateResult& r = results[k];
    h.pose = r.posterior;
    h.inlier_share = r.inlier_share;
    h.points_associated = r.num_associated;
    if (judge) {
      const bool disagrees = r.inlier_share < config_.disagree_inlier_share;
      h.disagreeing_frames = disagrees ? h.disagreeing_frames + 1 : 0;
      trackInlierShare(config_, r.inlier_share, &h);
    }
    log_likelihood[k] = r.mean_log_likelihood;
  }
  // Bayes: weight *= frame likelihood; relative to the best, so exp() cannot overflow. Mean
  // per-point differences within the deadband are not evidence: two poses that both explain the
  // lines differ by that much only through where the outliers happen to fall (more lines nearby,
  // more outliers close to one), and summed over frames that bias would pick the busier place.
  const double best = *std::max_element(log_likelihood.begin(), log_likelihood.end());
  for (size_t k = 0; k < hypotheses_.size(); ++k) {
    const double difference = std::min(0.0, log_likelihood[k] - best + config_.likelihood_deadband);
    const double ratio = std::exp(std::max(config_.likelihood_points * difference, -700.0));
    hypotheses_[k].pose.weight *= std::isfinite(ratio) ? ratio : 0.0;
  }
  finishSet();
  // The best hypothesis lost most of its weight to others in one frame: the view changed in a
  // way the held hypotheses disagree on, so ask whether a pose not held explains it better.
  double best_weight_now = 0.0;
  for (const TrackedHypothesis& h : hypotheses_) {
    if (h.id == best_id) best_weight_now = h.pose.weight;
  }
  weight_drop_since_injection_ = weight_drop_since_injection_ ||
                                 best_weight_now < config_.best_weight_drop_ratio * best_weight;
  if (!hypotheses_.empty()) {
    stats_.best_inlier_share = hypotheses_.front().inlier_share;
    stats_.points_used = hypotheses_.front().points_associated;
  }
}

void HypothesisTracker::injectHypotheses(const std::vector<GaussianPose>& poses) {
  // Asked only because the period passed: the best hypothesis agrees with the observations, so
  // a kidnap is unlikely and newcomers start small; a local view (one corner) fits several
  // places, and only history tells them apart.
  addPoses(poses, onlyPeriodic() ? config_.periodic_injected_share : config_.injected_share);
  markInjected();
  // A hint is checked by a global run on a frame with enough points to judge it.
  if (stats_.points_in >= config_.min_points_to_judge) global_after_hint_ = false;
}

void HypothesisTracker::markInjected() {
  weight_drop_since_injection_ = false;
  seconds_since_injection_ = 0.0;
  jump_since_injection_ = false;
  blind_since_injection_ = false;
  // Fresh hypotheses get a fresh chance: old disagreement counts no longer ask for more.
  for (TrackedHypothesis& h : hypotheses_) {
    h.disagreeing_frames = 0;
    h.share_drop = 0.0;
  }
}

void HypothesisTracker::addPoses(const std::vector<GaussianPose>& poses, double share) {
  std::vector<GaussianPose> valid;
  double max_likelihood = 0.0;
  for (GaussianPose p : poses) {
    if (!p.mean.isFinite()) continue;
    sanitizeCovariance(config_.motion, &p.covariance);
    p.weight = std::isfinite(p.weight) && p.weight > 0.0 ? p.weight : 0.0;
    max_likelihood = std::max(max_likelihood, p.weight);
    valid.push_back(p);
  }
  if (valid.empty()) return;
  // The one weight rule (docs/tracking.md "How weights flow"): share x belief x likelihood,
  // the likelihood relative to the batch's best. With nothing tracked the belief is flat and the
  // new poses take all the weight.
  const double total = hypotheses_.empty() ? 1.0 : std::clamp(share, 0.0, 1.0);
  std::vector<double> weights;
  for (const GaussianPose& p : valid) {
    const double likelihood = max_likelihood > 0.0 ? p.weight / max_likelihood : 1.0;
    weights.push_back(total * belief(p) * likelihood);
  }
  normalizeTrackedWeights(&hypotheses_);
  for (auto& h : hypotheses_) h.pose.weight *= 1.0 - total;
  for (size_t k = 0; k < valid.size(); ++k) {
    TrackedHypothesis h;
    h.pose = valid[k];
    h.pose.weight = weights[k];
    h.id = next_id_++;
    hypotheses_.push_back(h);
  }
  finishSet();
}

namespace {

/// sum_j w_j exp(-chi2_j / 2) / sum_j w_j over `poses` (docs/tracking.md "How weights flow").
template <typename Range, typename PoseOf>
double mixtureAt(const GaussianPose& pose, const Range& poses, PoseOf pose_of,
                 const Eigen::Matrix3d& spread) {
  double sum = 0.0, density = 0.0;
  for (const auto& item : poses) sum += std::max(0.0, pose_of(item).weight);
  if (!(sum > 0.0) || !std::isfinite(sum)) return -1.0;
  for (const auto& item : poses) {
    const GaussianPose& h = pose_of(item);
    const Eigen::Matrix3d s = h.covariance + pose.covariance + spread;
    const Eigen::Vector3d d = poseDifference(pose.mean, h.mean);
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(s);
    if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) continue;
    const double chi2 = d.dot(ldlt.solve(d));
    if (std::isfinite(chi2)) density += std::max(0.0, h.weight) / sum * std::exp(-0.5 * chi2);
  }
  return density;
}

}  // namespace

double HypothesisTracker::belief(const GaussianPose& pose) const {
  if (hypotheses_.empty()) return 1.0;
  const double spread_m = config_.belief_spread_m * config_.belief_spread_m;
  const double spread_rad = config_.belief_spread_rad * config_.belief_spread_rad;
  const Eigen::Matrix3d spread = Eigen::Vector3d(spread_m, spread_m, spread_rad).asDiagonal();
  const double set = mixtureAt(
      pose, hypotheses_, [](const TrackedHypothesis& h) -> const GaussianPose& { return h.pose; },
      spread);
  if (set < 0.0) return 1.0;
  const double hint = mixtureAt(
      pose, hint_prior_, [](const GaussianPose& p) -> const GaussianPose& { return p; }, spread);
  return std::clamp(std::max({config_.belief_floor, set, hint}), 0.0, 1.0);
}

void HypothesisTracker::finishSet() {
  normalizeTrackedWeights(&hypotheses_);
  mergeConverged(config_.set, &hypotheses_);
  pruneWeak(config_.set, &hypotheses_);
}

bool HypothesisTracker::bestIsLost() const {
  if (hypotheses_.empty()) return false;
  const TrackedHypothesis& best = hypotheses_.front();
  const double var_xy = std::max(best.pose.covariance(0, 0), best.pose.covariance(1, 1));
  return best.disagreeing_frames >= config_.disagree_frames ||
         !(var_xy <= config_.lost_sigma_m * config_.lost_sigma_m);
}

bool HypothesisTracker::dropAlarm(const TrackedHypothesis& h) const {
  return h.share_drop > config_.share_drop_alarm;
}

bool HypothesisTracker::onlyPeriodic() const {
  const bool check_hint = global_after_hint_ && stats_.points_in >= config_.min_points_to_judge;
  return !hypotheses_.empty() && !check_hint && !weight_drop_since_injection_ &&
         !jump_since_injection_ && !blind_since_injection_ && !bestIsLost() &&
         hypotheses_.front().pose.weight >= config_.low_best_weight;
}

bool HypothesisTracker::needsGlobalHypotheses() const {
  // A sudden drop asks at once but counts as a low-rate injection (periodic_injected_share): a
  // newcomer that explains clearly more wins within a frame or two through the likelihood, and
  // a false alarm (a robot walking into view) costs no more than a periodic injection.
  return !onlyPeriodic() || dropAlarm(hypotheses_.front()) ||
         seconds_since_injection_ >= config_.periodic_global_s;
}

bool HypothesisTracker::topHypothesesMirrorAmbiguous() const {
  if (hypotheses_.size() < 2) return false;
  const TrackedHypothesis& best = hypotheses_.front();
  for (size_t k = 1; k < hypotheses_.size(); ++k) {
    const TrackedHypothesis& h = hypotheses_[k];
    if (h.pose.weight < config_.ambiguous_weight_ratio * best.pose.weight) break;  // sorted
    if (areMirrors(best.pose.mean, h.pose.mean, config_.mirror_tolerance_m,
                   config_.mirror_tolerance_rad)) {
      return true;
    }
  }
  return false;
}

TrackerStatus HypothesisTracker::status() const {
  if (hypotheses_.empty()) return TrackerStatus::kInitializing;
  if (bestIsLost() || stats_.seconds_without_points > config_.lost_without_points_s) {
    return TrackerStatus::kLost;
  }
  if (topHypothesesMirrorAmbiguous()) return TrackerStatus::kAmbiguous;
  return TrackerStatus::kTracking;
}

}  // namespace houghloc
