#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace houghloc {

/// Colour and sensor statistics of one camera image, measured the same way on real and rendered
/// frames so the two can be compared (docs/render.md "Renders beside real frames"). Chromaticity
/// r = R / (R + G + B), g likewise; luma is BT.601 (0..255). NaN where a quantity could not be
/// measured in the frame (no turf sample, no line pixels, too few pixels).
struct FrameStatistics {
  // Turf: pixels below the horizon whose colour lies near the sample's median (see .cc).
  double turf_r = 0.0, turf_g = 0.0, turf_luma = 0.0;  ///< medians
  double turf_r_spread = 0.0, turf_g_spread = 0.0;     ///< robust sigma (1.4826 MAD)
  double turf_luma_spread = 0.0;                       ///< robust sigma, grey levels
  double turf_share = 0.0;        ///< share of the whole image that is turf-coloured
  double background_share = 0.0;  ///< share of the image above the horizon
  // Lines: the label mask's line pixels, or bright, nearly grey pixels below the horizon.
  double line_contrast = 0.0;         ///< median luma of line pixels minus the turf's
  double line_r = 0.0, line_g = 0.0;  ///< median chromaticity of line pixels
  double line_share = 0.0;            ///< share of the image
  /// Line contrast over the steepest luma slope across the lines' edges (px): a sharp step
  /// reads 2 (central differences), a Gaussian blur of sigma s about 2.5 s.
  double edge_width_px = 0.0;
  /// Robust sigma of luma minus its 3x3 mean on flat turf, scaled to the sigma of white noise
  /// (grey levels): sensor noise plus the turf's fine texture.
  double noise_sigma = 0.0;
  /// Turf luma in the image's outer ring (radius > 0.8 of the corner distance) over turf luma
  /// within 0.35 of it: 1 without vignetting (and without a lighting gradient).
  double vignetting_ratio = 0.0;
  double image_luma = 0.0;              ///< median luma of the whole image
  double image_r = 0.0, image_g = 0.0;  ///< mean chromaticity of the whole image (light tint)
};

/// Measures one BGR image. horizon_rows: CameraModel::horizonRows() of the frame (rows below
/// see the ground; +-infinity allowed); line_mask: optional labels (1 = line), image size.
FrameStatistics measureFrame(const cv::Mat3b& bgr, const std::vector<double>& horizon_rows,
                             const cv::Mat1b& line_mask = cv::Mat1b());

/// Medians over the frames of a recorded folder (DESIGN §5.1).
struct FolderStatistics {
  std::string folder;
  int frames = 0;
  int masked_frames = 0;  ///< frames whose lines came from labels/<stem>.png
  int frames_with_lines = 0;
  FrameStatistics median;  ///< per member: the median over frames where it is not NaN
};

/// Reads the recorded folder and measures at most max_frames frames, evenly spread (0: all).
/// Throws RecordingError on a malformed folder, std::runtime_error on an unreadable image.
FolderStatistics measureFolder(const std::string& folder, int max_frames = 0);

}  // namespace houghloc
