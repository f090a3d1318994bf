#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "tools/drawing/field_top_view.h"
#include "tools/offline/estimate_csv.h"
#include "tools/offline/offline_context.h"

namespace houghloc {

/// trajectory.png (DESIGN §5.2): field top view with the map, the ground truth (black), the best
/// pose per frame coloured by status (TRACKING green, AMBIGUOUS orange, LOST red, INITIALIZING
/// grey), covariance ellipses of the hypotheses every few seconds, kidnap and fall markers from
/// truth/events.csv, a legend and a scale bar; `notes` (a few short lines, e.g. the run's
/// metrics) go under the legend. Needs a field.
cv::Mat drawTrajectoryPlot(const OfflineContext& context,
                           const std::vector<FrameEstimate>& estimates,
                           const std::vector<std::string>& notes = {});

/// The top view the plot uses (a pale carpet so the status colours stand out, a scale that
/// keeps the image about 1400 px wide). The legend is a panel appended on the right, so
/// FieldTopView(field, trajectoryPlotViewConfig(field)).toPixel() gives positions in the plot.
FieldTopViewConfig trajectoryPlotViewConfig(const FieldModel& field);

/// BGR colour of a status in the plot (unknown statuses: grey like INITIALIZING).
cv::Scalar statusColour(const std::string& status);

}  // namespace houghloc
