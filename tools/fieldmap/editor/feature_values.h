#pragma once

#include <QString>
#include <vector>

#include "tools/fieldmap/editor_model/edit_commands.h"

namespace houghloc::fieldmap {

/// The property panel's view of one feature as labelled numbers (m, arc angles in degrees), and
/// the edit that writes numbers back.
std::vector<QString> featureLabels(EditorKind kind);
std::vector<double> featureValues(const EditorDocument& doc, const FeatureId& f);
Edit setFeatureValues(const EditorDocument& doc, const FeatureId& f,
                      const std::vector<double>& values);

/// The dimensions panel: the rules dimensions as labelled numbers (m) and back.
std::vector<QString> dimensionLabels();
std::vector<double> dimensionValues(const FieldDimensions& dims);
FieldDimensions dimensionsFrom(FieldDimensions base, const std::vector<double>& values);

/// The dimensions shown for a document: its rules, or the SPL defaults with its header.
FieldDimensions dimensionsOf(const EditorDocument& doc);

}  // namespace houghloc::fieldmap
