#include "tools/fieldmap/editor/number_form.h"

#include <QLabel>

namespace houghloc::fieldmap {

NumberForm::NumberForm(QWidget* parent) : QWidget(parent), layout_(new QFormLayout(this)) {}

void NumberForm::setFields(const std::vector<QString>& labels, int decimals) {
  while (layout_->rowCount() > 0) layout_->removeRow(0);
  boxes_.clear();
  for (const QString& label : labels) {
    auto* box = new QDoubleSpinBox(this);
    box->setDecimals(decimals);
    box->setRange(-1000.0, 1000.0);
    box->setSingleStep(0.05);
    layout_->addRow(label, box);
    boxes_.push_back(box);
  }
}

void NumberForm::setValues(const std::vector<double>& values) {
  for (std::size_t i = 0; i < boxes_.size() && i < values.size(); ++i)
    boxes_[i]->setValue(values[i]);
}

std::vector<double> NumberForm::values() const {
  std::vector<double> out;
  for (const QDoubleSpinBox* box : boxes_) out.push_back(box->value());
  return out;
}

}  // namespace houghloc::fieldmap
