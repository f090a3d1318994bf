#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/field_boundary.h"
#include "vision/field_color.h"
#include "vision/line_width_model.h"
#include "vision/scan_grid.h"

namespace houghloc {

/// How a line spot's run must go on in the scanlines beside it (line_continuation.h): a field
/// line does, a compact white blob of about a line's width (the rim of a ball or a robot's foot
/// seen close by the bottom camera) does not.
struct LineContinuationConfig {
  bool enabled = true;
  double offset_width_share = 0.5;  ///< the scanlines beside lie this share of the spot's width
  int min_offset_px = 2;            ///< ... but at least this many px away
  double max_width_ratio = 1.5;     ///< a run beside continues the spot when its width is within
  double width_tolerance_px = 1.5;  ///< this ratio of the spot's, plus this many px (far lines)
};

/// The ball (ball_spots.h): the chords of its white between the black patches and the rim look
/// like short pieces of line to the spot tests; a spot on a round blob of the ball's size that
/// is not turf, has dark patches and turf around it is dropped.
struct BallConfig {
  bool enabled = true;
  double radius_m = 0.05;            ///< SPL (10 cm ball); KidSize about 0.075, MSL 0.11
  double min_radius_px = 6.0;        ///< balls seen smaller than this are not looked for (on
                                     ///< the real frames 6 drops what 4 does, for less time)
  double min_radius_ratio = 0.5;     ///< the blob's radius as a share of the ball's expected
  double max_radius_ratio = 2.2;     ///< one lies between these: nominal camera poses and
                                     ///< intrinsics put it off by up to 2x (scarrix frames)
  double max_roundness = 1.6;        ///< largest / smallest of its four radii from the centre
  double min_patch_share = 0.1;      ///< samples inside that are dark grey: nearer grey than
  double patch_grey_ratio = 0.4;     ///< this share of the turf's distance to grey, not white
  double ring_ratio = 1.4;           ///< turf sampled at this many radii from the centre ...
  double min_ring_turf_share = 0.5;  ///< ... at least this share (feet or a line may touch it)
};

/// The support a spot needs from the others before it becomes a point (isolated_spots.h; applied
/// to the spots left after the own body and the boundary gap). A run this wide is a line near the
/// camera, which crosses neighbouring scanlines (at most ScanGridConfig::max_step_px, 32 px,
/// apart), so another spot lies within about three of those; alone it is a bar of some object
/// (a robot's arm, leg or foot seen by the bottom camera). Narrow spots need none: a far or faint
/// line often gives one spot only.
struct SpotSupportConfig {
  bool enabled = true;
  double radius_px = 96.0;    ///< another spot (either scan direction) within this distance ...
  double min_width_px = 8.0;  ///< ... for spots at least this wide (LineSpot::width_px)
};

struct LineSpotConfig {
  double min_contrast = 18.0;   ///< luma (0-255) a line must rise above the turf on both sides
  double noise_contrast = 3.5;  ///< ... and at least this many turf noise sigmas: the
                                ///< field's luma sigma, but at most ...
  double max_sigma_over_texture = 2.0;  ///< ... this many texture sigmas (FieldColor): turf that
                                        ///< varies much more over the image than between
                                        ///< neighbours varies with the light (gradients,
                                        ///< vignetting, shadows), which a 2-px rise does not see
  double far_turf_m_per_px = 0.005;     ///< where a pixel covers at least this much ground across
                                        ///< the view (m), the turf is far and its blades blur
                                        ///< together: the rows of a band of such turf cap the
                                        ///< noise sigma with the band's own texture where that is
                                        ///< lower (FieldColor::band_texture_sigma; 0: never)
  // Saturated light (SpotThresholds): a line cannot rise above the sensor's 255, so on bright
  // turf of luma b a run whose peak reaches headroom_min_peak_luma is asked at most
  // headroom_share x (255 - b), but not less than headroom_min_textures x the row's texture
  // (turf near saturation reaches 255 by its own texture). 0 share: no cap.
  double headroom_share = 0.75;
  double headroom_min_textures = 3.0;
  int headroom_min_peak_luma = 250;
  double max_blend_width_px = 4.0;  ///< a run at most this wide (px, half maximum) with turf
                                    ///< on both sides is white when the light it adds over
                                    ///< that turf is: cameras keep chroma at half the luma's
                                    ///< resolution (YUYV, JPEG 4:2:0), so a thin line takes
                                    ///< the turf's chroma and only its luma rises (0: off)
  double min_width_ratio = 0.4;     ///< measured / expected width; worn or anti-aliased lines
  double max_width_ratio = 1.7;     ///< above: robots, feet, ball, posts (the other scan direction
                                    ///< catches lines crossing this one obliquely)
  double width_tolerance_px = 2.0;  ///< added to the allowed width: blur, anti-aliasing
  int green_gap_px = 3;             ///< green must appear within this many px beyond each edge
  double green_gap_width_share = 0.3;    ///< ... plus this share of the expected width
  int min_turf_beside_px = 3;            ///< beyond the first turf pixel on each side, at least
                                         ///< half of this many px must be turf too ...
  double turf_beside_width_share = 0.5;  ///< ... or of this share of the expected width
  double dark_luma_ratio = 0.6;          ///< a non-turf pixel darker than this share of the turf's
                                         ///< median luma between edge and turf rejects the spot;
                                         ///< such dark pixels never count as turf beside a line
  int dark_run_turf_px = 8;  ///< a run rising from a dark pixel (a robot's joint, the shadow under
                             ///< it) is no line's edge; it ends where this many turf px follow
                             ///< in a row, so the scan goes on behind the object (else all that
                             ///< is brighter than the dark pixel passed for the run)
  double max_edge_ramp_px = 8.0;     ///< an edge ramping from peak to turf over more than this
                                     ///< (px; blur and motion blur stay below) ...
  double max_edge_ramp_ratio = 0.2;  ///< ... and this share of the expected width is no paint
                                     ///< but the shading of a round white bar (the goal frame
                                     ///< lying on the ground)
  LineContinuationConfig continuation;
  BallConfig ball;
  SpotSupportConfig support;
  bool keep_rejected = false;  ///< list rejected candidates in LineSpotStats (overlays; slower)
};

/// The centre of a bright run across a scanline that looks like a field line.
struct LineSpot {
  Eigen::Vector2f pixel = Eigen::Vector2f::Zero();  ///< (u, v), distorted image, sub-pixel
  float width_px = 0.f;     ///< measured width along the scanline (half maximum)
  float expected_px = 0.f;  ///< expected width along the scanline for a perpendicular line
  bool vertical_scan = false;
};

/// How a run's width compares with the width a line has at its pixel (LineSpotConfig's width
/// tests): the spot check and the width pitch fit (width_pitch.h) judge runs alike.
enum class WidthFit { kLine, kTooWide, kTooNarrow };
/// widest_px: when the pose's pitch is only a lower bound, the width a line has at that pixel
/// under the steepest pitch admitted (too wide means wider than a line under either).
WidthFit compareLineWidth(double width_px, double expected_px, const LineSpotConfig& config,
                          double widest_px = 0.0);

/// Why a candidate was rejected.
enum class SpotRejection {
  kTooNarrow,
  kTooWide,
  kNotGreenBounded,
  kNotWhite,
  kSoftEdge,
  kCompactBlob,  ///< the run does not go on beside the spot (LineContinuationConfig)
  kOnBall,       ///< the spot lies on a ball (BallConfig)
};

/// A rejected candidate where it lay, for overlays (LineSpotStats::rejected).
struct RejectedSpot {
  Eigen::Vector2f pixel = Eigen::Vector2f::Zero();  ///< (u, v) of the candidate's peak
  SpotRejection reason = SpotRejection::kNotGreenBounded;
};

/// Why candidates were rejected (for diagnostics and tuning).
struct LineSpotStats {
  int candidates = 0;
  int too_narrow = 0;
  int too_wide = 0;
  int not_green_bounded = 0;
  int not_white = 0;
  int soft_edge = 0;     ///< edges ramping too slowly for paint (round bars)
  int compact_blob = 0;  ///< runs that do not go on beside them (ball, feet)
  int on_ball = 0;       ///< spots on a ball (its white between the patches and the rim)
  /// The first kMaxTooWideRuns candidates rejected as too wide, as spots (pixel, width, expected,
  /// scan direction): a frame whose candidates are all too wide may have a pose that is off
  /// (width_pitch.h).
  std::vector<LineSpot> too_wide_runs;
  static constexpr std::size_t kMaxTooWideRuns = 256;
  std::vector<RejectedSpot> rejected;  ///< only with LineSpotConfig::keep_rejected
};

/// Scans the grid's rows and columns below the field boundary for bright, low-saturation runs with
/// turf on both sides whose half-maximum width matches the expected line width there.
/// image: BGR8 or YUYV (pixel_access.h); YUYV pixels are decoded per scanline.
/// widest: for a pose whose pitch is a lower bound (field_top_pitch.h), the widths lines have
/// under the steepest pitch it admits; a run is too wide only when wider than a line under both.
std::vector<LineSpot> detectLineSpots(const cv::Mat& image, const FieldColor& color,
                                      const FieldBoundary& boundary, const ScanGrid& grid,
                                      const LineWidthModel& widths, const LineSpotConfig& config,
                                      LineSpotStats* stats = nullptr,
                                      const LineWidthModel* widest = nullptr);

}  // namespace houghloc
