#include "tools/render/scene_objects.h"

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace houghloc {
namespace {

using V3 = Eigen::Vector3d;
const Material kWhite{Eigen::Vector3f(232, 234, 234), Pattern::kPlain};
const Material kShell{Eigen::Vector3f(215, 218, 220), Pattern::kPlain};
const Material kJoint{Eigen::Vector3f(62, 60, 60), Pattern::kPlain};
const Material kNet{Eigen::Vector3f(210, 210, 210), Pattern::kNet};

/// Robot-frame point (scaled) to field frame.
V3 place(const Pose2& pose, double scale, double x, double y, double z) {
  const Eigen::Vector2d p = pose.transform(Eigen::Vector2d(scale * x, scale * y));
  return V3(p.x(), p.y(), scale * z);
}

}  // namespace

void SceneObjects::append(const SceneObjects& other) {
  primitives.insert(primitives.end(), other.primitives.begin(), other.primitives.end());
  shadows.insert(shadows.end(), other.shadows.begin(), other.shadows.end());
}

SceneObjects makeGoals(const FieldModel& field, const SceneConfig& scene) {
  SceneObjects out;
  if (!scene.goals) return out;
  for (const Goal& g : field.goals) {
    const double side = g.center.x() >= 0.0 ? 1.0 : -1.0;  // outward
    const double r = 0.5 * g.post_diameter;
    // Posts on the goal line, their back flush with the line's outer edge.
    const double x = g.center.x() + side * (r - 0.5 * field.line_width);
    const double yl = g.center.y() + 0.5 * g.inner_width + r;
    const double yr = g.center.y() - 0.5 * g.inner_width - r;
    const double top = g.height - r;
    const double back = g.center.x() + side * g.depth;
    auto& p = out.primitives;
    p.push_back(makeCapsule(V3(x, yl, 0.0), V3(x, yl, top), r, kWhite));
    p.push_back(makeCapsule(V3(x, yr, 0.0), V3(x, yr, top), r, kWhite));
    p.push_back(makeCapsule(V3(x, yl, top), V3(x, yr, top), r, kWhite));
    const double fr = 0.02;  // frame tube radius
    if (scene.goal_frame) {
      for (double y : {yl, yr}) {
        p.push_back(makeCapsule(V3(x, y, fr), V3(back, y, fr), fr, kWhite));  // on the ground
        p.push_back(makeCapsule(V3(x, y, top), V3(back, y, top), fr, kWhite));
        p.push_back(makeCapsule(V3(back, y, fr), V3(back, y, top), fr, kWhite));
      }
      p.push_back(makeCapsule(V3(back, yl, fr), V3(back, yr, fr), fr, kWhite));
      p.push_back(makeCapsule(V3(back, yl, top), V3(back, yr, top), fr, kWhite));
    }
    if (scene.goal_nets) {
      const V3 corner(back, yr, 0.0);
      p.push_back(makeNetPanel(corner, V3(0, yl - yr, 0), V3(0, 0, top), kNet));  // back
      p.push_back(makeNetPanel(V3(x, yl, 0), V3(back - x, 0, 0), V3(0, 0, top), kNet));
      p.push_back(makeNetPanel(V3(x, yr, 0), V3(back - x, 0, 0), V3(0, 0, top), kNet));
      p.push_back(makeNetPanel(V3(x, yr, top), V3(back - x, 0, 0), V3(0, yl - yr, 0), kNet));
    }
  }
  return out;
}

SceneObjects makePeople(const FieldModel& field, const SceneConfig& scene, const RoomBox& room,
                        std::uint32_t seed) {
  SceneObjects out;
  std::mt19937 rng(seed * 13u + 1u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<Eigen::Vector3f> shirts = {{230, 230, 230}, {40, 40, 40},  {160, 60, 30},
                                               {40, 40, 170},   {60, 130, 60}, {30, 170, 220}};
  const std::vector<Eigen::Vector3f> skins = {{150, 180, 225}, {90, 120, 170}, {60, 80, 115}};
  const double ox = field.outerHalfLength(), oy = field.outerHalfWidth();
  for (int i = 0; i < scene.people; ++i) {
    // A point on the floor band between the carpet and the walls.
    double x = 0.0, y = 0.0;
    const double gap = 0.3 + (std::max(0.4, room.half_x - ox) - 0.6) * u(rng);
    const double along = 2.0 * u(rng) - 1.0;
    switch (static_cast<int>(u(rng) * 4.0)) {
      case 0:
        x = ox + gap, y = along * (oy + 0.5);
        break;
      case 1:
        x = -ox - gap, y = along * (oy + 0.5);
        break;
      case 2:
        y = oy + gap, x = along * (ox + 0.5);
        break;
      default:
        y = -oy - gap, x = along * (ox + 0.5);
        break;
    }
    const double h = 1.55 + 0.35 * u(rng);
    const Pose2 pose(x, y, std::atan2(-y, -x) + 0.6 * (u(rng) - 0.5));  // facing the field
    const Material shirt{shirts[static_cast<size_t>(u(rng) * 5.99)], Pattern::kPlain};
    const Material skin{skins[static_cast<size_t>(u(rng) * 2.99)], Pattern::kSkin};
    const Material legs{Eigen::Vector3f(90, 60, 40) * (0.6f + 0.6f * float(u(rng))),
                        Pattern::kPlain};
    auto& p = out.primitives;
    for (double side : {-1.0, 1.0}) {
      p.push_back(makeCapsule(place(pose, 1.0, 0.0, side * 0.1, 0.06),
                              place(pose, 1.0, 0.0, side * 0.1, 0.47 * h), 0.07, legs));
      p.push_back(makeCapsule(place(pose, 1.0, 0.05, side * 0.24, 0.78 * h),
                              place(pose, 1.0, 0.08, side * 0.27, 0.45 * h), 0.045, shirt));
    }
    p.push_back(makeCapsule(place(pose, 1.0, 0.0, 0.0, 0.55 * h),
                            place(pose, 1.0, 0.0, 0.0, 0.76 * h), 0.17, shirt));
    p.push_back(makeSphere(place(pose, 1.0, 0.0, 0.0, 0.91 * h), 0.105, skin));
    p.push_back(makeSphere(place(pose, 1.0, -0.02, 0.0, 0.93 * h), 0.1,
                           Material{Eigen::Vector3f(30, 35, 45), Pattern::kPlain}));  // hair
    out.shadows.push_back({Eigen::Vector2f(float(x), float(y)), 0.35f, 0.3f});
  }
  return out;
}

void addRobot(const Pose2& pose, double height_m, const Eigen::Vector3f& jersey, double gait,
              bool walking, SceneObjects& out) {
  const double s = height_m / 0.58;  // model built at NAO size (0.58 m)
  const double swing = walking ? 0.03 * std::sin(gait) : 0.0;
  auto& p = out.primitives;
  for (double side : {-1.0, 1.0}) {
    const double fx = side * swing;
    p.push_back(makeBox(place(pose, s, fx + 0.02, side * 0.05, 0.02), s * V3(0.08, 0.045, 0.02),
                        pose.theta, kShell));
    p.push_back(makeCapsule(place(pose, s, fx, side * 0.05, 0.06),
                            place(pose, s, 0.5 * fx, side * 0.05, 0.18), s * 0.037, kShell));
    p.push_back(makeCapsule(place(pose, s, 0.5 * fx, side * 0.05, 0.2),
                            place(pose, s, 0.0, side * 0.05, 0.3), s * 0.04, kJoint));
    p.push_back(makeCapsule(place(pose, s, -fx * 0.5, side * 0.115, 0.44),
                            place(pose, s, 0.03, side * 0.125, 0.27), s * 0.03, kShell));
  }
  p.push_back(makeBox(place(pose, s, 0.0, 0.0, 0.39), s * V3(0.055, 0.085, 0.095), pose.theta,
                      Material{jersey, Pattern::kPlain}));
  Primitive head = makeSphere(place(pose, s, 0.0, 0.0, 0.53), s * 0.065,
                              Material{Eigen::Vector3f(225, 228, 228), Pattern::kHead});
  head.pattern_rotation = Eigen::AngleAxisd(pose.theta, V3::UnitZ()).toRotationMatrix();
  p.push_back(head);
  out.shadows.push_back({pose.translation().cast<float>(), float(0.14 * s), 0.45f});
}

void addOwnFeet(const Pose2& pose, double height_m, double gait, bool walking, SceneObjects& out) {
  const double s = height_m / 0.58;
  const double swing = walking ? 0.03 * std::sin(gait) : 0.0;
  for (double side : {-1.0, 1.0}) {
    const double fx = side * swing;
    out.primitives.push_back(makeBox(place(pose, s, fx + 0.02, side * 0.05, 0.018),
                                     s * V3(0.08, 0.045, 0.014), pose.theta, kShell));
    out.primitives.push_back(makeBox(place(pose, s, fx + 0.02, side * 0.05, 0.003),
                                     s * V3(0.081, 0.046, 0.003), pose.theta, kJoint));  // sole
  }
  out.shadows.push_back({pose.translation().cast<float>(), float(0.14 * s), 0.35f});
}

void addBall(const Eigen::Vector2d& c, double diameter_m, const Eigen::Matrix3d& spin,
             SceneObjects& out) {
  const double r = 0.5 * diameter_m;
  Primitive ball =
      makeSphere(V3(c.x(), c.y(), r), r, Material{Eigen::Vector3f(235, 235, 235), Pattern::kBall});
  ball.pattern_rotation = spin;
  out.primitives.push_back(ball);
  out.shadows.push_back({c.cast<float>(), float(0.8 * r), 0.55f});
}

Eigen::Vector3f teamColour(const std::string& team) {
  if (team == "red") return {40, 40, 190};
  if (team == "black") return {45, 45, 45};
  if (team == "yellow") return {20, 200, 230};
  if (team == "green") return {50, 150, 40};
  if (team == "white") return {230, 230, 230};
  return {170, 80, 25};  // blue
}

}  // namespace houghloc
