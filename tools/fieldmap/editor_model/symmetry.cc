#include "tools/fieldmap/editor_model/symmetry.h"

#include <cmath>

namespace houghloc::fieldmap {

Eigen::Vector2d mirrored(const Eigen::Vector2d& p, Mirror mirror) {
  switch (mirror) {
    case Mirror::kThroughCenter:
      return -p;
    case Mirror::kAcrossXAxis:
      return {p.x(), -p.y()};
    case Mirror::kAcrossYAxis:
      return {-p.x(), p.y()};
  }
  return p;
}

Segment2 mirrored(const Segment2& s, Mirror mirror) {
  return Segment2{mirrored(s.a, mirror), mirrored(s.b, mirror)};
}

Arc2 mirrored(const Arc2& a, Mirror mirror) {
  Arc2 out = a;
  out.center = mirrored(a.center, mirror);
  const double end = a.start_rad + a.sweep_rad;
  // A half turn keeps the direction of travel; a reflection reverses it, so the mirrored end
  // angle becomes the new start.
  switch (mirror) {
    case Mirror::kThroughCenter:
      out.start_rad = a.start_rad + M_PI;
      break;
    case Mirror::kAcrossXAxis:
      out.start_rad = -end;
      break;
    case Mirror::kAcrossYAxis:
      out.start_rad = M_PI - end;
      break;
  }
  out.start_rad = normalizeAngle(out.start_rad);
  return out;
}

Edit mirrorFeatures(const EditorDocument& doc, const std::vector<FeatureId>& features,
                    Mirror mirror) {
  static const char* kNames[] = {"through the centre", "across the x axis", "across the y axis"};
  Edit edit{std::string("Mirror ") + kNames[static_cast<int>(mirror)], doc, doc};
  EditorDocument& d = edit.after;
  for (const FeatureId& f : features) {
    switch (f.kind) {
      case EditorKind::kSegment:
        d.add(mirrored(doc.segment(f), mirror));
        break;
      case EditorKind::kArc:
        d.add(mirrored(doc.arc(f), mirror));
        break;
      case EditorKind::kMark: {
        Mark m = doc.mark(f);
        m.center = mirrored(m.center, mirror);
        d.add(m);
        break;
      }
      case EditorKind::kGoal: {
        Goal g = doc.goal(f);
        g.center = mirrored(g.center, mirror);
        d.add(g);
        break;
      }
    }
  }
  return edit;
}

}  // namespace houghloc::fieldmap
