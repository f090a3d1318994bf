#include "localization/pose_solver.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace houghloc {

bool solveTranslation(const std::vector<TranslationConstraint>& constraints, double sigma_rho_m,
                      Eigen::Vector2d* translation, Eigen::Matrix2d* covariance) {
  Eigen::Matrix2d ata = Eigen::Matrix2d::Zero();
  Eigen::Vector2d atd = Eigen::Vector2d::Zero();
  for (const auto& c : constraints) {
    const Eigen::Vector2d a(std::cos(c.theta_mu), std::sin(c.theta_mu));
    ata += a * a.transpose();
    atd += a * c.d_m;
  }
  // Parallel rows make A^T A (nearly) singular: sin^2 of the angle between them is ~ det.
  if (constraints.size() < 2 || ata.determinant() < 1e-3) return false;
  const Eigen::Matrix2d inv = ata.inverse();
  *translation = inv * atd;
  *covariance = sigma_rho_m * sigma_rho_m * inv;
  return true;
}

PoseHypothesis parallelHypothesis(double theta_r, const TranslationConstraint& constraint,
                                  double along_m, const PoseSolverConfig& config) {
  const Eigen::Vector2d n(std::cos(constraint.theta_mu), std::sin(constraint.theta_mu));
  const Eigen::Vector2d u(-n.y(), n.x());
  const Eigen::Vector2d t = constraint.d_m * n + along_m * u;
  PoseHypothesis h;
  h.field_T_robot = Pose2(t.x(), t.y(), theta_r);
  h.covariance.setZero();
  h.covariance.topLeftCorner<2, 2>() =
      config.sigma_rho_m * config.sigma_rho_m * n * n.transpose() +
      config.sigma_along_m * config.sigma_along_m * u * u.transpose();
  h.covariance(2, 2) = config.sigma_theta_rad * config.sigma_theta_rad;
  h.kind = HypothesisKind::kParallel;
  h.line_direction = u;
  h.support = constraint.support;
  return h;
}

PoseHypothesis headingOnlyHypothesis(double theta_r, const PoseSolverConfig& config) {
  PoseHypothesis h;
  h.field_T_robot = Pose2(0.0, 0.0, theta_r);
  const double v = config.sigma_unknown_m * config.sigma_unknown_m;
  h.covariance =
      Eigen::Vector3d(v, v, config.sigma_theta_rad * config.sigma_theta_rad).asDiagonal();
  h.kind = HypothesisKind::kHeadingOnly;
  return h;
}

std::vector<PoseHypothesis> lineCandidates(
    double theta_r, const std::vector<std::vector<TranslationConstraint>>& per_direction,
    const PoseSolverConfig& config) {
  const std::vector<TranslationConstraint>* strongest = nullptr;
  for (const auto& constraints : per_direction) {
    if (!constraints.empty() &&
        (strongest == nullptr || constraints[0].support > (*strongest)[0].support)) {
      strongest = &constraints;
    }
  }
  std::vector<PoseHypothesis> out;
  if (strongest == nullptr) return out;
  for (const auto& c : *strongest) out.push_back(parallelHypothesis(theta_r, c, 0.0, config));
  return out;
}

std::vector<PoseHypothesis> solvePoses(
    double theta_r, const std::vector<std::vector<TranslationConstraint>>& per_direction,
    const PoseSolverConfig& config) {
  std::vector<PoseHypothesis> out;
  std::vector<int> seen;
  for (int k = 0; k < static_cast<int>(per_direction.size()); ++k) {
    if (!per_direction[k].empty()) seen.push_back(k);
  }
  int pairs = 0;
  bool any_pair = false;
  for (std::size_t a = 0; a < seen.size(); ++a) {
    for (std::size_t b = a + 1; b < seen.size(); ++b) {
      const auto& ca = per_direction[seen[a]];
      const auto& cb = per_direction[seen[b]];
      const double angle = std::abs(std::sin(ca[0].theta_mu - cb[0].theta_mu));
      if (angle < std::sin(config.min_direction_angle_rad)) continue;
      any_pair = true;
      for (const auto& first : ca) {
        for (const auto& second : cb) {
          if (pairs++ >= config.max_pairs) break;
          Eigen::Vector2d t;
          Eigen::Matrix2d cov;
          if (!solveTranslation({first, second}, config.sigma_rho_m, &t, &cov)) continue;
          PoseHypothesis h;
          h.field_T_robot = Pose2(t.x(), t.y(), theta_r);
          h.covariance.setZero();
          h.covariance.topLeftCorner<2, 2>() = cov;
          h.covariance(2, 2) = config.sigma_theta_rad * config.sigma_theta_rad;
          h.support = first.support + second.support;
          out.push_back(h);
        }
      }
    }
  }
  for (int k : seen) {
    double others = 0.0;
    for (int j : seen) {
      if (j != k) others = std::max(others, per_direction[j][0].support);
    }
    if (any_pair && per_direction[k][0].support < config.dominance_ratio * others) continue;
    for (const auto& c : per_direction[k]) {
      out.push_back(parallelHypothesis(theta_r, c, 0.0, config));
    }
  }
  if (out.empty()) out.push_back(headingOnlyHypothesis(theta_r, config));
  return out;
}

}  // namespace houghloc
