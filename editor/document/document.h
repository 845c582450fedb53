#pragma once
// The open document of the editor: one Scene, its undo History and the file it came from.
// Every edit goes through push() (a Command), so every view follows the scene through the
// changed() signal instead of editing it directly. Selection and the current time are editor
// state, not document content: they never dirty the file.
//
// Files are read on a worker (SceneLoader): the document keeps its scene until the new one
// arrives, and a failed or cancelled load leaves it untouched (scene, file path, history).
#include "node_placement.h"
#include "scene_loader.h"

#include "scene/core/scene.h"
#include "scene/history/command.h"
#include "scene/history/history.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
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
    // Takes back a cancelled interaction's edits without leaving a redo step (History).
    ChangeSet revertInteraction(std::uint64_t interaction);
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
    // Auto key (editor state): transform edits key every edited node at the current time
    // (keyed_transform.h); off, only nodes that have keys are keyed.
    bool autoKey() const { return autoKey_; }
    void setAutoKey(bool on);

    // --- where the viewport looks (editor state): new nodes land there (node_placement.h) ----
    // The viewport provides it when asked (it looks the focus up in its picker); none: the origin.
    ViewFocus viewFocus() const { return focusProvider_ ? focusProvider_() : ViewFocus{}; }
    void setViewFocusProvider(std::function<ViewFocus()> provider) { focusProvider_ = std::move(provider); }

    // --- files: each returns an empty string on success, a message for people otherwise ----
    // open, importFile and recover read on the calling thread (tests); the editor uses the
    // start* forms below. Each cancels the background loads first.
    void newScene(Scene scene = {}); // an untitled document with `scene` (a template); cancels the background loads
    QString open(const QString& path);
    QString save();
    QString saveAs(const QString& path);
    QString importFile(const QString& path); // merged into the scene as one undoable step
    // Loads an autosaved copy in place of `originalPath` (empty: untitled); the document stays
    // modified until it is saved, since the copy is newer than the file.
    QString recover(const QString& autosaveFile, const QString& originalPath);

    // --- the same, read in the background ---------------------------------------------------
    // An open (or recovery) supersedes every load in flight or queued; an import queues behind
    // the load in flight. Each ends in exactly one of loaded, loadFailed or loadCancelled.
    enum class LoadKind { Open, Import, Recover };
    Q_ENUM(LoadKind)
    void startOpen(const QString& path);
    void startImport(const QString& path);
    void startRecover(const QString& autosaveFile, const QString& originalPath);
    void cancelLoading(); // the load in flight and the queued ones
    bool isLoading() const { return inFlight_.has_value(); }
    LoadKind loadingKind() const { return inFlight_ ? inFlight_->kind : LoadKind::Open; }
    int runningReads() const { return loader_.runningReads(); } // cancelled ones included
    // Where the import worker is and its limits (tests name the worker they built).
    void setImportOptions(const ImportOptions& options);
    // Asked before a finished open replaces a document edited since the open started (its
    // unsaved-changes prompt came before those edits); false drops the opened scene.
    void setReplaceConfirmation(std::function<bool()> confirm) { confirmReplace_ = std::move(confirm); }

    const QString& filePath() const { return path_; }
    // The folder the scene's relative paths (the project's environment image) resolve in: the open
    // file's; empty while the scene is untitled.
    std::filesystem::path folder() const;
    // The project's environment image on disk: an absolute path as it is (what the editor stores
    // for a file chosen in an untitled scene, until the first save copies it beside the scene), a
    // relative one in folder(). Empty when there is none, or a relative one with no folder yet.
    std::filesystem::path environmentPath() const;
    // Points the project's environment image at `file`, another path of the same image (the copy a
    // save made beside the scene, the path an autosaved copy stands for). Not an undoable edit and
    // the clean state stays: the image is the same, only where it is read from changed.
    void relocateEnvironment(const std::string& file);
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
    void autoKeyChanged(bool on);
    void fileChanged();
    // Another scene took the document's place (open, recovery, new): views start afresh.
    void sceneReplaced();
    void cleanChanged(bool clean);
    // The undo position moved or a macro closed: canUndo/canRedo and their labels may differ.
    void historyIndexChanged();
    void warningsReported(const QStringList& lines);
    // Background loads. `path` is the file read (for a recovery: the file the copy stands for).
    void loadStarted(glint::editor::Document::LoadKind kind, const QString& path);
    void loadProgress(const QString& stage);
    void loaded(glint::editor::Document::LoadKind kind, const QString& path);
    void loadFailed(glint::editor::Document::LoadKind kind, const QString& path, const QString& message);
    void loadCancelled(glint::editor::Document::LoadKind kind, const QString& path);
    void loadingChanged(bool loading);

private:
    struct LoadRequest {
        LoadKind kind = LoadKind::Open;
        QString file;     // what is read
        QString original; // a recovery: the file the copy stands for
        QString shownPath() const { return kind == LoadKind::Recover ? original : file; }
    };
    void startLoad(LoadRequest request);
    void startNext();
    void onLoaded();
    void onLoadFailed(const QString& message);
    void applyOpened(const QString& path, LoadResult result);
    void applyRecovered(const QString& original, LoadResult result);
    void applyImported(const QString& path, LoadResult result);
    void onHistoryChanged(const ChangeSet& changes);
    void onHistoryIndex();
    void replaceScene(Scene scene);
    void adoptSavedEnvironment(const std::filesystem::path& savedFile, const Warnings& dropped);
    void pruneSelection();
    void reportWarnings(QStringList lines);

    Scene scene_;
    History history_;
    QString path_;
    std::vector<NodeId> selection_;
    // The selection before the command at each history index ran, restored when it is undone.
    std::map<std::size_t, std::vector<NodeId>> selectionBefore_;
    double time_ = 0.0;
    bool autoKey_ = false;
    std::function<ViewFocus()> focusProvider_;
    bool lastClean_ = true;
    bool recovered_ = false;
    QStringList warnings_;
    int macroDepth_ = 0;
    std::size_t macroIndex_ = 0;
    std::vector<NodeId> macroSelection_;
    History::ListenerId changeListener_ = 0;
    History::ListenerId indexListener_ = 0;
    std::uint64_t revision_ = 0; // counts every change, to tell edits made while a load ran
    ImportOptions importOptions_;
    SceneLoader loader_;
    std::optional<LoadRequest> inFlight_;
    std::deque<LoadRequest> queued_;
    std::uint64_t revisionAtLoad_ = 0;
    std::function<bool()> confirmReplace_;
};

} // namespace glint::editor
