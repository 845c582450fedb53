#pragma once
// The open document of the editor: one Scene, its undo History and the file it came from.
// Every edit goes through push() (a Command), so every view follows the scene through the
// changed() signal instead of editing it directly. Selection and the current time are editor
// state, not document content: they never dirty the file.
#include "scene/core/scene.h"
#include "scene/history/command.h"
#include "scene/history/history.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <map>
#include <vector>

namespace glint::editor {

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    Scene& scene() { return scene_; }
    const Scene& scene() const { return scene_; }
    History& history() { return history_; }
    const History& history() const { return history_; }

    // Applies and records a command. Exceptions from the command propagate (nothing recorded).
    ChangeSet push(CommandPtr command);
    ChangeSet undo();
    ChangeSet redo();
    ChangeSet jumpTo(std::size_t index);
    bool canUndo() const { return history_.canUndo(); }
    bool canRedo() const { return history_.canRedo(); }
    std::uint64_t beginInteraction() { return history_.beginInteraction(); }
    // Groups the pushes until the matching endMacro into one undo step (History::beginMacro);
    // undoing it restores the selection from before the macro.
    void beginMacro(const QString& label);
    void endMacro();

    // --- selection (editor state; never dirties the file) ------------------------------------
    const std::vector<NodeId>& selection() const { return selection_; }
    void setSelection(std::vector<NodeId> nodes);
    NodeId currentNode() const; // the last selected node, or none
    bool isSelected(NodeId id) const;

    // --- time ------------------------------------------------------------------------------
    double currentTime() const { return time_; }
    void setCurrentTime(double seconds);

    // --- files: each returns an empty string on success, a message for people otherwise ----
    void newScene();
    QString open(const QString& path);
    QString save();
    QString saveAs(const QString& path);
    QString importFile(const QString& path); // merged into the scene as one undoable step
    // Loads an autosaved copy in place of `originalPath` (empty: untitled); the document stays
    // modified until it is saved, since the copy is newer than the file.
    QString recover(const QString& autosaveFile, const QString& originalPath);

    const QString& filePath() const { return path_; }
    QString displayName() const;  // the scene name, else the file name, else "Untitled"
    bool isModified() const { return recovered_ || !history_.isClean(); }
    // Warnings of the last open, import or save, as "FILE: message" lines.
    const QStringList& lastWarnings() const { return warnings_; }

public slots:
    // For warnings that do not come from a file (the renderer, a worker): they reach the log
    // panel through warningsReported like the loader's.
    void reportWarning(const QString& line) { emit warningsReported({line}); }

signals:
    void changed(const glint::ChangeSet& changes);
    void selectionChanged();
    void timeChanged(double seconds);
    void fileChanged();
    void cleanChanged(bool clean);
    void warningsReported(const QStringList& lines);

private:
    void onHistoryChanged(const ChangeSet& changes);
    void onHistoryIndex();
    void replaceScene(Scene scene);
    void pruneSelection();
    void reportWarnings(QStringList lines);

    Scene scene_;
    History history_;
    QString path_;
    std::vector<NodeId> selection_;
    // The selection before the command at each history index ran, restored when it is undone.
    std::map<std::size_t, std::vector<NodeId>> selectionBefore_;
    double time_ = 0.0;
    bool lastClean_ = true;
    bool recovered_ = false;
    QStringList warnings_;
    int macroDepth_ = 0;
    std::size_t macroIndex_ = 0;
    std::vector<NodeId> macroSelection_;
    History::ListenerId changeListener_ = 0;
    History::ListenerId indexListener_ = 0;
};

} // namespace glint::editor
