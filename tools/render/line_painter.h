#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "field_models/field_model.h"

namespace houghloc {

/// The ground footprint of one pixel: ground motion (m) per pixel step along the image row (u)
/// and column (v). Used to box-filter painted lines analytically (anti-aliasing).
struct Footprint {
  Eigen::Vector2f du = Eigen::Vector2f::Zero();
  Eigen::Vector2f dv = Eigen::Vector2f::Zero();
  /// Width (m) of the footprint measured along a ground direction.
  float along(const Eigen::Vector2f& dir) const {
    const float a = dir.dot(du), b = dir.dot(dv);
    return std::sqrt(a * a + b * b);
  }
};

/// How much of a pixel is covered by paint, and by which item (its tag).
struct PaintCoverage {
  float coverage = 0.0f;
  int tag = -1;
};

/// Painted lines on the ground (field lines, or other sports' lines on the gym floor): bars with
/// the true width, rings (arcs) and filled discs, indexed on a coarse grid so a query only looks
/// at the few items near the ground point. Coverage is the exact box-filtered fraction of the
/// pixel's footprint covered by an item, so lines keep their true width in the image at any
/// distance and fade correctly where they are thinner than a pixel.
class LinePainter {
 public:
  /// Bar along a->b of full width `width`; the ends are extended by `cap` (square caps).
  void addBar(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double width, double cap,
              int tag);
  void addArc(const Arc2& arc, double width, int tag);
  void addDisc(const Eigen::Vector2d& center, double radius, int tag);
  /// Every line of a field map (segments with square caps, arcs, marks), tag = 0.
  void addField(const FieldModel& field);
  /// Builds the index over [min, max]; items outside it are never found.
  void build(const Eigen::Vector2d& min, const Eigen::Vector2d& max, double cell_m = 0.25,
             double reach_m = 0.5);

  /// Largest coverage of any item at ground point g; width_offset_m widens the paint (ragged
  /// edges).
  PaintCoverage coverage(const Eigen::Vector2f& g, const Footprint& fp,
                         float width_offset_m = 0.0f) const;
  bool empty() const { return items_.empty(); }

 private:
  struct Item {
    enum class Kind { kBar, kRing, kDisc } kind = Kind::kBar;
    Eigen::Vector2f a = Eigen::Vector2f::Zero();      ///< bar start, ring/disc centre
    Eigen::Vector2f dir = Eigen::Vector2f::UnitX();   ///< bar direction
    float length = 0.0f, cap = 0.0f;                  ///< bar
    float half_width = 0.0f;                          ///< bar, ring; disc: radius
    float radius = 0.0f, start = 0.0f, sweep = 0.0f;  ///< ring
    bool full = true;
    int tag = 0;
  };
  float itemCoverage(const Item& item, const Eigen::Vector2f& g, const Footprint& fp,
                     float offset) const;
  double itemDistance(const Item& item, const Eigen::Vector2d& p) const;

  std::vector<Item> items_;
  Eigen::Vector2d min_ = Eigen::Vector2d::Zero();
  double cell_ = 0.25;
  int cols_ = 0, rows_ = 0;
  std::vector<int> cell_start_;  ///< cols*rows+1 offsets into cell_items_
  std::vector<int> cell_items_;
};

}  // namespace houghloc
