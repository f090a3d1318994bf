#pragma once

#include <string>

#include "field_models/field_model.h"

namespace houghloc {

/// The field map a run localizes on, from the command line of houghloc-offline and
/// houghloc-node: `field_file` (read, then validated: a map with a zero-length segment or a
/// misplaced arc would localize wrongly without a sign) or the standard field `standard`. Give
/// exactly one. Throws std::runtime_error naming the file and its first issue, or
/// "--standard: ..." for an unknown name.
FieldModel loadRunField(const std::string& field_file, const std::string& standard);

}  // namespace houghloc
