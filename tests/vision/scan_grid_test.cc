#include "vision/scan_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "vision/camera_presets.h"

namespace houghloc {
namespace {

/// The first row (from the top) in column u whose ground lies within range_m of the camera's
/// foot, by pixelToGround row by row: the reference for the scan grid's range limit.
int firstRowWithin(const CameraModel& camera, int u, double range_m) {
  const Eigen::Vector2d foot(camera.pose().x, camera.pose().y);
  for (int v = 0; v < camera.height(); ++v) {
    const auto ground = camera.pixelToGround(u, v);
    if (ground && (*ground - foot).norm() <= range_m) return v;
  }
  return camera.height();
}

FieldBoundary fieldToTheTop(const CameraModel& camera) {
  FieldBoundary boundary;
  boundary.found = true;
  boundary.rows.assign(static_cast<size_t>(camera.width()), 0.f);
  return boundary;
}

TEST(ScanGrid, ReachesTheRangeOfTheCameraPitchedFurtherDownByTheMargin) {
  const CameraPreset preset = cameraPreset("nao-top");
  const CameraModel camera(preset.intrinsics, preset.robot_T_camera);
  const LineWidthModel widths(camera, 0.05);
  const FieldBoundary boundary = fieldToTheTop(camera);
  for (double margin_deg : {0.0, 1.0, 2.0}) {
    ScanGridConfig config;
    config.range_pitch_margin_rad = margin_deg * M_PI / 180.0;
    Pose3 steeper = preset.robot_T_camera;
    steeper.pitch += config.range_pitch_margin_rad;
    const CameraModel reference(preset.intrinsics, steeper);
    // No roll: the middle column's limit is the highest of the three the grid probes.
    const int expected = firstRowWithin(reference, (camera.width() - 1) / 2, config.max_range_m);
    const ScanGrid grid = makeScanGrid(camera, widths, boundary, config);
    EXPECT_NEAR(grid.top_row, expected, 1) << margin_deg << " deg";
    ASSERT_FALSE(grid.rows.empty());
    EXPECT_GE(grid.rows.back(), grid.top_row);
  }
}

TEST(ScanGrid, ScansTheMarginsBandSparselyAndLeavesTheRestAsItWas) {
  const CameraPreset preset = cameraPreset("nao-top");
  const CameraModel camera(preset.intrinsics, preset.robot_T_camera);
  const LineWidthModel widths(camera, 0.05);
  const FieldBoundary boundary = fieldToTheTop(camera);
  ScanGridConfig at_pose;
  at_pose.range_pitch_margin_rad = 0.0;
  const ScanGrid plain = makeScanGrid(camera, widths, boundary, at_pose);
  const ScanGrid wide = makeScanGrid(camera, widths, boundary, ScanGridConfig{});
  ASSERT_LT(wide.top_row, plain.top_row);  // 1 deg is about 10 rows of a NAO's top camera
  EXPECT_GT(plain.top_row - wide.top_row, 5);
  // Below the range limit at the pose the rows are the same.
  std::vector<int> below;
  for (int v : wide.rows) {
    if (v >= plain.top_row) below.push_back(v);
  }
  // The last plain row may differ where the band's sparser steps begin.
  ASSERT_GE(below.size() + 1, plain.rows.size());
  for (std::size_t i = 0; i + 1 < plain.rows.size(); ++i) EXPECT_EQ(below[i], plain.rows[i]);
  // In the band, rows are margin_row_step_px apart (the densest spacing is 1 px there).
  int band_rows = 0;
  for (std::size_t i = 1; i < wide.rows.size(); ++i) {
    if (wide.rows[i - 1] >= plain.top_row) continue;
    ++band_rows;
    EXPECT_GE(wide.rows[i - 1] - wide.rows[i], ScanGridConfig{}.margin_row_step_px);
  }
  EXPECT_GT(band_rows, 0);
  // Columns reach into the band too.
  const auto highest = std::min_element(
      wide.columns.begin(), wide.columns.end(),
      [](const ScanGrid::Column& a, const ScanGrid::Column& b) { return a.v_begin < b.v_begin; });
  EXPECT_EQ(highest->v_begin, wide.top_row);
}

TEST(ScanGrid, EndsWhateverItsConfigSays) {
  const CameraPreset preset = cameraPreset("nao-top");
  const CameraModel camera(preset.intrinsics, preset.robot_T_camera);
  const LineWidthModel widths(camera, 0.05);
  const FieldBoundary boundary = fieldToTheTop(camera);
  const int big = std::numeric_limits<int>::max();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int steps : {0, -3, big}) {
    for (double margin : {0.0, -5.0, 100.0, nan}) {
      ScanGridConfig config;
      config.min_row_step_px = steps;
      config.margin_row_step_px = steps;
      config.min_column_step_px = steps;
      config.max_step_px = steps == big ? big : steps;
      config.range_pitch_margin_rad = margin;
      const ScanGrid grid = makeScanGrid(camera, widths, boundary, config);
      // Rows strictly bottom to top inside the image, columns inside it.
      for (std::size_t i = 0; i < grid.rows.size(); ++i) {
        EXPECT_TRUE(grid.rows[i] >= 0 && grid.rows[i] < camera.height());
        if (i > 0) {
          EXPECT_LT(grid.rows[i], grid.rows[i - 1]);
        }
      }
      for (const ScanGrid::Column& c : grid.columns) {
        EXPECT_TRUE(c.u >= 0 && c.u < camera.width());
        EXPECT_TRUE(c.v_begin >= 0 && c.v_end <= camera.height());
      }
    }
  }
}

}  // namespace
}  // namespace houghloc
