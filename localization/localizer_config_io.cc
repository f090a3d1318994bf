#include "localization/localizer_config_io.h"

#include "field_models/config_sections.h"

namespace houghloc {
namespace {

// The key is the member's name, so a renamed member renames its key (round-trip tests catch
// a member that was added to a struct but not here only through the equality of the read-back).
#define HL_MEMBER(s, m) configMember(#m, &(s).m)

ConfigSection mapSection(MapSignatureConfig& c) {
  ConfigSection section;
  section.fields = {HL_MEMBER(c, sample_spacing_m), HL_MEMBER(c, dominant_share),
                    HL_MEMBER(c, mask_min_line_m), HL_MEMBER(c, evidence_spacing_m),
                    HL_MEMBER(c, lookup_resolution_m)};
  section.children = {
      {"hough", {{HL_MEMBER(c.hough, theta_step_rad), HL_MEMBER(c.hough, rho_step_m)}}},
      {"grid",
       {{HL_MEMBER(c.grid, resolution_m), HL_MEMBER(c.grid, margin_m),
         HL_MEMBER(c.grid, max_distance_m)}}}};
  return section;
}

ConfigSection globalSection(GlobalHoughConfig& c) {
  ConfigSection section;
  section.fields = {HL_MEMBER(c, max_range_m),        HL_MEMBER(c, max_points),
                    HL_MEMBER(c, prescore_points),    HL_MEMBER(c, min_points),
                    HL_MEMBER(c, min_spread_m),       HL_MEMBER(c, min_observed_weight),
                    HL_MEMBER(c, line_scan_step_m),   HL_MEMBER(c, line_scan_tolerance),
                    HL_MEMBER(c, max_line_scans),     HL_MEMBER(c, parallel_floor_m),
                    HL_MEMBER(c, parallel_floor_rad), HL_MEMBER(c, use_circle),
                    HL_MEMBER(c, use_marks),          HL_MEMBER(c, refine_points),
                    HL_MEMBER(c, parallel_only_share)};
  section.children = {
      {"map", mapSection(c.map)},
      {"orientation",
       {{HL_MEMBER(c.orientation, min_correlation), HL_MEMBER(c.orientation, relative_share),
         HL_MEMBER(c.orientation, max_candidates), HL_MEMBER(c.orientation, suppression_rad)}}},
      {"translation",
       {{HL_MEMBER(c.translation, min_line_weight), HL_MEMBER(c.translation, relative_share),
         HL_MEMBER(c.translation, max_peaks), HL_MEMBER(c.translation, suppression_m)}}},
      {"solver",
       {{HL_MEMBER(c.solver, sigma_rho_m), HL_MEMBER(c.solver, sigma_theta_rad),
         HL_MEMBER(c.solver, sigma_along_m), HL_MEMBER(c.solver, sigma_unknown_m),
         HL_MEMBER(c.solver, min_direction_angle_rad), HL_MEMBER(c.solver, max_pairs),
         HL_MEMBER(c.solver, dominance_ratio)}}},
      {"scoring",
       {{HL_MEMBER(c.scoring, kernel_width_m), HL_MEMBER(c.scoring, inlier_distance_m)}}},
      {"pruning",
       {{HL_MEMBER(c.pruning, min_inlier_share), HL_MEMBER(c.pruning, min_relative_score),
         HL_MEMBER(c.pruning, keep), HL_MEMBER(c.pruning, duplicate_distance_m),
         HL_MEMBER(c.pruning, duplicate_angle_rad)}}},
      {"refinement",
       {{HL_MEMBER(c.refinement, iterations), HL_MEMBER(c.refinement, max_distance_m),
         HL_MEMBER(c.refinement, huber_m), HL_MEMBER(c.refinement, sigma_floor_m),
         HL_MEMBER(c.refinement, effective_points), HL_MEMBER(c.refinement, prior_sigma_m),
         HL_MEMBER(c.refinement, prior_sigma_rad), HL_MEMBER(c.refinement, converged_m)}}},
      {"negative",
       {{HL_MEMBER(c.negative, enabled), HL_MEMBER(c.negative, margin_m),
         HL_MEMBER(c.negative, seen_radius_m), HL_MEMBER(c.negative, line_weight),
         HL_MEMBER(c.negative, outside_weight), HL_MEMBER(c.negative, outside_margin_m),
         HL_MEMBER(c.negative, green_spacing_m), HL_MEMBER(c.negative, raster_m)},
        {{"field_edge",
          {{HL_MEMBER(c.negative.field_edge, enabled), HL_MEMBER(c.negative.field_edge, weight_m),
            HL_MEMBER(c.negative.field_edge, sigma_floor_m),
            HL_MEMBER(c.negative.field_edge, clip_sigmas),
            HL_MEMBER(c.negative.field_edge, nearer_weight),
            HL_MEMBER(c.negative.field_edge, max_range_m),
            HL_MEMBER(c.negative.field_edge, min_samples)}}}}}},
      {"landmarks",
       {{HL_MEMBER(c.landmarks, circle_cell_m), HL_MEMBER(c.landmarks, circle_band_m),
         HL_MEMBER(c.landmarks, circle_min_support), HL_MEMBER(c.landmarks, circle_min_arc_rad),
         HL_MEMBER(c.landmarks, mark_link_m), HL_MEMBER(c.landmarks, mark_isolation_m),
         HL_MEMBER(c.landmarks, mark_min_points), HL_MEMBER(c.landmarks, max_marks),
         HL_MEMBER(c.landmarks, heading_scan_step_rad), HL_MEMBER(c.landmarks, heading_scan_maxima),
         HL_MEMBER(c.landmarks, circle_tangent_factor)}}},
      {"hypotheses",
       {{HL_MEMBER(c.hypotheses, merge_distance_m), HL_MEMBER(c.hypotheses, merge_angle_rad),
         HL_MEMBER(c.hypotheses, temperature), HL_MEMBER(c.hypotheses, max_hypotheses)}}}};
  return section;
}

ConfigSection updateSection(PointUpdateConfig& c) {
  ConfigSection section;
  section.fields = {HL_MEMBER(c, point_sigma_m),
                    HL_MEMBER(c, max_association_m),
                    HL_MEMBER(c, gate_chi2),
                    configEnumMember("kernel", &c.kernel,
                                     {{"huber", PointUpdateConfig::Kernel::kHuber},
                                      {"cauchy", PointUpdateConfig::Kernel::kCauchy}}),
                    HL_MEMBER(c, kernel_sigmas),
                    HL_MEMBER(c, max_iterations),
                    HL_MEMBER(c, max_iteration_points),
                    HL_MEMBER(c, poor_association_share),
                    HL_MEMBER(c, converged_m),
                    HL_MEMBER(c, converged_rad),
                    HL_MEMBER(c, max_effective_points),
                    HL_MEMBER(c, min_points),
                    HL_MEMBER(c, likelihood_sigma_m),
                    HL_MEMBER(c, outlier_chi2),
                    HL_MEMBER(c, inlier_m),
                    HL_MEMBER(c, search_min_sigma_m),
                    HL_MEMBER(c, search_step_m),
                    HL_MEMBER(c, search_sigmas),
                    HL_MEMBER(c, search_max_starts),
                    HL_MEMBER(c, pitch_sigma_rad),
                    HL_MEMBER(c, roll_sigma_rad),
                    HL_MEMBER(c, tilt_min_gain)};
  return section;
}

ConfigSection trackerSection(TrackerConfig& c) {
  ConfigSection section;
  section.fields = {HL_MEMBER(c, likelihood_points),     HL_MEMBER(c, likelihood_deadband),
                    HL_MEMBER(c, injected_share),        HL_MEMBER(c, periodic_injected_share),
                    HL_MEMBER(c, hint_add_share),        HL_MEMBER(c, min_points_to_judge),
                    HL_MEMBER(c, disagree_inlier_share), HL_MEMBER(c, disagree_frames),
                    HL_MEMBER(c, share_drop_slack),      HL_MEMBER(c, share_drop_alarm),
                    HL_MEMBER(c, expected_share_rate),   HL_MEMBER(c, low_best_weight),
                    HL_MEMBER(c, lost_sigma_m),          HL_MEMBER(c, periodic_global_s),
                    HL_MEMBER(c, lost_without_points_s), HL_MEMBER(c, mirror_tolerance_m),
                    HL_MEMBER(c, mirror_tolerance_rad),  HL_MEMBER(c, ambiguous_weight_ratio),
                    HL_MEMBER(c, own_half_margin_m),     HL_MEMBER(c, belief_floor),
                    HL_MEMBER(c, belief_spread_m),       HL_MEMBER(c, belief_spread_rad),
                    HL_MEMBER(c, hint_prior_s),          HL_MEMBER(c, best_weight_drop_ratio)};
  section.children = {
      {"motion",
       {{HL_MEMBER(c.motion, trans_var_per_m), HL_MEMBER(c.motion, trans_var_per_rad),
         HL_MEMBER(c.motion, rot_var_per_rad), HL_MEMBER(c.motion, rot_var_per_m),
         HL_MEMBER(c.motion, trans_var_per_s), HL_MEMBER(c.motion, rot_var_per_s),
         HL_MEMBER(c.motion, unknown_trans_var_per_s), HL_MEMBER(c.motion, unknown_rot_var_per_s),
         HL_MEMBER(c.motion, max_sigma_xy_m), HL_MEMBER(c.motion, max_sigma_theta_rad)}}},
      {"odometry",
       {{HL_MEMBER(c.odometry, max_speed_m_per_s), HL_MEMBER(c.odometry, max_turn_rad_per_s),
         HL_MEMBER(c.odometry, jump_slack_m), HL_MEMBER(c.odometry, jump_slack_rad),
         HL_MEMBER(c.odometry, timeout_s), HL_MEMBER(c.odometry, max_dt_s)}}},
      {"update", updateSection(c.update)},
      {"set",
       {{HL_MEMBER(c.set, max_hypotheses), HL_MEMBER(c.set, merge_chi2),
         HL_MEMBER(c.set, merge_distance_m), HL_MEMBER(c.set, merge_angle_rad),
         HL_MEMBER(c.set, merge_max_distance_m), HL_MEMBER(c.set, merge_max_angle_rad),
         HL_MEMBER(c.set, prune_relative_weight)}}},
      {"index", {{HL_MEMBER(c.index, resolution_m), HL_MEMBER(c.index, margin_m)}}}};
  return section;
}

ConfigSection localizerSection(LocalizerConfig& c) {
  ConfigSection section;
  section.fields = {HL_MEMBER(c, max_injected_hypotheses), HL_MEMBER(c, fallen_camera_height_m),
                    HL_MEMBER(c, fallen_tilt_rad), HL_MEMBER(c, global_frames_after_fall)};
  return section;
}

#undef HL_MEMBER

}  // namespace

LocalizerConfig readLocalizerConfig(const cv::FileNode& root, const std::string& source) {
  LocalizerConfig config;
  if (root.empty() || root.isNone()) return config;
  if (!root.isMap()) throw std::runtime_error(source + ": expected a map at the top level");
  readConfigSection(root["global"], globalSection(config.global), source + ": global");
  readConfigSection(root["tracker"], trackerSection(config.tracker), source + ": tracker");
  readConfigSection(root["localizer"], localizerSection(config), source + ": localizer");
  return config;
}

void writeLocalizerConfig(cv::FileStorage& storage, const LocalizerConfig& config) {
  LocalizerConfig copy = config;
  writeConfigSection(storage, "global", globalSection(copy.global));
  writeConfigSection(storage, "tracker", trackerSection(copy.tracker));
  writeConfigSection(storage, "localizer", localizerSection(copy));
}

}  // namespace houghloc
