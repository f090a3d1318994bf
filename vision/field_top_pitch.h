#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "vision/camera_model.h"
#include "vision/field_color.h"

namespace houghloc {

/// A frame whose field reaches well above the horizon computed from its pose is, on a real robot,
/// a frame whose camera looks further down than the pose says (a head pitched or a body leaning
/// more than the kinematics or a nominal pose say): the field's lines lie above the computed
/// horizon, where nothing is scanned. The ground plane's horizon lies above the whole field in
/// the image, so the field's top seen in the image bounds the pitch from below.
struct FieldTopPitchConfig {
  bool enabled = true;
  int column_step_px = 16;      ///< columns followed up from their scan start row ...
  int row_step_px = 4;          ///< ... sample by sample
  int max_gap_px = 12;          ///< the field goes on across this many non-field pixels (a line, a
                                ///< ball); beyond, what is above is no longer the turf
  double min_luma_ratio = 0.6;  ///< turf is at least this share of the turf's median luma below
                                ///< the horizon (dark curtains, walls, crowds pass the colour test)
  double min_rise_rad = 0.035;  ///< the field's top must lie this far above the computed
                                ///< horizon (2 deg; smaller errors lose only far ground) ...
  double min_share = 0.5;       ///< ... in this share of the columns whose start row is field
  double quantile = 0.5;  ///< the offset lifts the horizon above this share of the tops (robots
                          ///< before the border push some down, dark clutter beyond it that
                          ///< passes for turf some up) ...
  double border_depression_rad = 0.05;  ///< ... and this much more: the far border seen from a
                                        ///< 0.5 m camera 10 m away lies 2.9 deg below the horizon
  double max_shortfall_rad = 0.115;  ///< the real pitch may exceed the bound by this much (a border
                                     ///< 3 m from a 0.5 m camera lies 9.5 deg below the horizon,
                                     ///< 6.6 deg more than assumed): a frame scanned with the bound
                                     ///< accepts runs as wide as a line under the pitch plus this
                                     ///< (lines are nearer and wider than the bound's pose says)
  double max_offset_rad = 0.52;      ///< at most +30 deg (a NAO head pitches 29.5 deg down)
};

/// The camera pitch offset (rad, positive: further down, added to the pose's pitch) that puts
/// `camera`'s horizon above the field seen in `image`: in sampled columns the turf (`color`) is
/// followed up from the scan start row (`start_rows`, just below the computed horizon) to where
/// it ends. None when the field does not reach config.min_rise_rad above the horizontal in
/// config.min_share of the columns, or the offset would exceed config.max_offset_rad.
/// image: BGR8 or YUYV (pixel_access.h).
std::optional<double> pitchToSeeFieldTop(const cv::Mat& image, const FieldColor& color,
                                         const CameraModel& camera,
                                         const std::vector<int>& start_rows,
                                         const FieldTopPitchConfig& config);

}  // namespace houghloc
