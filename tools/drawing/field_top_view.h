#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"

namespace houghloc {

struct FieldTopViewConfig {
  double pixels_per_metre = 100.0;  ///< image scale, px/m
  int margin_px = 40;               ///< frame around the carpet for the title and the scale bar
  /// Largest image side, px; bigger requests throw instead of allocating gigabytes.
  int max_side_px = 20000;
  cv::Scalar background = {235, 235, 235};  ///< BGR, around the carpet
  cv::Scalar carpet = {60, 135, 50};        ///< BGR
  cv::Scalar lines = {255, 255, 255};       ///< BGR
  cv::Scalar goal = {0, 215, 255};          ///< BGR, posts and net outline
  cv::Scalar text = {30, 30, 30};           ///< BGR
};

/// A top view of the field: x (toward the opponent goal) to the right, y up, the carpet (field
/// plus border strip) centred in the image with `margin_px` around it. Pixel (u, v) covers
/// [u, u + 1) x [v, v + 1), so toPixel() returns sub-pixel coordinates whose integer part is the
/// pixel. Everything is drawn anti-aliased with real sizes (lines with the map's line width).
class FieldTopView {
 public:
  /// Throws std::invalid_argument when the field's size or the scale is not positive and finite,
  /// or the image would exceed max_side_px.
  explicit FieldTopView(const FieldModel& field, const FieldTopViewConfig& config = {});

  /// Image position of a field point, px (sub-pixel).
  cv::Point2d toPixel(const Eigen::Vector2d& p_field) const;
  /// Field point at an image position (inverse of toPixel()), m.
  Eigen::Vector2d toField(const cv::Point2d& pixel) const;

  /// Carpet, lines, arcs, marks and goals; non-finite features are skipped.
  void drawField();
  /// A bar of a round length (1, 2, 5, ... m) with its label, below the carpet.
  void drawScaleBar();
  /// The field frame: origin marker, x arrow toward the opponent goal, y arrow, 1 m long.
  void drawAxes();
  /// Text centred above the carpet.
  void drawTitle(const std::string& title);
  /// drawField(), drawAxes(), drawScaleBar() and a title with the map's name and size.
  void drawAll();

  /// A robot pose: a circle of `radius_m` and a heading line.
  void drawPose(const Pose2& field_T_robot, const cv::Scalar& colour, double radius_m = 0.15);
  /// The `sigma`-sigma ellipse of a 2x2 position covariance (m^2) around `mean` (m).
  void drawCovarianceEllipse(const Eigen::Vector2d& mean, const Eigen::Matrix2d& cov,
                             const cv::Scalar& colour, double sigma = 2.0);
  /// A polyline through field points, e.g. a trajectory.
  void drawPolyline(const std::vector<Eigen::Vector2d>& points_field, const cv::Scalar& colour,
                    int thickness_px = 2);

  const cv::Mat& image() const { return image_; }
  cv::Mat& image() { return image_; }
  double pixelsPerMetre() const { return config_.pixels_per_metre; }

 private:
  /// Fills closed field-frame polygons (holes allowed) anti-aliased, at sub-pixel accuracy.
  void fillPolygons(const std::vector<std::vector<Eigen::Vector2d>>& polygons_field,
                    const cv::Scalar& colour);
  void drawBand(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double width_m,
                const cv::Scalar& colour);
  void drawArcBand(const Arc2& arc, double width_m, const cv::Scalar& colour);
  void drawDisc(const Eigen::Vector2d& center, double radius_m, const cv::Scalar& colour);
  void drawArrow(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const cv::Scalar& colour,
                 const std::string& label);
  void drawGoal(const Goal& goal);

  FieldModel field_;
  FieldTopViewConfig config_;
  cv::Mat image_;
};

}  // namespace houghloc
