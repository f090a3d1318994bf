#pragma once

#include <Eigen/Core>
#include <vector>

namespace houghloc {

/// Discretisation of the Hough space (paper step 1, DESIGN Appendix A).
struct HoughConfig {
  double theta_step_rad = M_PI / 180.0;  ///< column width; theta covers [0, pi)
  double rho_step_m = 0.03;              ///< row height; rho is signed
};

/// Points with weights, the input of every step (robot frame for sensor data, field frame for
/// map samples).
struct WeightedPoints {
  std::vector<Eigen::Vector2d> points;  ///< m
  std::vector<double> weights;          ///< > 0, one per point

  std::size_t size() const { return points.size(); }
  bool empty() const { return points.empty(); }
  double totalWeight() const;
};

/// HT(theta, rho) = sum_i w_i K(rho - (x_i cos theta + y_i sin theta)) on a regular grid with
/// theta in [0, pi) and rho in [-rho_max, rho_max]; K splits each vote linearly between the two
/// nearest rho rows (paper step 1). Row j holds rho = (j - centre) * rho_step, so rho and -rho are
/// mirror rows, which makes the wrap of theta across pi (theta - pi, -rho) a row flip.
class HoughTransform {
 public:
  HoughTransform() = default;
  HoughTransform(const HoughConfig& config, double rho_max_m);

  void addPoint(const Eigen::Vector2d& p, double weight);
  void addPoints(const WeightedPoints& points);

  int numTheta() const { return num_theta_; }
  int numRho() const { return num_rho_; }
  double theta(int column) const { return column * config_.theta_step_rad; }
  double rho(int row) const { return (row - centre_row_) * config_.rho_step_m; }
  double rhoMax() const { return centre_row_ * config_.rho_step_m; }
  const HoughConfig& config() const { return config_; }

  float at(int column, int row) const { return cells_[index(column, row)]; }
  /// The rho column at `column` (numRho() values).
  const float* column(int column) const { return &cells_[index(column, 0)]; }

 private:
  std::size_t index(int column, int row) const {
    return static_cast<std::size_t>(column) * num_rho_ + row;
  }

  HoughConfig config_;
  int num_theta_ = 0;
  int num_rho_ = 0;
  int centre_row_ = 0;
  std::vector<float> cos_, sin_;
  std::vector<float> cells_;
};

/// One rho column of the transform at an arbitrary angle theta (not wrapped: rho is measured along
/// (cos theta, sin theta)), votes split linearly between rows like HoughTransform. Row j holds
/// rho = (j - centre) * rho_step with centre = ceil(rho_max / rho_step). Used by step 3, where the
/// sensor column at theta_mu - theta_R is needed at the exact (sub-bin) heading.
std::vector<float> houghColumn(const WeightedPoints& points, double theta_rad, double rho_step_m,
                               double rho_max_m);

/// Number of rows of a column covering [-rho_max, rho_max]; the centre row is (rows - 1) / 2.
int houghRows(double rho_step_m, double rho_max_m);

}  // namespace houghloc
