#include "localization/map_signature.h"

#include <algorithm>
#include <cmath>

namespace houghloc {
namespace {

void sampleSegment(const Segment2& s, double spacing, WeightedPoints& out) {
  const int n = std::max(1, static_cast<int>(std::ceil(s.length() / spacing)));
  for (int i = 0; i <= n; ++i) {
    out.points.push_back(s.a + (s.b - s.a) * (static_cast<double>(i) / n));
    out.weights.push_back(1.0);
  }
}

void sampleArc(const Arc2& arc, double spacing, WeightedPoints& out) {
  const int n = std::max(2, static_cast<int>(std::ceil(arc.length() / spacing)));
  const int last = arc.isFullCircle() ? n - 1 : n;
  for (int i = 0; i <= last; ++i) {
    out.points.push_back(arc.pointAt(arc.start_rad + arc.sweep_rad * i / n));
    out.weights.push_back(1.0);
  }
}

/// Local maxima of a circular profile above `share` of its largest value, strongest first.
std::vector<int> circularMaxima(const std::vector<double>& v, double share) {
  const int n = static_cast<int>(v.size());
  std::vector<int> out;
  if (n == 0) return out;
  const double top = *std::max_element(v.begin(), v.end());
  for (int i = 0; i < n; ++i) {
    const double prev = v[(i + n - 1) % n], next = v[(i + 1) % n];
    if (v[i] > prev && v[i] >= next && v[i] > 0.0 && v[i] >= share * top) out.push_back(i);
  }
  std::sort(out.begin(), out.end(), [&](int a, int b) { return v[a] > v[b]; });
  return out;
}

}  // namespace

WeightedPoints sampleMapLines(const FieldModel& field, double spacing_m, bool include_marks) {
  WeightedPoints out;
  for (const Segment2& s : field.segments) sampleSegment(s, spacing_m, out);
  for (const Arc2& a : field.arcs) sampleArc(a, spacing_m, out);
  if (include_marks) {
    for (const Mark& m : field.marks) {
      const double h = 0.5 * m.size;
      sampleSegment({m.center - Eigen::Vector2d(h, 0), m.center + Eigen::Vector2d(h, 0)}, spacing_m,
                    out);
      sampleSegment({m.center - Eigen::Vector2d(0, h), m.center + Eigen::Vector2d(0, h)}, spacing_m,
                    out);
    }
  }
  return out;
}

std::vector<double> orientationProfile(const HoughTransform& transform) {
  const int columns = transform.numTheta(), rows = transform.numRho();
  std::vector<double> h(columns, 0.0);
  // Each column's sum of squares in row order; four columns side by side, so that four
  // independent sums hide the latency of the additions.
  constexpr int kSide = 4;
  int i = 0;
  for (; i + kSide <= columns; i += kSide) {
    const float* col[kSide];
    double sum[kSide] = {0.0, 0.0, 0.0, 0.0};
    for (int c = 0; c < kSide; ++c) col[c] = transform.column(i + c);
    for (int j = 0; j < rows; ++j) {
      for (int c = 0; c < kSide; ++c) sum[c] += static_cast<double>(col[c][j]) * col[c][j];
    }
    for (int c = 0; c < kSide; ++c) h[i + c] = sum[c];
  }
  for (; i < columns; ++i) {
    const float* col = transform.column(i);
    double sum = 0.0;
    for (int j = 0; j < rows; ++j) sum += static_cast<double>(col[j]) * col[j];
    h[i] = sum;
  }
  double mean = 0.0;
  for (double v : h) mean += v;
  mean /= std::max<std::size_t>(1, h.size());
  double norm = 0.0;
  for (double& v : h) {
    v -= mean;
    norm += v * v;
  }
  norm = std::sqrt(norm);
  // A flat profile (one point, a point cloud without lines) carries no heading information.
  if (!(norm > 1e-9 * std::max(1.0, std::abs(mean)) * std::sqrt(h.size()))) {
    std::fill(h.begin(), h.end(), 0.0);
    return h;
  }
  for (double& v : h) v /= norm;
  return h;
}

MapSignature::MapSignature(const FieldModel& field, const MapSignatureConfig& config)
    : field_(field), config_(config) {
  rho_max_ = std::hypot(field.outerHalfLength(), field.outerHalfWidth()) + 0.5;
  const WeightedPoints samples = sampleMapLines(field, config.sample_spacing_m, true);
  transform_ = HoughTransform(config.hough, rho_max_);
  transform_.addPoints(samples);
  profile_ = orientationProfile(transform_);
  const double step = transform_.config().theta_step_rad;
  const float min_votes = static_cast<float>(config.mask_min_line_m / config.sample_spacing_m);
  for (int i : circularMaxima(profile_, config.dominant_share)) {
    dominant_.push_back(i * step);
    std::vector<float> col =
        houghColumn(samples, i * step, transform_.config().rho_step_m, rho_max_);
    // A line is a narrow peak: lines across the direction spread their votes evenly over many
    // rows, so each row is compared with the smallest count nearby (top-hat filter).
    const int w = 4;
    std::vector<float> mask(col.size(), 0.0f);
    for (int j = 0; j < static_cast<int>(col.size()); ++j) {
      float low = col[j];
      for (int k = std::max(0, j - w); k <= std::min<int>(col.size() - 1, j + w); ++k) {
        low = std::min(low, col[k]);
      }
      mask[j] = col[j] - low >= min_votes ? 1.0f : 0.0f;
    }
    masks_.push_back(std::move(mask));
  }
  grid_ = DistanceGrid(field, config.grid);
  features_ = FeatureLookup(field, config.lookup_resolution_m, config.grid.margin_m);
  const WeightedPoints evidence = sampleMapLines(field, config.evidence_spacing_m, false);
  bucketEvidence(evidence.points);
  point_symmetric_ = true;
  for (const Eigen::Vector2d& p : evidence.points) {
    point_symmetric_ =
        point_symmetric_ && grid_.distance(-p) <= std::max(field.line_width, grid_.resolution());
  }
  for (const Arc2& a : field.arcs) {
    if (a.isFullCircle()) circles_.push_back(a);
  }
}

void MapSignature::bucketEvidence(const std::vector<Eigen::Vector2d>& samples) {
  // Row-major buckets; a row's buckets are contiguous, so a box query visits one range per row.
  const double b = kEvidenceBucketM;
  bucket_origin_ = Eigen::Vector2d(-field_.outerHalfLength() - b, -field_.outerHalfWidth() - b);
  bucket_cols_ = static_cast<int>(std::ceil(2.0 * (field_.outerHalfLength() + b) / b)) + 1;
  bucket_rows_ = static_cast<int>(std::ceil(2.0 * (field_.outerHalfWidth() + b) / b)) + 1;
  auto bucket = [&](const Eigen::Vector2d& p) {
    const int c =
        std::clamp(static_cast<int>((p.x() - bucket_origin_.x()) / b), 0, bucket_cols_ - 1);
    const int r =
        std::clamp(static_cast<int>((p.y() - bucket_origin_.y()) / b), 0, bucket_rows_ - 1);
    return r * bucket_cols_ + c;
  };
  bucket_start_.assign(static_cast<std::size_t>(bucket_cols_) * bucket_rows_ + 1, 0);
  for (const auto& p : samples) ++bucket_start_[bucket(p) + 1];
  for (std::size_t i = 1; i < bucket_start_.size(); ++i) bucket_start_[i] += bucket_start_[i - 1];
  evidence_.resize(samples.size());
  std::vector<int> fill(bucket_start_.begin(), bucket_start_.end() - 1);
  for (const auto& p : samples) evidence_[fill[bucket(p)]++] = p;
}

}  // namespace houghloc
