#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "field_models/field_model.h"
#include "tools/render/line_painter.h"
#include "tools/render/noise_texture.h"
#include "tools/render/scenario.h"

namespace houghloc {

/// The hall around the field: floor up to the walls at |x| = half_x, |y| = half_y, ceiling.
struct RoomBox {
  double half_x = 8.0, half_y = 6.0, height = 6.0;  ///< m
  bool containsFloor(float x, float y) const {
    return std::abs(x) < half_x && std::abs(y) < half_y;
  }
};
RoomBox makeRoomBox(const FieldModel& field, const SceneConfig& scene);

/// A soft contact shadow on the floor (field frame).
struct ShadowDisc {
  Eigen::Vector2f center = Eigen::Vector2f::Zero();
  float radius = 0.1f;    ///< m
  float strength = 0.4f;  ///< darkening at the centre (fraction)
};

/// Colour of the floor at a ground point: textured artificial turf with mowing stripes, the
/// field lines (true width, anti-aliased, worn in places), and beyond the carpet a wooden gym
/// floor with other sports' lines; all under an uneven hall lighting.
class GroundShader {
 public:
  GroundShader(const FieldModel& field, const SceneConfig& scene, const RoomBox& room,
               std::uint32_t seed);

  /// BGR (0..255 scale, may exceed 255 before exposure). `view_z` is the ray's z component
  /// (-1 looking straight down, near 0 grazing).
  Eigen::Vector3f shade(const Eigen::Vector2f& g, const Footprint& fp, float view_z,
                        const std::vector<ShadowDisc>& shadows) const;
  /// Hall lighting at a floor point (about 1).
  float light(const Eigen::Vector2f& g) const;

 private:
  Eigen::Vector3f turf(const Eigen::Vector2f& g, const Footprint& fp, float size,
                       float view_z) const;
  Eigen::Vector3f gymFloor(const Eigen::Vector2f& g, const Footprint& fp, float size) const;
  void addCourtLines(std::uint32_t seed);

  FieldModel field_;
  SceneConfig scene_;
  RoomBox room_;
  Eigen::Vector3f turf_, sheen_, paint_;  ///< carpet, carpet at grazing angles, line paint (BGR)
  LinePainter field_lines_, court_lines_;
  std::vector<Eigen::Vector3f> court_colours_;
  NoiseTexture blades_, fine_, blotch_, large_;
  cv::Mat1f light_map_;
  float light_res_ = 0.2f;
};

}  // namespace houghloc
