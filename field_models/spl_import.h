#pragma once

#include <string>

#include "field_models/format_error.h"
#include "field_models/standard_fields.h"

namespace houghloc {

/// Import of the RoboCup SPL `field_dimensions.json` exactly as DESIGN §4 defines it: the top
/// level is exactly {"field": {...}, "goal": {...}}, every value is a non-zero JSON number within
/// the range of the table, goalAreaLength and goalAreaWidth come both or neither (neither = the
/// 2019 field without goal areas), and missing, unknown, duplicate or outdated keys are errors.
/// Every error is a FormatError naming the source and the key, e.g.
/// "field_dimensions.json: field.lineWidth: must be exactly 0.05, got 0.04".

/// Parses JSON text; `source_name` names it in error messages (usually the file name).
FieldDimensions parseSplFieldDimensions(const std::string& json_text,
                                        const std::string& source_name);

/// Reads and parses a field_dimensions.json file.
FieldDimensions readSplFieldDimensions(const std::string& path);

/// The dimensions as field_dimensions.json text with the keys of the table above (the goal-area
/// keys left out when goal_area_length is 0). Throws FormatError, naming the key, when a value is
/// outside the table's range (e.g. a line width other than 0.05), since the file would not load.
std::string splFieldDimensionsToJson(const FieldDimensions& dims);

/// makeField(readSplFieldDimensions(path)).
FieldModel importSplField(const std::string& path);

}  // namespace houghloc
