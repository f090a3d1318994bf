#include "tools/fieldmap/editor/screenshot.h"

#include <QApplication>
#include <iostream>

#include "tools/fieldmap/editor/field_view.h"

namespace houghloc::fieldmap {

int saveScreenshot(QWidget& window, FieldView* view, const std::string& path) {
  QApplication::processEvents();
  view->fitField();
  QApplication::processEvents();
  if (!window.grab().save(QString::fromStdString(path))) {
    std::cerr << "houghloc-fieldmap: " << path << ": cannot write the PNG\n";
    return 1;
  }
  std::cout << "wrote " << path << "\n";
  return 0;
}

}  // namespace houghloc::fieldmap
