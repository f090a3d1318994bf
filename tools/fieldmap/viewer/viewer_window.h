#pragma once

#include <QMainWindow>
#include <memory>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "tools/fieldmap/viewer_model/viewer_state.h"

class QLabel;
class QSlider;

namespace houghloc::fieldmap {

class FieldView;

/// The live viewer window: the map (the editor's FieldView), every robot's hypotheses with 2-sigma
/// ellipses and weights, its last line points at the best pose, its ground truth, and one status
/// line per robot. With a log, a time slider below the view replays it.
class ViewerWindow : public QMainWindow {
 public:
  /// `source` names where messages come from (an LCM URL or a log file), for the waiting text.
  ViewerWindow(const FieldModel& field, std::vector<std::string> prefixes, QString source);

  /// Redraws the robots from `state`.
  void showState(const ViewerState& state);
  /// Puts a slider over the log's time span; moving it shows the log's state at that time.
  void setLog(std::shared_ptr<const LogIndex> log);
  /// Moves the slider to `t_us` (log time) and shows that state.
  void seek(std::int64_t t_us);

  FieldView* view() const { return view_; }
  QSlider* slider() const { return slider_; }
  const ViewerState& state() const { return state_; }
  /// Items of the scene with data(kViewerRole) == role.
  int countItems(int role) const;

 private:
  std::vector<std::string> prefixes_;
  QString source_;
  ViewerState state_;
  std::shared_ptr<const LogIndex> log_;
  FieldView* view_;
  QLabel* status_;
  QLabel* time_;
  QSlider* slider_;
};

}  // namespace houghloc::fieldmap
