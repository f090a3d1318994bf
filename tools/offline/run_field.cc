#include "tools/offline/run_field.h"

#include <stdexcept>
#include <vector>

#include "field_models/field_validation.h"
#include "field_models/field_yaml.h"
#include "field_models/standard_fields.h"

namespace houghloc {

FieldModel loadRunField(const std::string& field_file, const std::string& standard) {
  if (field_file.empty() == standard.empty())
    throw std::invalid_argument("loadRunField: give a field file or a standard name");
  if (!standard.empty()) {
    try {
      return makeStandardField(standard);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(std::string("--standard: ") + e.what());
    }
  }
  FieldModel field = readFieldYaml(field_file);
  const std::vector<FieldIssue> issues = validateField(field);
  if (!issues.empty()) {
    throw std::runtime_error(field_file + ": " + issues.front().toString() + " (" +
                             std::to_string(issues.size()) +
                             " issue(s), houghloc-fieldmap validate lists them)");
  }
  return field;
}

}  // namespace houghloc
