#include "tools/render/line_painter.h"

#include <gtest/gtest.h>

#include "field_models/standard_fields.h"

namespace houghloc {
namespace {

Footprint squarePixel(float size_m) {
  Footprint fp;
  fp.du = Eigen::Vector2f(size_m, 0.0f);
  fp.dv = Eigen::Vector2f(0.0f, size_m);
  return fp;
}

TEST(LinePainterTest, CoverageIsTheBoxFilteredLine) {
  LinePainter p;
  p.addBar(Eigen::Vector2d(-1, 0), Eigen::Vector2d(1, 0), 0.05, 0.025, 0);
  p.build(Eigen::Vector2d(-2, -2), Eigen::Vector2d(2, 2));
  const Footprint small = squarePixel(0.01f);
  EXPECT_NEAR(p.coverage({0.0f, 0.0f}, small).coverage, 1.0f, 1e-3);
  EXPECT_NEAR(p.coverage({0.0f, 0.024f}, small).coverage, 0.6f, 1e-3);  // edge inside the pixel
  EXPECT_NEAR(p.coverage({0.0f, 0.04f}, small).coverage, 0.0f, 1e-3);
  // A pixel 0.2 m wide sees a quarter of a 0.05 m line: the line fades, it does not alias.
  EXPECT_NEAR(p.coverage({0.0f, 0.03f}, squarePixel(0.2f)).coverage, 0.25f, 1e-5);
  // Square caps: painted up to half the width beyond the end.
  EXPECT_NEAR(p.coverage({1.02f, 0.0f}, squarePixel(0.001f)).coverage, 1.0f, 1e-3);
  EXPECT_NEAR(p.coverage({1.03f, 0.0f}, squarePixel(0.001f)).coverage, 0.0f, 1e-3);
}

TEST(LinePainterTest, FieldPaintMatchesTheMapWidth) {
  for (const std::string& name : standardFieldNames()) {
    const FieldModel field = makeStandardField(name);
    LinePainter p;
    p.addField(field);
    const Eigen::Vector2d outer(field.outerHalfLength(), field.outerHalfWidth());
    p.build(-outer, outer);
    const Footprint fp = squarePixel(0.002f);
    const float hw = static_cast<float>(0.5 * field.line_width);
    // Centre circle, halfway line, touch line: inside at hw - 2 mm, outside at hw + 2 mm.
    const float r = static_cast<float>(field.arcs[0].radius);
    EXPECT_NEAR(p.coverage({r + hw - 0.002f, 0.0f}, fp).coverage, 1.0f, 1e-3) << name;
    EXPECT_NEAR(p.coverage({r + hw + 0.002f, 0.0f}, fp).coverage, 0.0f, 1e-3) << name;
    const float y = static_cast<float>(field.halfWidth());
    EXPECT_NEAR(p.coverage({1.0f, y - hw + 0.002f}, fp).coverage, 1.0f, 1e-3) << name;
    EXPECT_NEAR(p.coverage({1.0f, y + hw + 0.002f}, fp).coverage, 0.0f, 1e-3) << name;
  }
}

}  // namespace
}  // namespace houghloc
