#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "tools/recording/recording.h"
#include "tools/render/image_renderer.h"
#include "tools/render/ray_table.h"
#include "vision/camera_model.h"

namespace houghloc {

/// truth/visible.csv (DESIGN §5.1): how much of each map feature a frame really shows. Every
/// feature is sampled every ~2 cm; a sample counts when it lies within max_range_m of the robot,
/// projects into the image (below the horizon) and is not hidden by an opaque object in the
/// rendered occlusion depth.
class VisibilityCounter {
 public:
  explicit VisibilityCounter(const FieldModel& field, double spacing_m = 0.02,
                             double max_range_m = 4.0);

  /// camera: intrinsics and the rendered robot_T_camera of this frame.
  std::vector<VisibleRecord> count(std::int64_t t_us, const Pose2& field_T_robot,
                                   const CameraModel& camera, const FrameView& view,
                                   const RayTable& rays, const RenderBuffers& buffers) const;

 private:
  struct Sample {
    Eigen::Vector2d p_field;
    double length_m;  ///< of the feature this sample stands for
    int feature;      ///< index into names_
  };
  std::vector<Sample> samples_;
  std::vector<std::string> names_;
  std::vector<double> directions_deg_;
  double max_range_m_;
};

}  // namespace houghloc
