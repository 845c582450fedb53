// The child process of test_editor_killed: the editor's main window (no viewport) on SCENE with its
// autosave in FOLDER, editing as killed_session.h describes until it is killed.
//
//   editor_killed_session SCENE FOLDER SEED
#include "killed_session.h"
#include "window_options.h"

#include <QApplication>
#include <QTimer>

#include <cstdio>

using namespace glint::editor;

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    if (argc != 4) {
        std::fprintf(stderr, "usage: editor_killed_session SCENE FOLDER SEED\n");
        return 2;
    }
    MainWindow::Options options = test::windowOptions(QString::fromLocal8Bit(argv[2]));
    options.createViewport = false;
    MainWindow window(options);
    if (!window.openFile(QString::fromLocal8Bit(argv[1]))) return 1;
    glint::test::RandomSource random(static_cast<std::uint32_t>(std::strtoul(argv[3], nullptr, 10)));
    int step = 0;
    QTimer timer;
    QObject::connect(&timer, &QTimer::timeout, [&] {
        test::sessionStep(window.document(), random);
        ++step;
        const test::SessionEvent event = test::sessionEventAfter(step);
        if (event == test::SessionEvent::Save && window.save()) std::printf("saved %d\n", step);
        if (event == test::SessionEvent::Autosave && window.autosave().saveNow().isEmpty()) std::printf("autosaved %d\n", step);
        std::fflush(stdout);
    });
    timer.start(2);
    return app.exec();
}
