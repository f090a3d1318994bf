#include "tools/fieldmap/editor_model/document_io.h"

#include <fstream>

#include "field_models/field_yaml.h"
#include "field_models/spl_import.h"

namespace houghloc::fieldmap {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

EditorDocument loadDocument(const std::string& path) {
  if (endsWith(path, ".json")) {
    const FieldDimensions dims = readSplFieldDimensions(path);
    return EditorDocument(makeField(dims), dims);
  }
  return EditorDocument(readFieldYaml(path));
}

EditorDocument standardDocument(const std::string& name) {
  const FieldDimensions dims = standardFieldDimensions(name);
  return EditorDocument(makeField(dims), dims);
}

void saveDocument(const EditorDocument& doc, const std::string& path) {
  writeFieldYaml(doc.field(), path);
}

void exportSplJson(const EditorDocument& doc, const std::string& path) {
  if (!doc.isRulesShaped()) {
    throw FormatError(path +
                      ": the map is not a rules-shaped field (edited by hand since it was "
                      "generated from dimensions); field_dimensions.json cannot describe it");
  }
  const std::string text = splFieldDimensionsToJson(*doc.rules());
  std::ofstream out(path, std::ios::binary);
  if (!(out << text)) throw FormatError(path + ": cannot write");
}

}  // namespace houghloc::fieldmap
