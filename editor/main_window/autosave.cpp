#include "autosave.h"

#include "editor/document/document.h"

#include "scene/io/scene_io.h"

#include <QDir>
#include <QFile>
#include <QSaveFile>
#include <QStandardPaths>

#include <exception>

namespace glint::editor {

Autosave::Autosave(Document& document, QString folder, QObject* parent)
    : QObject(parent), document_(document), folder_(std::move(folder)) {
    if (folder_.isEmpty())
        folder_ = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave");
    connect(&timer_, &QTimer::timeout, this, [this] {
        const QString error = saveNow();
        if (!error.isEmpty()) emit failed(error);
    });
    // Saved: the copy is older than the file, so it must not be offered after a crash.
    connect(&document_, &Document::cleanChanged, this, [this](bool clean) {
        if (clean) discard();
    });
    setIntervalMinutes(2);
}

void Autosave::setIntervalMinutes(int minutes) {
    if (minutes <= 0) {
        timer_.stop();
        return;
    }
    timer_.start(minutes * 60 * 1000);
}

QString Autosave::copyPath() const { return folder_ + QStringLiteral("/autosave.glb"); }
QString Autosave::notePath() const { return folder_ + QStringLiteral("/autosave.source"); }

QString Autosave::saveNow() {
    if (!document_.isModified()) return {};
    if (!QDir().mkpath(folder_)) return tr("Cannot create the autosave folder %1").arg(folder_);
    try {
        saveScene(document_.scene(), std::filesystem::path(copyPath().toStdString()));
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    QSaveFile note(notePath());
    if (!note.open(QIODevice::WriteOnly)) return note.errorString();
    note.write(document_.filePath().toUtf8());
    if (!note.commit()) return note.errorString();
    return {};
}

void Autosave::discard() {
    QFile::remove(copyPath());
    QFile::remove(folder_ + QStringLiteral("/autosave.glint.json"));
    QFile::remove(notePath());
}

std::optional<Autosave::Leftover> Autosave::leftover() const {
    if (!QFile::exists(copyPath())) return std::nullopt;
    Leftover found{copyPath(), {}};
    QFile note(notePath());
    if (note.open(QIODevice::ReadOnly)) found.original = QString::fromUtf8(note.readAll());
    return found;
}

} // namespace glint::editor
