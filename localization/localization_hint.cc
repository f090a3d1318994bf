#include "localization/localization_hint.h"

#include <array>
#include <utility>

namespace houghloc {
namespace {

constexpr std::array<std::pair<HintKind, const char*>, 5> kNames = {{
    {HintKind::kUnknown, "UNKNOWN"},
    {HintKind::kResetTo, "RESET_TO"},
    {HintKind::kAdd, "ADD"},
    {HintKind::kOwnHalf, "OWN_HALF"},
    {HintKind::kMirror, "MIRROR"},
}};

}  // namespace

const char* hintKindName(HintKind kind) {
  for (const auto& [k, name] : kNames) {
    if (k == kind) return name;
  }
  return "UNKNOWN";
}

std::optional<HintKind> parseHintKind(const std::string& name) {
  for (const auto& [k, n] : kNames) {
    if (name == n) return k;
  }
  return std::nullopt;
}

}  // namespace houghloc
