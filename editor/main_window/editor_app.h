#pragma once
// Starts the editor: the GL defaults the viewport needs (shared contexts, a 4.1 core format) set
// before QApplication, the translations and theme from the preferences, then the main window,
// offering crash recovery before opening FILE.
namespace glint::editor {

// Whether a window system is reachable (X11 or Wayland, or a platform chosen explicitly).
bool haveDisplay();

int runEditor(int argc, char** argv, const char* version);

} // namespace glint::editor
