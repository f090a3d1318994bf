#include "tools/fieldmap/editor_model/document_validation.h"

#include <cstdlib>

namespace houghloc::fieldmap {
namespace {

/// "segments[3]" -> the id of segments[3]; nullopt for other `where`s ("line_width", "map").
std::optional<FeatureId> featureOf(const EditorDocument& doc, const std::string& where) {
  static const std::pair<const char*, EditorKind> kLists[] = {{"segments[", EditorKind::kSegment},
                                                              {"arcs[", EditorKind::kArc},
                                                              {"marks[", EditorKind::kMark},
                                                              {"goals[", EditorKind::kGoal}};
  for (const auto& [prefix, kind] : kLists) {
    const std::string p = prefix;
    if (where.compare(0, p.size(), p) != 0) continue;
    const int index = std::atoi(where.c_str() + p.size());
    if (index >= 0 && index < static_cast<int>(doc.ids(kind).size())) return doc.idAt(kind, index);
  }
  return std::nullopt;
}

}  // namespace

std::vector<DocumentIssue> validateDocument(const EditorDocument& doc,
                                            const FieldValidationConfig& config) {
  std::vector<DocumentIssue> out;
  for (const FieldIssue& issue : validateField(doc.field(), config)) {
    const std::optional<FeatureId> feature = featureOf(doc, issue.where);
    out.push_back(
        {feature, (feature ? describeFeatureId(*feature) + " (" + issue.where + ")" : issue.where) +
                      ": " + issue.problem});
  }
  return out;
}

}  // namespace houghloc::fieldmap
