#include "vision/vision_config_io.h"

#include <functional>
#include <map>
#include <stdexcept>

namespace houghloc {
namespace {

/// One struct's keys: name -> reader and writer of the member.
struct Field {
  std::function<void(const cv::FileNode&)> read;
  std::function<void(cv::FileStorage&)> write;
};
using Fields = std::map<std::string, Field>;

template <typename T>
Field member(const std::string& name, T* value) {
  return {[value](const cv::FileNode& node) {
            if (node.isInt()) {
              *value = static_cast<T>(static_cast<int>(node));
            } else if (node.isReal()) {
              *value = static_cast<T>(static_cast<double>(node));
            } else {
              throw std::invalid_argument("expected a number");
            }
          },
          [name, value](cv::FileStorage& fs) { fs << name << *value; }};
}

Field member(const std::string& name, bool* value) {
  return {[value](const cv::FileNode& node) {
            if (!node.isInt()) throw std::invalid_argument("expected 0 or 1");
            *value = static_cast<int>(node) != 0;
          },
          [name, value](cv::FileStorage& fs) { fs << name << static_cast<int>(*value); }};
}

#define HL_MEMBER(s, m) \
  { #m, member(#m, &(s).m) }

std::map<std::string, Fields> sections(VisionConfig& c) {
  return {
      {"", {HL_MEMBER(c, line_width_m)}},
      {"horizon", {HL_MEMBER(c.horizon, margin_px)}},
      {"field_color",
       {HL_MEMBER(c.field_color, sample_step_px), HL_MEMBER(c.field_color, histogram_bins),
        HL_MEMBER(c.field_color, min_luma), HL_MEMBER(c.field_color, min_chroma_radius),
        HL_MEMBER(c.field_color, max_chroma_radius), HL_MEMBER(c.field_color, radius_sigmas),
        HL_MEMBER(c.field_color, min_field_share), HL_MEMBER(c.field_color, shadow_luma_ratio),
        HL_MEMBER(c.field_color, white_chroma_ratio)}},
      {"boundary",
       {HL_MEMBER(c.boundary, column_step_px), HL_MEMBER(c.boundary, row_step_px),
        HL_MEMBER(c.boundary, min_green_run), HL_MEMBER(c.boundary, max_spike_px),
        HL_MEMBER(c.boundary, max_spike_passes), HL_MEMBER(c.boundary, min_body_px),
        HL_MEMBER(c.boundary, min_body_width_share)}},
      {"line_width", {HL_MEMBER(c.line_width, grid_cols), HL_MEMBER(c.line_width, grid_rows)}},
      {"scan_grid",
       {HL_MEMBER(c.scan_grid, target_spacing_m), HL_MEMBER(c.scan_grid, min_row_step_px),
        HL_MEMBER(c.scan_grid, min_column_step_px), HL_MEMBER(c.scan_grid, max_step_px),
        HL_MEMBER(c.scan_grid, max_range_m)}},
      {"spots",
       {HL_MEMBER(c.spots, min_contrast), HL_MEMBER(c.spots, noise_contrast),
        HL_MEMBER(c.spots, min_width_ratio), HL_MEMBER(c.spots, max_width_ratio),
        HL_MEMBER(c.spots, width_tolerance_px), HL_MEMBER(c.spots, green_gap_px),
        HL_MEMBER(c.spots, green_gap_width_share), HL_MEMBER(c.spots, dark_luma_ratio)}},
      {"projection",
       {HL_MEMBER(c.projection, max_range_m), HL_MEMBER(c.projection, min_depression_rad),
        HL_MEMBER(c.projection, thin_cell_m), HL_MEMBER(c.projection, weight_range_m),
        HL_MEMBER(c.projection, region_columns)}},
      {"segments",
       {HL_MEMBER(c.segments, enabled), HL_MEMBER(c.segments, link_slope),
        HL_MEMBER(c.segments, link_gap_px), HL_MEMBER(c.segments, link_tolerance_px),
        HL_MEMBER(c.segments, split_distance_m), HL_MEMBER(c.segments, min_length_m),
        HL_MEMBER(c.segments, min_points), HL_MEMBER(c.segments, max_rms_m),
        HL_MEMBER(c.segments, circle_radius_m), HL_MEMBER(c.segments, max_arc_radius_m),
        HL_MEMBER(c.segments, circle_radius_tolerance), HL_MEMBER(c.segments, circle_max_rms_m)}},
      {"pose_correction",
       {HL_MEMBER(c.pose_correction, enabled), HL_MEMBER(c.pose_correction, min_segment_length_m),
        HL_MEMBER(c.pose_correction, max_segment_rms_m),
        HL_MEMBER(c.pose_correction, min_point_sigma_m),
        HL_MEMBER(c.pose_correction, max_pair_angle_rad), HL_MEMBER(c.pose_correction, huber_rad),
        HL_MEMBER(c.pose_correction, step_sigma_rad),
        HL_MEMBER(c.pose_correction, max_correction_rad), HL_MEMBER(c.pose_correction, forgetting),
        HL_MEMBER(c.pose_correction, max_information), HL_MEMBER(c.pose_correction, iterations)}},
  };
}

#undef HL_MEMBER

void readFields(const cv::FileNode& node, const Fields& fields, const std::string& where,
                const std::map<std::string, Fields>* subsections) {
  for (cv::FileNodeIterator it = node.begin(); it != node.end(); ++it) {
    const cv::FileNode child = *it;
    const std::string key = child.name();
    if (subsections && subsections->count(key) && !key.empty()) continue;
    const auto found = fields.find(key);
    if (found == fields.end()) throw std::runtime_error(where + "." + key + ": unknown key");
    try {
      found->second.read(child);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(where + "." + key + ": " + e.what());
    }
  }
}

}  // namespace

VisionConfig readVisionConfig(const cv::FileNode& section, const std::string& source) {
  VisionConfig config;
  if (section.empty() || section.isNone()) return config;
  if (!section.isMap()) throw std::runtime_error(source + ": vision: expected a map");
  const std::map<std::string, Fields> all = sections(config);
  readFields(section, all.at(""), source + ": vision", &all);
  for (const auto& [name, fields] : all) {
    if (name.empty()) continue;
    const cv::FileNode sub = section[name];
    if (sub.empty() || sub.isNone()) continue;
    if (!sub.isMap()) throw std::runtime_error(source + ": vision." + name + ": expected a map");
    readFields(sub, fields, source + ": vision." + name, nullptr);
  }
  return config;
}

void writeVisionConfig(cv::FileStorage& storage, const VisionConfig& config) {
  VisionConfig copy = config;
  const std::map<std::string, Fields> all = sections(copy);
  storage << "vision"
          << "{";
  for (const auto& [key, field] : all.at("")) field.write(storage);
  for (const auto& [name, fields] : all) {
    if (name.empty()) continue;
    storage << name << "{";
    for (const auto& [key, field] : fields) field.write(storage);
    storage << "}";
  }
  storage << "}";
}

}  // namespace houghloc
