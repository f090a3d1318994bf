#pragma once

#include <QTableWidget>
#include <QWidget>
#include <functional>
#include <memory>
#include <optional>

#include "tools/fieldmap/editor/number_form.h"
#include "tools/fieldmap/editor_model/editor_document.h"
#include "tools/fieldmap/editor_model/residuals.h"
#include "tools/fieldmap/frame_check/frame_check.h"

class QLabel;
class QSpinBox;

namespace houghloc::fieldmap {

class FieldView;

/// Check against reality: a recorded folder's frame, its line points drawn on the map at a pose
/// (the ground truth, typed in, or dragged with Shift in the view), and the residuals per feature
/// and overall. Clicking a residual row selects the feature.
class CheckPanel : public QWidget {
 public:
  CheckPanel(FieldView* view, QWidget* parent = nullptr);

  /// Opens a recorded folder and shows `frame`; throws RecordingError (also for a frame the
  /// folder does not have).
  void openRecording(const QString& folder, int frame = 0);
  /// Redraws the points and residuals for this map (after every edit).
  void update(const EditorDocument& doc);
  /// Moves the pose by a field-frame translation (m) and a rotation (rad) about the robot.
  void nudgePose(const Eigen::Vector2d& delta_m, double delta_rad);
  /// Sets the pose to the global localizer's next pose for this frame on the map as edited
  /// (lowest mean residual first; the next call cycles on, e.g. to the mirror twin of a
  /// point-symmetric field).
  void localize();
  const ResidualReport& report() const { return report_; }
  /// The pose the points are drawn at (field_T_robot; the form holds mm and 0.001 deg).
  Pose2 pose() const;

  std::function<void(FeatureId)> on_feature_clicked;
  std::function<void()> on_pose_changed;

 private:
  void showFrame(int index);
  void setPose(const Pose2& pose);

  FieldView* view_;
  std::unique_ptr<FrameSource> source_;
  std::optional<CheckFrame> frame_;
  /// The localizer's poses for frame_ on doc_'s map; cleared when the frame or the map changes.
  std::optional<std::vector<Pose2>> located_;
  std::size_t next_located_ = 0;
  EditorDocument doc_;
  ResidualReport report_;
  QLabel* status_;
  QSpinBox* frame_box_;
  QLabel* located_status_;
  NumberForm* pose_;
  QTableWidget* table_;
};

}  // namespace houghloc::fieldmap
