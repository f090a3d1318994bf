#pragma once

#include <opencv2/core.hpp>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "vision/camera_model.h"

namespace houghloc::testing {

/// How the test drawing looks; all colours BGR.
struct SyntheticStyle {
  cv::Vec3b turf{40, 140, 50};
  cv::Vec3b line{235, 235, 235};
  cv::Vec3b background{150, 120, 110};  ///< beyond the carpet and above the horizon
  double gradient = 0.0;     ///< brightness factor change from left to right (0.4 = 1.0 -> 0.6)
  double noise_sigma = 0.0;  ///< Gaussian pixel noise, 0-255
  unsigned seed = 1;
};

/// Draws what `camera` sees of `field` from field_T_robot: green carpet (field plus border),
/// anti-aliased white lines of the map's width, background elsewhere. Independent of the vision
/// code: every pixel is back-projected with the camera model and compared with the map.
cv::Mat drawFieldView(const CameraModel& camera, const FieldModel& field,
                      const Pose2& field_T_robot, const SyntheticStyle& style = {});

}  // namespace houghloc::testing
