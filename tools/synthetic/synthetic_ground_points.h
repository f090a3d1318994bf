#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/ground_points.h"
#include "field_models/pose2.h"

namespace houghloc {

/// A simple camera footprint on the ground: a wedge in front of the robot (robot frame).
struct ViewModel {
  std::string name;
  double half_angle_rad = 0.49;    ///< half the horizontal opening
  double min_range_m = 0.4;        ///< nearest ground seen
  double max_range_m = 4.5;        ///< farthest line points reported
  double camera_height_m = 0.5;    ///< for the field edge's range error: a row error of d alpha
                                   ///< moves a ground point at range r by (r^2 + h^2) / h d alpha
  double pixel_rad = 0.0017;       ///< angle of one pixel
  double image_far_range_m = 1e9;  ///< farthest ground in the image (the image top); the
                                   ///< horizon's infinity when it is in view
};

/// nao-top (+-28 deg, 0.4-4.5 m, 0.50 m high), nao-bottom (+-30 deg, 0.15-1.2 m, 0.45 m),
/// kid-wide (+-60 deg, 0.3-5 m, 0.90 m), adult (+-35 deg, 0.6-7 m, 1.40 m), wide-pinhole (+-45 deg,
/// 0.45-4.5 m, 0.50 m); pixel angles as the camera presets; only nao-bottom's image ends before
/// the horizon (at 1.2 m).
std::vector<std::string> viewModelNames();
/// Throws std::invalid_argument naming the unknown view.
ViewModel viewModel(const std::string& name);

struct SyntheticConfig {
  ViewModel view = viewModel("nao-top");
  double point_spacing_m = 0.05;  ///< between points along lines and arcs
  double noise_sigma_m = 0.01;    ///< isotropic position noise at the robot ...
  double noise_per_m = 0.004;     ///< ... growing by this per metre of range
  double outlier_share = 0.05;    ///< extra random points in view, share of the line points
  int occluders = 0;              ///< robots standing in view (discs hiding what is behind)
  double occluder_radius_m = 0.2;
  bool marks = true;            ///< report points on the marks
  bool visible_region = true;   ///< fill GroundPoints::visible_regions
  int field_edge_samples = 24;  ///< bearings across the view with a GroundPoints::field_edge
                                ///< sample (0: none); an occluder in the way gives its distance
  double field_edge_sigma_px = 2.0;      ///< error of the detected boundary row
  double field_edge_max_range_m = 30.0;  ///< farther edges are too close to the horizon
  std::uint64_t seed = 1;
};

/// Ground truth of what was in view (unoccluded, before noise) per feature, like
/// truth/visible.csv (DESIGN §5.1).
struct VisibleFeature {
  FeatureRef feature;
  double length_m = 0.0;       ///< visible length
  double direction_rad = 0.0;  ///< segment direction in [0, pi); NaN for arcs and marks
};

struct SyntheticFrame {
  Pose2 field_T_robot;
  GroundPoints ground;
  std::vector<VisibleFeature> visible;
};

/// Points along the map's lines, arcs and marks that fall into the view (noise, outliers,
/// occlusions as configured, deterministic for a seed), the visible region: the wedge minus
/// the occluders' shadows, clipped to the carpet (field plus border strip), and the carpet's
/// edge along bearings across the view at any range up to field_edge_max_range_m.
SyntheticFrame generateFrame(const FieldModel& field, const Pose2& field_T_robot,
                             const SyntheticConfig& config);

/// DESIGN §5.3: >= 0.5 m of lines in two directions at least 30 deg apart, or >= 1 m of circle.
bool hasTwoDirections(const SyntheticFrame& frame);
/// Only parallel lines (>= 0.5 m in one direction, < 0.2 m in any other, < 0.3 m of arcs and no
/// mark in view).
bool hasOnlyParallelLines(const SyntheticFrame& frame);

/// A uniformly random pose within the field plus `margin_m`, any heading.
Pose2 randomPose(const FieldModel& field, double margin_m, std::mt19937_64& rng);

}  // namespace houghloc
