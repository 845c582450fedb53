#pragma once
// The main window as the window tests open it: autosaves into a folder of the test's own and any
// recovery offered beside the file rather than asked about first.
#include "editor/main_window/main_window.h"

#include <QString>

namespace glint::editor::test {

inline MainWindow::Options windowOptions(const QString& autosaveFolder) {
    MainWindow::Options options;
    options.autosaveFolder = autosaveFolder;
    options.askBeforeRecovery = false;
    return options;
}

} // namespace glint::editor::test
