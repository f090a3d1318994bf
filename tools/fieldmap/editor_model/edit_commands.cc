#include "tools/fieldmap/editor_model/edit_commands.h"

#include <cmath>
#include <stdexcept>

namespace houghloc::fieldmap {
namespace {

template <typename Change>
Edit change(const EditorDocument& doc, std::string text, Change&& apply) {
  Edit edit{std::move(text), doc, doc};
  apply(edit.after);
  return edit;
}

/// Sweep in (0, 2 pi] from a start to an end angle, counter-clockwise.
double sweepBetween(double start_rad, double end_rad) {
  double sweep = std::fmod(end_rad - start_rad, 2.0 * M_PI);
  if (sweep <= 1e-12) sweep += 2.0 * M_PI;
  return sweep;
}

}  // namespace

double normalizeAngle(double angle_rad) {
  double a = std::remainder(angle_rad, 2.0 * M_PI);  // [-pi, pi]
  if (a <= -M_PI) a += 2.0 * M_PI;
  return a;
}

void EditHistory::push(Edit edit, EditorDocument& document) {
  document = edit.after;
  done_.push_back(std::move(edit));
  undone_.clear();
}

bool EditHistory::undo(EditorDocument& document) {
  if (done_.empty()) return false;
  document = done_.back().before;
  undone_.push_back(std::move(done_.back()));
  done_.pop_back();
  return true;
}

bool EditHistory::redo(EditorDocument& document) {
  if (undone_.empty()) return false;
  document = undone_.back().after;
  done_.push_back(std::move(undone_.back()));
  undone_.pop_back();
  return true;
}

Edit moveHandle(const EditorDocument& doc, const FeatureId& f, Handle handle,
                const Eigen::Vector2d& p) {
  return change(doc, "Move " + describeFeatureId(f), [&](EditorDocument& d) {
    switch (f.kind) {
      case EditorKind::kSegment:
        (handle == Handle::kEnd ? d.segment(f).b : d.segment(f).a) = p;
        break;
      case EditorKind::kMark:
        d.mark(f).center = p;
        break;
      case EditorKind::kGoal:
        d.goal(f).center = p;
        break;
      case EditorKind::kArc: {
        Arc2& arc = d.arc(f);
        const Eigen::Vector2d r = p - arc.center;
        const double angle = std::atan2(r.y(), r.x());
        if (handle == Handle::kCenter) {
          arc.center = p;
        } else if (handle == Handle::kRadius) {
          if (r.norm() > 0.0) arc.radius = r.norm();
        } else if (handle == Handle::kArcStart && !arc.isFullCircle()) {
          const double end = arc.start_rad + arc.sweep_rad;
          arc.start_rad = normalizeAngle(angle);
          arc.sweep_rad = sweepBetween(arc.start_rad, end);
        } else if (handle == Handle::kArcEnd && !arc.isFullCircle()) {
          arc.sweep_rad = sweepBetween(arc.start_rad, angle);
        }
        break;
      }
    }
  });
}

Edit setSegment(const EditorDocument& doc, const FeatureId& f, const Segment2& v) {
  return change(doc, "Edit " + describeFeatureId(f), [&](EditorDocument& d) { d.segment(f) = v; });
}
Edit setArc(const EditorDocument& doc, const FeatureId& f, const Arc2& v) {
  return change(doc, "Edit " + describeFeatureId(f), [&](EditorDocument& d) {
    Arc2& arc = d.arc(f);
    arc = v;
    arc.start_rad = normalizeAngle(v.start_rad);
  });
}
Edit setMark(const EditorDocument& doc, const FeatureId& f, const Mark& v) {
  return change(doc, "Edit " + describeFeatureId(f), [&](EditorDocument& d) { d.mark(f) = v; });
}
Edit setGoal(const EditorDocument& doc, const FeatureId& f, const Goal& v) {
  return change(doc, "Edit " + describeFeatureId(f), [&](EditorDocument& d) { d.goal(f) = v; });
}

Edit addSegment(const EditorDocument& doc, const Segment2& v) {
  return change(doc, "Add segment", [&](EditorDocument& d) { d.add(v); });
}
Edit addArc(const EditorDocument& doc, const Arc2& v) {
  Arc2 arc = v;
  arc.start_rad = normalizeAngle(v.start_rad);
  return change(doc, "Add arc", [&](EditorDocument& d) { d.add(arc); });
}
Edit addMark(const EditorDocument& doc, const Mark& v) {
  return change(doc, "Add mark", [&](EditorDocument& d) { d.add(v); });
}
Edit addGoal(const EditorDocument& doc, const Goal& v) {
  return change(doc, "Add goal", [&](EditorDocument& d) { d.add(v); });
}

Edit deleteFeatures(const EditorDocument& doc, const std::vector<FeatureId>& features) {
  const std::string what = features.size() == 1 ? describeFeatureId(features[0])
                                                : std::to_string(features.size()) + " features";
  return change(doc, "Delete " + what, [&](EditorDocument& d) {
    for (const FeatureId& f : features) d.remove(f);
  });
}

Edit translateFeatures(const EditorDocument& doc, const std::vector<FeatureId>& features,
                       const Eigen::Vector2d& delta) {
  const std::string what = features.size() == 1 ? describeFeatureId(features[0])
                                                : std::to_string(features.size()) + " features";
  return change(doc, "Move " + what, [&](EditorDocument& d) {
    for (const FeatureId& f : features) {
      switch (f.kind) {
        case EditorKind::kSegment:
          d.segment(f).a += delta;
          d.segment(f).b += delta;
          break;
        case EditorKind::kArc:
          d.arc(f).center += delta;
          break;
        case EditorKind::kMark:
          d.mark(f).center += delta;
          break;
        case EditorKind::kGoal:
          d.goal(f).center += delta;
          break;
      }
    }
  });
}

Edit setHeader(const EditorDocument& doc, const FieldModel& header) {
  return change(doc, "Edit field size", [&](EditorDocument& d) {
    d.header().name = header.name;
    d.header().field_length = header.field_length;
    d.header().field_width = header.field_width;
    d.header().line_width = header.line_width;
    d.header().border_strip_width = header.border_strip_width;
  });
}

Edit regenerate(const EditorDocument& doc, const FieldDimensions& dims) {
  return Edit{"Regenerate from dimensions", doc, EditorDocument(makeField(dims), dims)};
}

}  // namespace houghloc::fieldmap
