#include "tools/realframes/frame_statistics.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "tools/recording/recording.h"
#include "vision/camera_model.h"

namespace houghloc {
namespace {

constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();
/// Turf-coloured: chromaticity within this of the turf sample's median ...
constexpr double kTurfChromaRadius = 0.04;
/// ... and luma within these factors of its median.
constexpr double kTurfLumaLow = 0.6, kTurfLumaHigh = 1.5;
/// Fewer pixels than this share of the image: the quantity is not measured.
constexpr double kMinShare = 0.001;

double medianOf(std::vector<double> v) {
  if (v.empty()) return kNotMeasured;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double quantileOf(std::vector<double> v, double q) {
  if (v.empty()) return kNotMeasured;
  const auto at = v.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), at, v.end());
  return *at;
}

double robustSigma(const std::vector<double>& v, double centre) {
  std::vector<double> dev(v.size());
  for (size_t i = 0; i < v.size(); ++i) dev[i] = std::abs(v[i] - centre);
  return 1.4826 * medianOf(dev);
}

/// Per-pixel luma and chromaticity.
struct Planes {
  cv::Mat1f luma, r, g;
};

Planes planes(const cv::Mat3b& bgr) {
  Planes p{cv::Mat1f(bgr.size()), cv::Mat1f(bgr.size()), cv::Mat1f(bgr.size())};
  for (int y = 0; y < bgr.rows; ++y) {
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b c = bgr(y, x);
      const float sum = static_cast<float>(c[0] + c[1] + c[2]);
      p.luma(y, x) = 0.114f * c[0] + 0.587f * c[1] + 0.299f * c[2];
      p.r(y, x) = sum > 0.0f ? c[2] / sum : 1.0f / 3.0f;
      p.g(y, x) = sum > 0.0f ? c[1] / sum : 1.0f / 3.0f;
    }
  }
  return p;
}

/// Pixels at least `margin` rows below the horizon (the near ground, mostly turf).
cv::Mat1b belowHorizon(const std::vector<double>& horizon_rows, cv::Size size, double margin) {
  cv::Mat1b mask = cv::Mat1b::zeros(size);
  const bool known = static_cast<int>(horizon_rows.size()) == size.width;
  for (int x = 0; x < size.width; ++x) {
    const double h = known ? horizon_rows[static_cast<size_t>(x)] : -1e9;
    if (std::isnan(h) || h == std::numeric_limits<double>::infinity()) continue;
    const int start = static_cast<int>(std::clamp(std::ceil(h + margin), 0.0, 1.0 * size.height));
    for (int y = start; y < size.height; ++y) mask(y, x) = 255;
  }
  return mask;
}

std::vector<double> valuesAt(const cv::Mat1f& plane, const cv::Mat1b& mask) {
  std::vector<double> v;
  for (int y = 0; y < plane.rows; ++y) {
    for (int x = 0; x < plane.cols; ++x) {
      if (mask(y, x)) v.push_back(plane(y, x));
    }
  }
  return v;
}

/// Pixels of turf colour (r0, g0, y0) anywhere in the image.
cv::Mat1b turfColoured(const Planes& p, double r0, double g0, double y0) {
  cv::Mat1b mask(p.luma.size());
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      const double chroma = std::hypot(p.r(y, x) - r0, p.g(y, x) - g0);
      const double luma = p.luma(y, x);
      mask(y, x) =
          (chroma < kTurfChromaRadius && luma >= kTurfLumaLow * y0 && luma <= kTurfLumaHigh * y0)
              ? 255
              : 0;
    }
  }
  return mask;
}

/// Bright pixels near grey below the horizon: the paint when no label mask is given (white
/// robots and goal posts there count too; the medians keep them small).
cv::Mat1b brightGreyPixels(const Planes& p, const cv::Mat1b& sample, const FrameStatistics& s) {
  const double threshold = s.turf_luma + std::max(25.0, 3.0 * s.turf_luma_spread);
  const double turf_to_grey = std::hypot(s.turf_r - 1.0 / 3.0, s.turf_g - 1.0 / 3.0);
  cv::Mat1b mask = cv::Mat1b::zeros(p.luma.size());
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      const double to_grey = std::hypot(p.r(y, x) - 1.0 / 3.0, p.g(y, x) - 1.0 / 3.0);
      if (sample(y, x) && p.luma(y, x) > threshold && to_grey < 0.5 * turf_to_grey + 0.03)
        mask(y, x) = 255;
    }
  }
  return mask;
}

void measureTurf(const Planes& p, const cv::Mat1b& sample, FrameStatistics& s) {
  // The sample's median colour is the turf's first guess; the turf-coloured part refines it.
  const double r0 = medianOf(valuesAt(p.r, sample)), g0 = medianOf(valuesAt(p.g, sample));
  const double y0 = medianOf(valuesAt(p.luma, sample));
  const cv::Mat1b turf = turfColoured(p, r0, g0, y0) & sample;
  const std::vector<double> r = valuesAt(p.r, turf), g = valuesAt(p.g, turf);
  const std::vector<double> luma = valuesAt(p.luma, turf);
  s.turf_r = medianOf(r);
  s.turf_g = medianOf(g);
  s.turf_luma = medianOf(luma);
  s.turf_r_spread = robustSigma(r, s.turf_r);
  s.turf_g_spread = robustSigma(g, s.turf_g);
  s.turf_luma_spread = robustSigma(luma, s.turf_luma);
}

void measureLines(const Planes& p, const cv::Mat1b& lines, FrameStatistics& s) {
  const double total = static_cast<double>(lines.total());
  const int count = cv::countNonZero(lines);
  s.line_share = count / total;
  if (count < kMinShare * total || std::isnan(s.turf_luma)) {
    s.line_contrast = s.line_r = s.line_g = s.edge_width_px = kNotMeasured;
    return;
  }
  s.line_contrast = medianOf(valuesAt(p.luma, lines)) - s.turf_luma;
  s.line_r = medianOf(valuesAt(p.r, lines));
  s.line_g = medianOf(valuesAt(p.g, lines));
  // Steepest slope near the lines: Sobel / 8 is the central difference of a ramp.
  cv::Mat1f gx, gy, slope;
  cv::Sobel(p.luma, gx, CV_32F, 1, 0, 3, 1.0 / 8.0);
  cv::Sobel(p.luma, gy, CV_32F, 0, 1, 3, 1.0 / 8.0);
  cv::magnitude(gx, gy, slope);
  cv::Mat1b band;
  cv::dilate(lines, band, cv::Mat::ones(5, 5, CV_8U));
  const double steep = quantileOf(valuesAt(slope, band), 0.9);
  s.edge_width_px = steep > 0.0 ? s.line_contrast / steep : kNotMeasured;
}

void measureNoise(const Planes& p, const cv::Mat1b& turf, FrameStatistics& s) {
  cv::Mat1b flat;
  cv::erode(turf, flat, cv::Mat::ones(5, 5, CV_8U));
  if (cv::countNonZero(flat) < 500) {
    s.noise_sigma = kNotMeasured;
    return;
  }
  cv::Mat1f mean;
  cv::blur(p.luma, mean, cv::Size(3, 3));
  const std::vector<double> residual = valuesAt(p.luma - mean, flat);
  // White noise of sigma n leaves a residual of sigma n * sqrt(8/9) after the 3x3 mean.
  s.noise_sigma = robustSigma(residual, medianOf(residual)) * 3.0 / std::sqrt(8.0);
}

void measureVignetting(const Planes& p, const cv::Mat1b& turf, FrameStatistics& s) {
  cv::Mat1b outer = cv::Mat1b::zeros(turf.size()), inner = cv::Mat1b::zeros(turf.size());
  const double cx = 0.5 * (turf.cols - 1), cy = 0.5 * (turf.rows - 1);
  const double corner = std::hypot(cx, cy);
  for (int y = 0; y < turf.rows; ++y) {
    for (int x = 0; x < turf.cols; ++x) {
      if (!turf(y, x)) continue;
      const double rr = std::hypot(x - cx, y - cy) / corner;
      if (rr > 0.8) outer(y, x) = 255;
      if (rr < 0.35) inner(y, x) = 255;
    }
  }
  const double min_pixels = kMinShare * static_cast<double>(turf.total());
  if (cv::countNonZero(outer) < min_pixels || cv::countNonZero(inner) < min_pixels) {
    s.vignetting_ratio = kNotMeasured;
    return;
  }
  s.vignetting_ratio = medianOf(valuesAt(p.luma, outer)) / medianOf(valuesAt(p.luma, inner));
}

}  // namespace

FrameStatistics measureFrame(const cv::Mat3b& bgr, const std::vector<double>& horizon_rows,
                             const cv::Mat1b& line_mask) {
  FrameStatistics s;
  const Planes p = planes(bgr);
  const double total = static_cast<double>(bgr.total());
  s.background_share = 1.0 - cv::countNonZero(belowHorizon(horizon_rows, bgr.size(), 0.0)) / total;
  s.image_luma = medianOf(valuesAt(p.luma, cv::Mat1b(bgr.size(), 255)));
  s.image_r = cv::mean(p.r)[0];
  s.image_g = cv::mean(p.g)[0];
  // The turf sample starts 5 % of the image height below the horizon (the far carpet edge and
  // the hall floor lie near it); when that leaves almost nothing (a camera looking up, a wrong
  // nominal pose) the bottom quarter of the image stands in.
  cv::Mat1b sample = belowHorizon(horizon_rows, bgr.size(), 0.05 * bgr.rows);
  if (cv::countNonZero(sample) < 0.05 * total) {
    sample = cv::Mat1b::zeros(bgr.size());
    sample.rowRange(bgr.rows * 3 / 4, bgr.rows).setTo(255);
  }
  measureTurf(p, sample, s);
  const cv::Mat1b turf_anywhere = turfColoured(p, s.turf_r, s.turf_g, s.turf_luma);
  s.turf_share = cv::countNonZero(turf_anywhere) / total;
  const cv::Mat1b turf = turf_anywhere & sample;
  const bool masked = !line_mask.empty() && line_mask.size() == bgr.size();
  measureLines(p, masked ? cv::Mat1b(line_mask == 1) : brightGreyPixels(p, sample, s), s);
  measureNoise(p, turf, s);
  measureVignetting(p, turf, s);
  return s;
}

FolderStatistics measureFolder(const std::string& folder, int max_frames) {
  namespace fs = std::filesystem;
  const Recording rec = readRecording(folder);
  FolderStatistics out;
  out.folder = folder;
  std::vector<FrameStatistics> frames;
  const size_t n = rec.frames.size();
  const size_t count = max_frames > 0 ? std::min(n, static_cast<size_t>(max_frames)) : n;
  for (size_t k = 0; k < count; ++k) {
    const FrameRecord& frame = rec.frames[k * n / count];
    const fs::path image_path = fs::path(folder) / frame.image;
    const cv::Mat3b bgr = cv::imread(image_path.string(), cv::IMREAD_COLOR);
    if (bgr.empty()) throw std::runtime_error(image_path.string() + ": cannot read image");
    const CameraModel camera(rec.intrinsicsFor(frame), frame.robot_T_camera);
    const fs::path mask_path =
        fs::path(folder) / "labels" / (fs::path(frame.image).stem().string() + ".png");
    cv::Mat1b mask;
    if (fs::exists(mask_path)) mask = cv::imread(mask_path.string(), cv::IMREAD_GRAYSCALE);
    if (!mask.empty()) ++out.masked_frames;
    frames.push_back(measureFrame(bgr, camera.horizonRows(), mask));
    if (!std::isnan(frames.back().line_contrast)) ++out.frames_with_lines;
  }
  out.frames = static_cast<int>(frames.size());
  for (double FrameStatistics::*member :
       {&FrameStatistics::turf_r, &FrameStatistics::turf_g, &FrameStatistics::turf_luma,
        &FrameStatistics::turf_r_spread, &FrameStatistics::turf_g_spread,
        &FrameStatistics::turf_luma_spread, &FrameStatistics::turf_share,
        &FrameStatistics::background_share, &FrameStatistics::line_contrast,
        &FrameStatistics::line_r, &FrameStatistics::line_g, &FrameStatistics::line_share,
        &FrameStatistics::edge_width_px, &FrameStatistics::noise_sigma,
        &FrameStatistics::vignetting_ratio, &FrameStatistics::image_luma, &FrameStatistics::image_r,
        &FrameStatistics::image_g}) {
    std::vector<double> values;
    for (const FrameStatistics& f : frames) {
      if (!std::isnan(f.*member)) values.push_back(f.*member);
    }
    out.median.*member = medianOf(values);
  }
  return out;
}

}  // namespace houghloc
