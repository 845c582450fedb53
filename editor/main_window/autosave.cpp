#include "autosave.h"

#include "editor/document/document.h"

#include "scene/io/scene_io.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QSaveFile>
#include <QStandardPaths>

#include <algorithm>
#include <atomic>
#include <exception>
#include <utility>

namespace glint::editor {

namespace {

// The note beside a copy: the file it stands for, the session that wrote it, the environment image.
struct Note {
    QString original;
    QString session;
    QString environment;
};

std::optional<Note> readNote(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return std::nullopt;
    const QStringList lines = QString::fromUtf8(file.readAll()).split('\n');
    return Note{lines.value(0), lines.value(1), lines.value(2)};
}

// Whether an editor that is still running holds this session's lock.
bool sessionRunning(const QString& lockPath) {
    if (!QFile::exists(lockPath)) return false;
    QLockFile probe(lockPath);
    probe.setStaleLockTime(0); // only a lock whose process is gone is stale, however old
    if (probe.tryLock(0)) {
        probe.unlock();
        return false;
    }
    return probe.error() == QLockFile::LockFailedError;
}

QString newSessionId() {
    static std::atomic<int> counter{0};
    return QStringLiteral("%1-%2-%3")
        .arg(QCoreApplication::applicationPid())
        .arg(QDateTime::currentMSecsSinceEpoch())
        .arg(counter.fetch_add(1));
}

} // namespace

Autosave::Autosave(Document& document, QString folder, QObject* parent)
    : QObject(parent), document_(document), folder_(std::move(folder)), session_(newSessionId()) {
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
    // Another file (opened, saved as, recovered, new): this session's copy of the one before is
    // obsolete (it was saved, or the user chose to discard it).
    lastSlot_ = slot();
    connect(&document_, &Document::fileChanged, this, [this] {
        const QString now = slot();
        if (now == lastSlot_) return;
        removeSlot(lastSlot_);
        lastSlot_ = now;
    });
    setIntervalMinutes(2);
}

Autosave::~Autosave() = default; // the lock goes with it: what is left over is offered next time

void Autosave::setIntervalMinutes(int minutes) {
    if (minutes <= 0) {
        timer_.stop();
        return;
    }
    timer_.start(minutes * 60 * 1000);
}

QString Autosave::slot() const {
    const QString path = document_.filePath();
    if (path.isEmpty()) return QStringLiteral("untitled-") + session_;
    const QByteArray key = QFileInfo(path).absoluteFilePath().toUtf8();
    return QStringLiteral("file-") + QString::fromLatin1(QCryptographicHash::hash(key, QCryptographicHash::Sha1).toHex().left(16));
}

QString Autosave::slotPath(const QString& slot, const char* suffix) const {
    return folder_ + QLatin1Char('/') + slot + QLatin1String(suffix);
}

QString Autosave::copyPath() const { return slotPath(slot(), ".glb"); }

bool Autosave::lockSession() {
    if (lock_) return true;
    auto lock = std::make_unique<QLockFile>(folder_ + QStringLiteral("/session-") + session_ + QStringLiteral(".lock"));
    lock->setStaleLockTime(0);
    if (!lock->tryLock(0)) return false;
    lock_ = std::move(lock);
    return true;
}

QString Autosave::saveNow() {
    if (!document_.isModified()) return {};
    if (!QDir().mkpath(folder_)) return tr("Cannot create the autosave folder %1").arg(folder_);
    lockSession();
    // The environment image stays where the document names it (an absolute path would not load
    // from the copy, a relative one would be copied into the autosave folder every time): the
    // note keeps its name and the copy goes without it.
    Scene& scene = document_.scene();
    const std::string environment = std::exchange(scene.settings.environment.file, std::string());
    try {
        saveScene(scene, std::filesystem::path(copyPath().toStdString()));
    } catch (const std::exception& e) {
        scene.settings.environment.file = environment;
        return QString::fromStdString(e.what());
    }
    scene.settings.environment.file = environment;
    // Its errors name it, as the copy's do (a full disk or a read-only folder is said with the file).
    const QString notePath = slotPath(slot(), ".source");
    QSaveFile note(notePath);
    if (!note.open(QIODevice::WriteOnly)) return notePath + QStringLiteral(": ") + note.errorString();
    note.write(QStringList{document_.filePath(), session_, QString::fromStdString(environment)}.join('\n').toUtf8());
    if (!note.commit()) return notePath + QStringLiteral(": ") + note.errorString();
    return {};
}

// Only this session's copies: another editor's copy of the same file is its own business.
void Autosave::removeSlot(const QString& slot) {
    const std::optional<Note> note = readNote(slotPath(slot, ".source"));
    if (note && !note->session.isEmpty() && note->session != session_) return;
    QFile::remove(slotPath(slot, ".glb"));
    QFile::remove(slotPath(slot, ".glint.json"));
    QFile::remove(slotPath(slot, ".source"));
}

void Autosave::discard() { removeSlot(slot()); }

QList<Autosave::Leftover> Autosave::leftovers() const {
    QList<Leftover> found;
    const QDir dir(folder_);
    for (const QString& name : dir.entryList({QStringLiteral("*.source")}, QDir::Files)) {
        const QString slot = name.chopped(int(qstrlen(".source")));
        const std::optional<Note> note = readNote(dir.filePath(name));
        const QString copy = slotPath(slot, ".glb");
        if (!note || !QFile::exists(copy) || note->session == session_) continue;
        if (!note->session.isEmpty() && sessionRunning(folder_ + QStringLiteral("/session-") + note->session + QStringLiteral(".lock")))
            continue; // an editor still working on it
        const QDateTime saved = QFileInfo(copy).lastModified();
        const QFileInfo original(note->original);
        const bool superseded = !note->original.isEmpty() && original.exists() && original.lastModified() > saved;
        found.push_back({copy, note->original, note->environment, saved, superseded});
    }
    std::sort(found.begin(), found.end(), [](const Leftover& a, const Leftover& b) { return a.saved > b.saved; });
    return found;
}

std::optional<Autosave::Leftover> Autosave::leftover() const {
    for (const Leftover& leftover : leftovers())
        if (!leftover.superseded) return leftover;
    return std::nullopt;
}

void Autosave::discard(const Leftover& leftover) {
    const QString base = leftover.copy.chopped(int(qstrlen(".glb")));
    QFile::remove(leftover.copy);
    QFile::remove(base + QStringLiteral(".glint.json"));
    QFile::remove(base + QStringLiteral(".source"));
}

void Autosave::adopt(const Leftover& leftover) {
    if (!leftover.environment.isEmpty()) document_.relocateEnvironment(leftover.environment.toStdString());
    lastSlot_ = slot();
    const bool same = QFileInfo(leftover.copy) == QFileInfo(copyPath());
    const QString error = saveNow(); // the recovered work is safe under this session before the old copy goes
    if (!error.isEmpty()) {
        emit failed(error);
        return;
    }
    if (!same) discard(leftover);
}

} // namespace glint::editor
