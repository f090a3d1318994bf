#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace houghloc {

// Pieces of trajectory.png shared by the plot and its legend (trajectory_plot.cc).

inline const cv::Scalar kAlternativeColour(170, 60, 170);  ///< BGR, hypotheses other than best
inline const cv::Scalar kEventColour(150, 0, 110);         ///< BGR, kidnap and fall markers

/// A cross in a circle at `p` (FieldTopView pixel position) with the label "kidnap".
void drawKidnapMarker(cv::Mat& image, const cv::Point2d& p);
/// A triangle at `p`, pointing down for a fall's start and up for its end, labelled.
void drawFallMarker(cv::Mat& image, const cv::Point2d& p, bool start);

/// The plot with a legend panel appended on the right (the plot's pixels keep their place) and
/// `notes` under the legend.
cv::Mat appendLegend(const cv::Mat& plot, const std::vector<std::string>& notes);

}  // namespace houghloc
