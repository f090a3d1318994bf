#include "vision/vision_config_io.h"

#include "field_models/config_sections.h"

namespace houghloc {
namespace {

#define HL_MEMBER(s, m) configMember(#m, &(s).m)

/// Every VisionConfig member bound by name: the keys of the `vision:` section.
ConfigSection visionSection(VisionConfig& c) {
  ConfigSection section;
  section.fields = {HL_MEMBER(c, line_width_m)};
  section.children = {
      {"horizon", {{HL_MEMBER(c.horizon, margin_px)}}},
      {"field_color",
       {{HL_MEMBER(c.field_color, sample_step_px),
         HL_MEMBER(c.field_color, histogram_bins),
         HL_MEMBER(c.field_color, min_luma),
         HL_MEMBER(c.field_color, min_chroma_radius),
         HL_MEMBER(c.field_color, max_chroma_radius),
         HL_MEMBER(c.field_color, radius_sigmas),
         HL_MEMBER(c.field_color, min_field_share),
         HL_MEMBER(c.field_color, shadow_luma_ratio),
         HL_MEMBER(c.field_color, white_chroma_ratio),
         HL_MEMBER(c.field_color, chroma_noise),
         HL_MEMBER(c.field_color, max_candidates),
         HL_MEMBER(c.field_color, bottom_band_share),
         HL_MEMBER(c.field_color, bottom_weight_floor),
         HL_MEMBER(c.field_color, clear_grey_distance),
         HL_MEMBER(c.field_color, min_grey_distance),
         HL_MEMBER(c.field_color, min_green_over_red),
         HL_MEMBER(c.field_color, max_grey_share),
         HL_MEMBER(c.field_color, memory_bonus),
         HL_MEMBER(c.field_color, memory_frames),
         HL_MEMBER(c.field_color, min_light_share),
         HL_MEMBER(c.field_color, min_light_ratio),
         HL_MEMBER(c.field_color, max_other_light_distance),
         HL_MEMBER(c.field_color, texture_bands),
         HL_MEMBER(c.field_color, min_band_samples)}}},
      {"boundary",
       {{HL_MEMBER(c.boundary, column_step_px), HL_MEMBER(c.boundary, row_step_px),
         HL_MEMBER(c.boundary, min_green_run), HL_MEMBER(c.boundary, max_spike_px),
         HL_MEMBER(c.boundary, max_spike_passes), HL_MEMBER(c.boundary, min_body_px),
         HL_MEMBER(c.boundary, min_body_width_share),
         HL_MEMBER(c.boundary, body_height_tolerance)}}},
      {"line_width", {{HL_MEMBER(c.line_width, grid_cols), HL_MEMBER(c.line_width, grid_rows)}}},
      {"scan_grid",
       {{HL_MEMBER(c.scan_grid, target_spacing_m), HL_MEMBER(c.scan_grid, min_row_step_px),
         HL_MEMBER(c.scan_grid, min_column_step_px), HL_MEMBER(c.scan_grid, max_step_px),
         HL_MEMBER(c.scan_grid, max_range_m), HL_MEMBER(c.scan_grid, range_pitch_margin_rad),
         HL_MEMBER(c.scan_grid, margin_row_step_px)}}},
      {"spots",
       {{HL_MEMBER(c.spots, min_contrast),           HL_MEMBER(c.spots, noise_contrast),
         HL_MEMBER(c.spots, max_sigma_over_texture), HL_MEMBER(c.spots, min_width_ratio),
         HL_MEMBER(c.spots, max_width_ratio),        HL_MEMBER(c.spots, width_tolerance_px),
         HL_MEMBER(c.spots, green_gap_px),           HL_MEMBER(c.spots, green_gap_width_share),
         HL_MEMBER(c.spots, min_turf_beside_px),     HL_MEMBER(c.spots, turf_beside_width_share),
         HL_MEMBER(c.spots, dark_luma_ratio),        HL_MEMBER(c.spots, dark_run_turf_px),
         HL_MEMBER(c.spots, max_edge_ramp_px),       HL_MEMBER(c.spots, max_edge_ramp_ratio),
         HL_MEMBER(c.spots, max_blend_width_px),     HL_MEMBER(c.spots, far_turf_m_per_px),
         HL_MEMBER(c.spots, headroom_share),         HL_MEMBER(c.spots, headroom_min_textures),
         HL_MEMBER(c.spots, headroom_min_peak_luma), HL_MEMBER(c.spots, keep_rejected)},
        {{"continuation",
          {{HL_MEMBER(c.spots.continuation, enabled),
            HL_MEMBER(c.spots.continuation, offset_width_share),
            HL_MEMBER(c.spots.continuation, min_offset_px),
            HL_MEMBER(c.spots.continuation, max_width_ratio),
            HL_MEMBER(c.spots.continuation, width_tolerance_px)}}},
         {"ball",
          {{HL_MEMBER(c.spots.ball, enabled), HL_MEMBER(c.spots.ball, radius_m),
            HL_MEMBER(c.spots.ball, min_radius_px), HL_MEMBER(c.spots.ball, min_radius_ratio),
            HL_MEMBER(c.spots.ball, max_radius_ratio), HL_MEMBER(c.spots.ball, max_roundness),
            HL_MEMBER(c.spots.ball, min_patch_share), HL_MEMBER(c.spots.ball, patch_grey_ratio),
            HL_MEMBER(c.spots.ball, ring_ratio), HL_MEMBER(c.spots.ball, min_ring_turf_share)}}},
         {"support",
          {{HL_MEMBER(c.spots.support, enabled), HL_MEMBER(c.spots.support, radius_px),
            HL_MEMBER(c.spots.support, min_width_px)}}}}}},
      {"projection",
       {{HL_MEMBER(c.projection, max_range_m), HL_MEMBER(c.projection, min_depression_rad),
         HL_MEMBER(c.projection, thin_cell_m), HL_MEMBER(c.projection, weight_range_m),
         HL_MEMBER(c.projection, region_columns), HL_MEMBER(c.projection, min_boundary_gap_m),
         HL_MEMBER(c.projection, min_boundary_gap_range_m)}}},
      {"own_body",
       {{HL_MEMBER(c.own_body, front_m), HL_MEMBER(c.own_body, back_m),
         HL_MEMBER(c.own_body, half_width_m)}}},
      {"field_edge",
       {{HL_MEMBER(c.field_edge, columns), HL_MEMBER(c.field_edge, row_sigma_px),
         HL_MEMBER(c.field_edge, max_range_m), HL_MEMBER(c.field_edge, min_rows_below_start)}}},
      {"segments",
       {{HL_MEMBER(c.segments, enabled), HL_MEMBER(c.segments, link_slope),
         HL_MEMBER(c.segments, link_gap_px), HL_MEMBER(c.segments, link_tolerance_px),
         HL_MEMBER(c.segments, split_distance_m), HL_MEMBER(c.segments, min_length_m),
         HL_MEMBER(c.segments, min_points), HL_MEMBER(c.segments, max_rms_m),
         HL_MEMBER(c.segments, circle_radius_m), HL_MEMBER(c.segments, max_arc_radius_m),
         HL_MEMBER(c.segments, circle_radius_tolerance), HL_MEMBER(c.segments, circle_max_rms_m)}}},
      {"width_pitch",
       {{HL_MEMBER(c.width_pitch, enabled), HL_MEMBER(c.width_pitch, max_offset_rad),
         HL_MEMBER(c.width_pitch, step_rad), HL_MEMBER(c.width_pitch, min_runs),
         HL_MEMBER(c.width_pitch, min_share), HL_MEMBER(c.width_pitch, max_runs)}}},
      {"field_top_pitch",
       {{HL_MEMBER(c.field_top_pitch, enabled), HL_MEMBER(c.field_top_pitch, column_step_px),
         HL_MEMBER(c.field_top_pitch, row_step_px), HL_MEMBER(c.field_top_pitch, max_gap_px),
         HL_MEMBER(c.field_top_pitch, min_luma_ratio), HL_MEMBER(c.field_top_pitch, min_rise_rad),
         HL_MEMBER(c.field_top_pitch, min_share), HL_MEMBER(c.field_top_pitch, quantile),
         HL_MEMBER(c.field_top_pitch, border_depression_rad),
         HL_MEMBER(c.field_top_pitch, max_shortfall_rad),
         HL_MEMBER(c.field_top_pitch, max_offset_rad)}}},
      {"pose_correction",
       {{HL_MEMBER(c.pose_correction, enabled),
         HL_MEMBER(c.pose_correction, min_segment_length_m),
         HL_MEMBER(c.pose_correction, max_segment_rms_m),
         HL_MEMBER(c.pose_correction, min_segment_points),
         HL_MEMBER(c.pose_correction, min_point_sigma_m),
         HL_MEMBER(c.pose_correction, max_segments_per_frame),
         HL_MEMBER(c.pose_correction, window_frames),
         HL_MEMBER(c.pose_correction, max_residual_rad),
         HL_MEMBER(c.pose_correction, huber_sigmas),
         HL_MEMBER(c.pose_correction, prior_sigma_rad),
         HL_MEMBER(c.pose_correction, max_correction_rad),
         HL_MEMBER(c.pose_correction, iterations),
         HL_MEMBER(c.pose_correction, relinearize_rad),
         HL_MEMBER(c.pose_correction, runaway_restart_frames),
         HL_MEMBER(c.pose_correction, runaway_restart_solves),
         HL_MEMBER(c.pose_correction, min_frames),
         HL_MEMBER(c.pose_correction, use_circles),
         HL_MEMBER(c.pose_correction, max_circle_residual_m),
         HL_MEMBER(c.pose_correction, significance_sigmas),
         HL_MEMBER(c.pose_correction, min_correction_rad),
         HL_MEMBER(c.pose_correction, shared_between_cameras)},
        {{"map",
          {{HL_MEMBER(c.pose_correction.map, enabled),
            HL_MEMBER(c.pose_correction.map, max_points_per_frame),
            HL_MEMBER(c.pose_correction.map, max_range_m),
            HL_MEMBER(c.pose_correction.map, search_radius_m),
            HL_MEMBER(c.pose_correction.map, gate_m), HL_MEMBER(c.pose_correction.map, min_inliers),
            HL_MEMBER(c.pose_correction.map, min_inlier_share),
            HL_MEMBER(c.pose_correction.map, pose_fit_iterations),
            HL_MEMBER(c.pose_correction.map, max_pose_shift_m),
            HL_MEMBER(c.pose_correction.map, max_pose_turn_rad),
            HL_MEMBER(c.pose_correction.map, min_points_per_line),
            HL_MEMBER(c.pose_correction.map, min_spread_m)}}}}}},
  };
  return section;
}

#undef HL_MEMBER

}  // namespace

VisionConfig readVisionConfig(const cv::FileNode& section, const std::string& source) {
  VisionConfig config;
  readConfigSection(section, visionSection(config), source + ": vision");
  return config;
}

void writeVisionConfig(cv::FileStorage& storage, const VisionConfig& config) {
  VisionConfig copy = config;
  writeConfigSection(storage, "vision", visionSection(copy));
}

}  // namespace houghloc
