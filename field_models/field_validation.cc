#include "field_models/field_validation.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace houghloc {
namespace {

std::string entry(const char* list, std::size_t index) {
  return std::string(list) + "[" + std::to_string(index) + "]";
}

std::string format(double value) {
  std::ostringstream out;
  // Snap rounding noise such as cos(pi / 2) = 6e-17 so messages show the intended 0.
  out << (std::abs(value) < 1e-12 ? 0.0 : value);
  return out.str();
}

/// Collects issues and knows the carpet (field plus border strip) for "outside" checks.
class Checker {
 public:
  Checker(const FieldModel& field, const FieldValidationConfig& config)
      : field_(field), config_(config) {}

  void add(const std::string& where, const std::string& problem) {
    issues_.push_back({where, problem});
  }

  /// Adds "outside" when p lies beyond the field plus border; returns true when it does.
  bool checkInside(const std::string& where, const Eigen::Vector2d& p) {
    if (!carpet_known_) return false;
    const double hx = field_.outerHalfLength() + config_.outside_tolerance_m;
    const double hy = field_.outerHalfWidth() + config_.outside_tolerance_m;
    if (std::abs(p.x()) <= hx && std::abs(p.y()) <= hy) return false;
    add(where, "(" + format(p.x()) + ", " + format(p.y()) +
                   ") is outside the field plus border strip (|x| <= " + format(hx) +
                   ", |y| <= " + format(hy) + ")");
    return true;
  }

  void checkDimensions() {
    auto positive = [&](const char* key, double value, bool allow_zero) {
      const bool ok = std::isfinite(value) && (allow_zero ? value >= 0.0 : value > 0.0);
      if (!ok)
        add(key,
            std::string("must be ") + (allow_zero ? ">= 0" : "> 0") + ", got " + format(value));
      return ok;
    };
    const bool length_ok = positive("field_length", field_.field_length, false);
    const bool width_ok = positive("field_width", field_.field_width, false);
    positive("line_width", field_.line_width, false);
    const bool border_ok = positive("border_strip_width", field_.border_strip_width, true);
    carpet_known_ = length_ok && width_ok && border_ok;
    if (field_.segments.empty() && field_.arcs.empty() && field_.marks.empty()) {
      add("map", "no line features (segments, arcs and marks are all empty)");
    }
  }

  void checkSegments() {
    const auto& segments = field_.segments;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Segment2& s = segments[i];
      const std::string where = entry("segments", i);
      if (!s.a.allFinite() || !s.b.allFinite()) {
        add(where, "coordinate is not a finite number");
        continue;
      }
      if (s.length() < config_.min_segment_length_m) {
        add(where,
            s.length() == 0.0 ? "zero length" : "degenerate, length " + format(s.length()) + " m");
        continue;
      }
      if (!checkInside(where, s.a)) checkInside(where, s.b);
      for (std::size_t j = 0; j < i; ++j) checkPair(j, i);
    }
  }

  void checkArcs() {
    for (std::size_t i = 0; i < field_.arcs.size(); ++i) {
      const Arc2& a = field_.arcs[i];
      const std::string where = entry("arcs", i);
      if (!a.center.allFinite() || !std::isfinite(a.radius) || !std::isfinite(a.start_rad) ||
          !std::isfinite(a.sweep_rad)) {
        add(where, "value is not a finite number");
        continue;
      }
      const std::size_t issues_before = issues_.size();
      if (!(a.radius > 0.0)) add(where, "radius must be > 0, got " + format(a.radius));
      if (!(a.start_rad > -M_PI && a.start_rad <= M_PI)) {
        add(where, "start must be in (-pi, pi], got " + format(a.start_rad));
      }
      if (!(a.sweep_rad > 0.0 && a.sweep_rad <= 2.0 * M_PI + 1e-12)) {
        add(where, "sweep must be in (0, 2pi], got " + format(a.sweep_rad));
      }
      if (issues_.size() != issues_before) continue;
      // The arc's extreme points: its ends and the axis directions it passes through.
      for (double angle :
           {a.start_rad, a.start_rad + a.sweep_rad, 0.0, 0.5 * M_PI, M_PI, -0.5 * M_PI}) {
        if (a.containsAngle(angle) && checkInside(where, a.pointAt(angle))) break;
      }
    }
  }

  void checkMarksAndGoals() {
    for (std::size_t i = 0; i < field_.marks.size(); ++i) {
      const Mark& m = field_.marks[i];
      const std::string where = entry("marks", i);
      if (!m.center.allFinite() || !std::isfinite(m.size)) {
        add(where, "value is not a finite number");
        continue;
      }
      if (!(m.size > 0.0)) add(where, "size must be > 0, got " + format(m.size));
      const int shape = static_cast<int>(m.shape);
      if (shape != 0 && shape != 1) add(where, "shape must be 0 (cross) or 1 (dot)");
      checkInside(where, m.center);
    }
    for (std::size_t i = 0; i < field_.goals.size(); ++i) {
      const Goal& g = field_.goals[i];
      const std::string where = entry("goals", i);
      const double sizes[] = {g.inner_width, g.post_diameter, g.height, g.depth};
      const char* names[] = {"inner_width", "post_diameter", "height", "depth"};
      if (!g.center.allFinite()) {
        add(where, "centre is not finite");
        continue;
      }
      for (int k = 0; k < 4; ++k) {
        if (!(std::isfinite(sizes[k]) && sizes[k] > 0.0)) {
          add(where, std::string(names[k]) + " must be > 0, got " + format(sizes[k]));
        }
      }
      checkInside(where, g.center);
    }
  }

  std::vector<FieldIssue> issues() const { return issues_; }

 private:
  /// Segment i (later) against segment j (earlier): the same segment, or collinear and sharing
  /// more than a point, which would count the same painted line twice.
  void checkPair(std::size_t j, std::size_t i) {
    const Segment2& s = field_.segments[i];
    const Segment2& t = field_.segments[j];
    if (!t.a.allFinite() || !t.b.allFinite() || t.length() < config_.min_segment_length_m) return;
    const double tol = config_.duplicate_tolerance_m;
    const bool same = ((s.a - t.a).norm() <= tol && (s.b - t.b).norm() <= tol) ||
                      ((s.a - t.b).norm() <= tol && (s.b - t.a).norm() <= tol);
    if (same) {
      add(entry("segments", i), "duplicate of " + entry("segments", j));
      return;
    }
    const Eigen::Vector2d d = t.direction();
    const Eigen::Vector2d normal(-d.y(), d.x());
    if (std::abs(normal.dot(s.a - t.a)) > tol || std::abs(normal.dot(s.b - t.a)) > tol) return;
    const double u0 = d.dot(s.a - t.a), u1 = d.dot(s.b - t.a);
    const double overlap = std::min(std::max(u0, u1), t.length()) - std::max(std::min(u0, u1), 0.0);
    if (overlap > tol) {
      add(entry("segments", i),
          "overlaps " + entry("segments", j) + " by " + format(overlap) + " m (collinear)");
    }
  }

  const FieldModel& field_;
  const FieldValidationConfig& config_;
  bool carpet_known_ = false;
  std::vector<FieldIssue> issues_;
};

}  // namespace

std::vector<FieldIssue> validateField(const FieldModel& field,
                                      const FieldValidationConfig& config) {
  Checker checker(field, config);
  checker.checkDimensions();
  checker.checkSegments();
  checker.checkArcs();
  checker.checkMarksAndGoals();
  return checker.issues();
}

}  // namespace houghloc
