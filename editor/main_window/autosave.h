#pragma once
// Autosave and crash recovery. While the document has unsaved changes, a copy is saved every few
// minutes into the autosave folder (a GLB with its project file, plus a note naming the file the
// copy stands for). Saving, or closing without a crash, removes the copy; a copy found at start
// means the last session ended without that, and the main window offers to recover it.
#include <QObject>
#include <QString>
#include <QTimer>

#include <optional>

namespace glint::editor {

class Document;

class Autosave : public QObject {
    Q_OBJECT
public:
    // `folder` empty: <AppDataLocation>/autosave.
    Autosave(Document& document, QString folder = {}, QObject* parent = nullptr);

    void setIntervalMinutes(int minutes); // 0 turns autosave off
    QString folder() const { return folder_; }
    QString copyPath() const;             // the GLB of the copy

    // Saves a copy now when the document has unsaved changes. Returns an error message or "".
    QString saveNow();
    void discard(); // removes the copy (after a save, or on a clean exit)

    // A copy left by an earlier session, if any: its GLB and the file it stands for.
    struct Leftover {
        QString copy;
        QString original;
    };
    std::optional<Leftover> leftover() const;

signals:
    void failed(const QString& message);

private:
    QString notePath() const;

    Document& document_;
    QString folder_;
    QTimer timer_;
};

} // namespace glint::editor
