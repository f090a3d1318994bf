#include "field_models/field_model.h"

namespace houghloc {

std::string describeFeature(const FeatureRef& feature) {
  const char* list = feature.kind == FeatureKind::kSegment ? "segments"
                     : feature.kind == FeatureKind::kArc   ? "arcs"
                                                           : "marks";
  return std::string(list) + "[" + std::to_string(feature.index) + "]";
}

}  // namespace houghloc
