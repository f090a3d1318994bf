#pragma once

#include <optional>
#include <vector>

#include "vision/camera_model.h"
#include "vision/line_spots.h"

namespace houghloc {

/// A frame whose line candidates are all too wide for the recorded camera pose is, on a real
/// robot, most often a frame whose pose is off: a head pitched or a body leaning a few to 30 deg
/// more than the kinematics say, so the lines are nearer than the pose puts them. The widths
/// themselves tell the pitch: a line's width in the image grows with its row's distance below
/// the horizon (linearly along a row, quadratically along a column).
struct WidthPitchConfig {
  bool enabled = true;
  double max_offset_rad = 0.52;  ///< pitch offsets tried, up to +-30 deg (a NAO head pitches
                                 ///< 29.5 deg down) ...
  double step_rad = 0.0087;      ///< ... in steps of 0.5 deg
  int min_runs = 6;              ///< the offset must explain at least this many too-wide runs
  double min_share = 0.7;        ///< ... and this share of them (robots, feet and balls vote apart)
  int max_runs = 64;             ///< runs used (evenly spaced among those recorded)
};

/// The camera pitch offset (rad, added to the pose's pitch) under which most of `runs` (the
/// candidates rejected as too wide, LineSpotStats::too_wide_runs, with the widths `camera`'s
/// pose expects for them) have a line's width by `spots`' width tests; none when no offset explains
/// config.min_runs and config.min_share of them. Among offsets that explain equally many, the one
/// whose widths fit best wins.
std::optional<double> fitPitchToWidths(const CameraModel& camera, const std::vector<LineSpot>& runs,
                                       const LineSpotConfig& spots, const WidthPitchConfig& config);

/// For a pose whose pitch is only a lower bound (field_top_pitch.h): the offset in
/// [0, max_offset_rad] (steps of config.step_rad) under which the accepted line spots' widths fit
/// the widths a line has there best (least summed |log(width / expected)|). The range is what
/// bounds it: over a wider one, blur (real widths run wider than the model) and robots' legs
/// pulled such fits to +45 deg.
double fitPitchAboveBound(const CameraModel& camera, const std::vector<LineSpot>& spots,
                          double max_offset_rad, const WidthPitchConfig& config);

}  // namespace houghloc
