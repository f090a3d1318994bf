#include "tools/render/ground_shader.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace houghloc {
namespace {

// Colours, BGR on a 0..255 scale, as a NAO camera sees them under hall lighting. The turf and
// the paint are the scenario's (SceneConfig::turf_bgr, paint_bgr).
const Eigen::Vector3f kTurf(52.0f, 128.0f, 62.0f);        ///< SceneConfig's default turf_bgr
const Eigen::Vector3f kTurfSheen(70.0f, 150.0f, 110.0f);  ///< that turf seen at grazing angles
/// Other carpets seen at grazing angles: the pile's lighter sides, without a colour shift.
constexpr float kCarpetSheenGain = 1.3f;
const Eigen::Vector3f kWood(92.0f, 142.0f, 190.0f);
const Eigen::Vector3f kConcrete(140.0f, 142.0f, 145.0f);

float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

/// Cheap integer hash to [0, 1) for per-plank variation.
float hash01(int a, int b) {
  std::uint32_t h =
      static_cast<std::uint32_t>(a) * 73856093u ^ static_cast<std::uint32_t>(b) * 19349663u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return static_cast<float>(h & 0xffffu) / 65536.0f;
}

}  // namespace

RoomBox makeRoomBox(const FieldModel& field, const SceneConfig& scene) {
  RoomBox room;
  room.half_x = field.outerHalfLength() + scene.room_margin_m;
  room.half_y = field.outerHalfWidth() + scene.room_margin_m;
  room.height = 6.0;
  return room;
}

GroundShader::GroundShader(const FieldModel& field, const SceneConfig& scene, const RoomBox& room,
                           std::uint32_t seed)
    : field_(field), scene_(scene), room_(room) {
  turf_ = Eigen::Vector3d(scene.turf_bgr[0], scene.turf_bgr[1], scene.turf_bgr[2]).cast<float>();
  sheen_ = turf_ == kTurf ? kTurfSheen : Eigen::Vector3f(kCarpetSheenGain * turf_);
  paint_ =
      Eigen::Vector3d(scene.paint_bgr[0], scene.paint_bgr[1], scene.paint_bgr[2]).cast<float>();
  blades_ = NoiseTexture(512, 0.0015, 0.6, seed * 7u + 6u);  // single blades, close up
  fine_ = NoiseTexture(512, 0.006, 0.7, seed * 7u + 1u);     // turf fibres
  blotch_ = NoiseTexture(256, 0.03, 2.5, seed * 7u + 2u);    // tufts, dirt
  large_ = NoiseTexture(64, 0.25, 2.0, seed * 7u + 3u);      // wear, uneven pile
  field_lines_.addField(field);
  const Eigen::Vector2d outer(field.outerHalfLength(), field.outerHalfWidth());
  field_lines_.build(-outer, outer);
  if (scene.court_lines) addCourtLines(seed);
  // Hall lighting: a grid of ceiling lamps plus a window-side gradient, as a coarse map.
  const int cols = static_cast<int>(2.0 * room.half_x / light_res_) + 2;
  const int rows = static_cast<int>(2.0 * room.half_y / light_res_) + 2;
  light_map_ = cv::Mat1f(rows, cols, 1.0f);
  if (scene.lighting_gradient) {
    std::mt19937 rng(seed * 7u + 4u);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double lamp_dx = 3.0 + u(rng), lamp_dy = 3.0 + 0.5 * u(rng);
    const double ox = u(rng), oy = u(rng), gx = u(rng), gy = u(rng);
    double sum = 0.0;
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) {
        const double x = -room.half_x + c * light_res_, y = -room.half_y + r * light_res_;
        // Lamps every few metres (smooth bumps) and a linear gradient toward the windows.
        const double lamps =
            std::cos(2.0 * M_PI * (x - ox) / lamp_dx) * std::cos(2.0 * M_PI * (y - oy) / lamp_dy);
        const double v = 0.5 * lamps + gx * x / room.half_x + gy * y / room.half_y -
                         0.5 * std::hypot(x / room.half_x, y / room.half_y);
        light_map_(r, c) = static_cast<float>(v);
        sum += v;
      }
    }
    const double mean = sum / (rows * cols);
    light_map_ = 1.0f + static_cast<float>(scene.lighting_strength) * (light_map_ - mean) / 1.2f;
  }
}

void GroundShader::addCourtLines(std::uint32_t seed) {
  // Basketball, volleyball and badminton courts of a sports hall, centred somewhere else.
  std::mt19937 rng(seed * 7u + 5u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  court_colours_ = {{40, 50, 200}, {190, 110, 30}, {20, 190, 230}, {225, 225, 225}};
  const double cx = 3.0 * u(rng), cy = 2.0 * u(rng);
  const double courts[3][2] = {{28.0, 15.0}, {18.0, 9.0}, {13.4, 6.1}};
  for (int k = 0; k < 3; ++k) {
    const double hl = 0.5 * courts[k][0], hw = 0.5 * courts[k][1];
    const double ox = cx + 1.5 * k * u(rng), oy = cy + 1.5 * u(rng);
    const Eigen::Vector2d c(ox, oy);
    const Eigen::Vector2d p[4] = {c + Eigen::Vector2d(-hl, -hw), c + Eigen::Vector2d(hl, -hw),
                                  c + Eigen::Vector2d(hl, hw), c + Eigen::Vector2d(-hl, hw)};
    for (int i = 0; i < 4; ++i) court_lines_.addBar(p[i], p[(i + 1) % 4], 0.05, 0.025, k);
    court_lines_.addBar(c + Eigen::Vector2d(0, -hw), c + Eigen::Vector2d(0, hw), 0.05, 0.0, k);
    if (k == 0) court_lines_.addArc(Arc2{c, 1.8, 0.0, 2.0 * M_PI}, 0.05, k);
  }
  court_lines_.build(Eigen::Vector2d(-room_.half_x, -room_.half_y),
                     Eigen::Vector2d(room_.half_x, room_.half_y), 0.5, 0.5);
}

float GroundShader::light(const Eigen::Vector2f& g) const {
  const float u = (g.x() + static_cast<float>(room_.half_x)) / light_res_;
  const float v = (g.y() + static_cast<float>(room_.half_y)) / light_res_;
  const int c = std::clamp(static_cast<int>(u), 0, light_map_.cols - 2);
  const int r = std::clamp(static_cast<int>(v), 0, light_map_.rows - 2);
  const float a = std::clamp(u - c, 0.0f, 1.0f), b = std::clamp(v - r, 0.0f, 1.0f);
  return (1 - b) * ((1 - a) * light_map_(r, c) + a * light_map_(r, c + 1)) +
         b * ((1 - a) * light_map_(r + 1, c) + a * light_map_(r + 1, c + 1));
}

Eigen::Vector3f GroundShader::turf(const Eigen::Vector2f& g, const Footprint& fp, float size,
                                   float view_z) const {
  float tex = 1.0f;
  float fine = 0.0f, blade = 0.0f;
  if (scene_.turf_texture) {
    fine = fine_.sample(g.x(), g.y(), size);
    // Blades only matter close up (a footprint of a few mm); skip them farther away.
    if (size < 0.01f) blade = (1.0f - 100.0f * size) * blades_.sample(g.x(), g.y(), size);
    tex += 0.08f * blade;
    tex += 0.08f * fine + 0.03f * blotch_.sample(g.x(), g.y(), size) +
           0.02f * large_.sample(g.x(), g.y(), size);
  }
  if (scene_.mowing_stripes) {
    // Box-filtered square wave of bands alternating along x.
    const float w = static_cast<float>(scene_.stripe_width_m);
    const float f = std::max(fp.along(Eigen::Vector2f::UnitX()), 0.04f);
    const float phase = g.x() / w - std::floor(g.x() / w);  // [0, 1)
    const float to_edge = std::min(phase, 1.0f - phase) * w;
    const int band = static_cast<int>(std::floor(g.x() / w));
    const float sign = (band & 1) ? 1.0f : -1.0f;
    const float value = sign * std::clamp(to_edge / (0.5f * f), 0.0f, 1.0f) *
                        std::clamp(1.0f - f / (2.0f * w), 0.0f, 1.0f);
    tex *= 1.0f + static_cast<float>(scene_.stripe_contrast) * value;
  }
  // Seen flat, the pile shows its lighter sides.
  const float sheen = smoothstep(0.5f, 0.05f, -view_z);
  Eigen::Vector3f colour = tex * ((1.0f - 0.5f * sheen) * turf_ + 0.5f * sheen * sheen_);
  // Field lines: true width, ragged turf edges, worn and dirty in places.
  // Ragged at the scale of single blades, straight from afar.
  const float rough =
      static_cast<float>(scene_.line_edge_roughness_m) * (0.7f * blade + 0.3f * fine);
  const PaintCoverage paint = field_lines_.coverage(g, fp, rough);
  if (paint.coverage > 0.0f) {
    float alpha = paint.coverage;
    if (scene_.line_wear > 0.0) {
      const float patch = large_.sample(g.x() + 31.7f, g.y() - 17.3f, size);
      const float worn = smoothstep(0.3f, 1.6f, patch) * static_cast<float>(scene_.line_wear);
      alpha *= 1.0f - 0.45f * worn * (0.8f + 0.2f * fine);
    }
    const float dirt = scene_.turf_texture ? 0.04f * blotch_.sample(g.y(), g.x(), size) : 0.0f;
    const Eigen::Vector3f paint_colour = paint_ * (1.0f + 0.03f * fine + dirt);
    colour = (1.0f - alpha) * colour + alpha * paint_colour;
  }
  return colour;
}

Eigen::Vector3f GroundShader::gymFloor(const Eigen::Vector2f& g, const Footprint& fp,
                                       float size) const {
  Eigen::Vector3f colour = kConcrete;
  if (scene_.gym_floor) {
    // Planks 0.1 m wide along x, 2 m long, staggered, each a little different.
    const int row = static_cast<int>(std::floor(g.y() / 0.1f));
    const float shift = 2.0f * hash01(row, 7);
    const int col = static_cast<int>(std::floor((g.x() + shift) / 2.0f));
    const float plank = 0.88f + 0.24f * hash01(row, col);
    const float grain = fine_.sample(0.15f * g.x(), 3.0f * g.y(), size * 3.0f);
    colour = kWood * plank * (1.0f + 0.04f * grain);
  } else {
    colour *= 1.0f + 0.05f * blotch_.sample(g.x(), g.y(), size);
  }
  if (!court_lines_.empty()) {
    const PaintCoverage paint = court_lines_.coverage(g, fp);
    if (paint.coverage > 0.0f) {
      colour = (1.0f - paint.coverage) * colour + paint.coverage * court_colours_[paint.tag];
    }
  }
  return colour;
}

Eigen::Vector3f GroundShader::shade(const Eigen::Vector2f& g, const Footprint& fp, float view_z,
                                    const std::vector<ShadowDisc>& shadows) const {
  const float size = std::max(fp.du.norm(), fp.dv.norm());
  const bool on_carpet =
      std::abs(g.x()) <= field_.outerHalfLength() && std::abs(g.y()) <= field_.outerHalfWidth();
  Eigen::Vector3f colour = on_carpet ? turf(g, fp, size, view_z) : gymFloor(g, fp, size);
  float shade = light(g);
  for (const ShadowDisc& s : shadows) {
    const float d2 = (g - s.center).squaredNorm() / (s.radius * s.radius);
    if (d2 < 4.0f) shade *= 1.0f - s.strength * std::exp(-d2);
  }
  return colour * shade;
}

}  // namespace houghloc
