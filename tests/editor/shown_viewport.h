#pragma once
// A viewport alone in a 160x120 main window, shown: the set-up of the viewport tests that need no
// other panel.
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"

#include <QMainWindow>

namespace glint::test {

struct ShownViewport {
    QMainWindow window;
    editor::Viewport* viewport = nullptr;
    explicit ShownViewport(editor::Document& document) {
        viewport = new editor::Viewport(document, &window);
        window.setCentralWidget(viewport);
        window.resize(160, 120);
        window.show();
    }
    editor::RenderView& view() { return viewport->view(); }
};

} // namespace glint::test
