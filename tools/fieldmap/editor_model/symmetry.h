#pragma once

#include <vector>

#include "tools/fieldmap/editor_model/edit_commands.h"

namespace houghloc::fieldmap {

/// The symmetries of a field (DESIGN §3 frame): a half turn about the centre mark, and the
/// reflections across the x axis (y -> -y, left/right) and the y axis (x -> -x, the halfway line).
enum class Mirror { kThroughCenter, kAcrossXAxis, kAcrossYAxis };

Eigen::Vector2d mirrored(const Eigen::Vector2d& p, Mirror mirror);
Segment2 mirrored(const Segment2& s, Mirror mirror);
/// The mirrored arc, still counter-clockwise with start in (-pi, pi].
Arc2 mirrored(const Arc2& a, Mirror mirror);

/// Adds a mirrored copy of every listed feature (goals and marks included), so that one half
/// drawn by hand gives the other.
Edit mirrorFeatures(const EditorDocument& doc, const std::vector<FeatureId>& features,
                    Mirror mirror);

}  // namespace houghloc::fieldmap
