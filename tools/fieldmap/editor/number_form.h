#pragma once

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QWidget>
#include <vector>

namespace houghloc::fieldmap {

/// A column of labelled numeric fields (metres or degrees) with exact values, for the dimensions
/// and property panels.
class NumberForm : public QWidget {
 public:
  explicit NumberForm(QWidget* parent = nullptr);
  /// Replaces the fields: one per label, `decimals` digits, range +-1000.
  void setFields(const std::vector<QString>& labels, int decimals = 4);
  void setValues(const std::vector<double>& values);
  std::vector<double> values() const;
  QFormLayout* layout() const { return layout_; }

 private:
  QFormLayout* layout_;
  std::vector<QDoubleSpinBox*> boxes_;
};

}  // namespace houghloc::fieldmap
