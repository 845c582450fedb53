#pragma once
// Autosave and crash recovery. While the document has unsaved changes, a copy is saved every few
// minutes into the autosave folder: a GLB with its project file, plus a note naming the file the
// copy stands for, the session that wrote it and the project's environment image. Copies are kept
// per file (per session while untitled), so an editor on another file never overwrites them.
// Saving, or closing without a crash, removes the document's copy. A copy whose session is gone
// (its lock file is not held by a running editor) is a leftover the main window offers back.
#include <QDateTime>
#include <QList>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>

class QLockFile;

namespace glint::editor {

class Document;

class Autosave : public QObject {
    Q_OBJECT
public:
    // `folder` empty: <AppDataLocation>/autosave.
    Autosave(Document& document, QString folder = {}, QObject* parent = nullptr);
    ~Autosave() override;

    void setIntervalMinutes(int minutes); // 0 turns autosave off
    QString folder() const { return folder_; }
    QString copyPath() const;             // the GLB of the document's copy

    // Saves a copy now when the document has unsaved changes. Returns an error message or "".
    QString saveNow();
    void discard(); // removes the document's copy (after a save, or on a clean exit)

    // A copy left by an earlier session that did not end normally.
    struct Leftover {
        QString copy;        // its GLB
        QString original;    // the file it stands for; empty: an untitled scene
        QString environment; // the project's environment image as the document named it
        QDateTime saved;
        // Its file was saved after it: a save completed but the editor died before removing the
        // copy. Listed in File > Recover, never offered as newer than the file.
        bool superseded = false;
    };
    // Every leftover, newest first: neither this session's copies nor a running editor's.
    QList<Leftover> leftovers() const;
    std::optional<Leftover> leftover() const; // the newest one not superseded
    void discard(const Leftover& leftover);
    // The document now holds `leftover` (recovered): its environment image is named as before, the
    // document's own copy is saved at once and the leftover's files go.
    void adopt(const Leftover& leftover);

signals:
    void failed(const QString& message);

private:
    QString slot() const; // the copy's base name: per file, or per session while untitled
    QString slotPath(const QString& slot, const char* suffix) const;
    void removeSlot(const QString& slot);
    bool lockSession();

    Document& document_;
    QString folder_;
    QTimer timer_;
    QString session_;                 // this editor's id: its untitled copy and its lock file
    std::unique_ptr<QLockFile> lock_; // held while this session has copies
    QString lastSlot_;                // the slot of the document's file before it changed
};

} // namespace glint::editor
