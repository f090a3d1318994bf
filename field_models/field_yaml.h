#pragma once

#include <string>

#include "field_models/field_model.h"
#include "field_models/format_error.h"

namespace houghloc {

/// The field-map YAML of DESIGN §4, read and written with cv::FileStorage. Numbers are written
/// with 17 significant digits, so write-then-read gives back exactly the same doubles.
///
/// Reading checks the format only (keys, types, counts); whether the geometry makes sense is
/// validateField()'s job. Errors are FormatError naming the source and the entry, e.g.
/// "field.yaml: segments[3]: expected 4 numbers, got 3".

/// Reads a map file; throws FormatError.
FieldModel readFieldYaml(const std::string& path);

/// Parses map text; `source_name` names it in error messages (usually the file name).
FieldModel parseFieldYaml(const std::string& text, const std::string& source_name);

/// The map as YAML text (with the "%YAML:1.0" header FileStorage needs). Throws FormatError when
/// the name contains a double quote or a line break, which FileStorage cannot write back exactly.
std::string fieldToYaml(const FieldModel& field);

/// Writes fieldToYaml(field) to `path`; throws FormatError when the file cannot be written.
void writeFieldYaml(const FieldModel& field, const std::string& path);

}  // namespace houghloc
