#pragma once

#include <optional>
#include <string>
#include <vector>

#include "field_models/field_validation.h"
#include "tools/fieldmap/editor_model/editor_document.h"

namespace houghloc::fieldmap {

/// One validateField() issue with the feature it concerns (none for map-wide issues such as
/// "line_width"), so the editor can select it.
struct DocumentIssue {
  std::optional<FeatureId> feature;
  std::string text;  ///< "segment 7: zero length" or "line_width: must be > 0, got 0"
};

/// The rules of `houghloc-fieldmap validate` (validateField) on the document's map.
std::vector<DocumentIssue> validateDocument(const EditorDocument& doc,
                                            const FieldValidationConfig& config = {});

}  // namespace houghloc::fieldmap
