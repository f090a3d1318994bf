#pragma once

#include <string>

#include "tools/fieldmap/editor_model/editor_document.h"

namespace houghloc::fieldmap {

/// Opens a map: a field_dimensions.json (".json", SPL import rules, the document keeps its
/// dimensions so it can be exported again) or a YAML map (anything else; when its lines are exactly
/// a rules layout, as after saving a generated field, the document gets those dimensions back).
/// Throws FormatError naming the file and key.
EditorDocument loadDocument(const std::string& path);

/// A standard field by name (spl, spl2019, kid, adult, msl), with its dimensions.
EditorDocument standardDocument(const std::string& name);

/// Writes the YAML map of DESIGN §4; throws FormatError.
void saveDocument(const EditorDocument& doc, const std::string& path);

/// Writes field_dimensions.json; throws FormatError when the map is not rules-shaped (edited by
/// hand since its generation) or its dimensions break the SPL table (e.g. a kid-size line width).
void exportSplJson(const EditorDocument& doc, const std::string& path);

}  // namespace houghloc::fieldmap
