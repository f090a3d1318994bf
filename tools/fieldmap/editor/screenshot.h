#pragma once

#include <QWidget>
#include <string>

namespace houghloc::fieldmap {

class FieldView;

/// `--screenshot`: lays out `window`, fits `view` to the field, renders the window to the PNG
/// `path` and prints it. Returns the exit code (1, with a message naming the file, when the PNG
/// cannot be written).
int saveScreenshot(QWidget& window, FieldView* view, const std::string& path);

}  // namespace houghloc::fieldmap
