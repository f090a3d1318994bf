#include "vision/own_body.h"

#include <cmath>

namespace houghloc {

bool onOwnBody(const Eigen::Vector2d& p_robot, const OwnBodyConfig& config) {
  return p_robot.x() < config.front_m && p_robot.x() > -config.back_m &&
         std::abs(p_robot.y()) < config.half_width_m;
}

std::vector<SpotRay> dropSpotsOnOwnBody(const std::vector<SpotRay>& rays,
                                        const Pose3& robot_T_camera, const OwnBodyConfig& config,
                                        int* dropped) {
  std::vector<SpotRay> kept;
  kept.reserve(rays.size());
  const GroundProjector projector(robot_T_camera);
  const GroundProjectionConfig unlimited = unlimitedProjection();
  for (const SpotRay& ray : rays) {
    const auto p = projector.project(ray.ray_camera, unlimited);
    if (p && onOwnBody(*p, config)) continue;
    kept.push_back(ray);
  }
  if (dropped) *dropped = static_cast<int>(rays.size() - kept.size());
  return kept;
}

}  // namespace houghloc
