#include "document.h"

#include "labelled_command.h"
#include "scene_merge.h"

#include "editor/history_view/command_labels.h"
#include "scene/history/set_node_field.h"


#include <QFileInfo>

#include <algorithm>
#include <exception>
#include <memory>

namespace glint::editor {
namespace {

std::filesystem::path toPath(const QString& path) { return std::filesystem::path(path.toStdString()); }

QStringList warningLines(const Warnings& warnings) {
    QStringList lines;
    for (const Warning& w : warnings) lines << QString::fromStdString(w.file + ": " + w.message);
    return lines;
}

} // namespace

Document::Document(QObject* parent) : QObject(parent), history_(scene_) {
    connect(&loader_, &SceneLoader::progress, this, &Document::loadProgress);
    connect(&loader_, &SceneLoader::finished, this, &Document::onLoaded);
    connect(&loader_, &SceneLoader::failed, this, &Document::onLoadFailed);
    changeListener_ = history_.addChangeListener([this](const ChangeSet& c) { onHistoryChanged(c); });
    indexListener_ = history_.addIndexListener([this](std::size_t) { onHistoryIndex(); });
}

Document::~Document() {
    history_.removeListener(changeListener_);
    history_.removeListener(indexListener_);
}

ChangeSet Document::push(CommandPtr command) {
    // A transform edit says what it does ("Rotate" for the rotate gizmo or a rotation field), not
    // the core's "Move" for everything. Every one is labelled, so a drag's steps still merge.
    if (const auto* transform = dynamic_cast<const SetTransform*>(command.get()); transform && scene_.contains(transform->node()))
        command = std::make_unique<LabelledCommand>(
            std::move(command), describeTransformEdit(scene_.at(transform->node()).local, transform->newValue()));
    const std::size_t index = history_.index();
    std::vector<NodeId> before = selection_;
    ChangeSet changes = history_.push(std::move(command));
    // A merge leaves the index where it was: the selection before the drag stays recorded.
    if (history_.index() > index && macroDepth_ == 0) selectionBefore_[index] = std::move(before);
    return changes;
}

void Document::beginMacro(const QString& label) {
    if (macroDepth_++ == 0) {
        macroIndex_ = history_.index();
        macroSelection_ = selection_;
    }
    history_.beginMacro(label.toStdString());
}

void Document::endMacro() {
    history_.endMacro();
    if (--macroDepth_ == 0 && history_.index() > macroIndex_) selectionBefore_[macroIndex_] = macroSelection_;
}

ChangeSet Document::undo() {
    if (!history_.canUndo()) return {};
    const std::size_t undone = history_.index() - 1;
    ChangeSet changes = history_.undo();
    if (auto it = selectionBefore_.find(undone); it != selectionBefore_.end()) setSelection(it->second);
    return changes;
}

ChangeSet Document::revertInteraction(std::uint64_t interaction) {
    const std::size_t before = history_.index();
    ChangeSet changes = history_.revertInteraction(interaction);
    for (std::size_t i = history_.index(); i < before; ++i) selectionBefore_.erase(i);
    return changes;
}

ChangeSet Document::redo() {
    if (!history_.canRedo()) return {};
    ChangeSet changes = history_.redo();
    // Redoing an edit of nodes selects them again, as they were right after the edit.
    if (!changes.nodes.empty() && changes.has(Change::Structure)) {
        std::vector<NodeId> nodes(changes.nodes.begin(), changes.nodes.end());
        setSelection(std::move(nodes));
    }
    return changes;
}

ChangeSet Document::jumpTo(std::size_t index) {
    ChangeSet all;
    while (history_.index() > index && history_.canUndo()) all.merge(undo());
    while (history_.index() < index && history_.canRedo()) all.merge(redo());
    return all;
}

void Document::setSelection(std::vector<NodeId> nodes) {
    std::vector<NodeId> unique;
    for (NodeId id : nodes)
        if (id && scene_.contains(id) && std::find(unique.begin(), unique.end(), id) == unique.end())
            unique.push_back(id);
    if (unique == selection_) return;
    selection_ = std::move(unique);
    emit selectionChanged();
}

NodeId Document::currentNode() const { return selection_.empty() ? NodeId{} : selection_.back(); }

bool Document::isSelected(NodeId id) const {
    return std::find(selection_.begin(), selection_.end(), id) != selection_.end();
}

void Document::setAutoKey(bool on) {
    if (on == autoKey_) return;
    autoKey_ = on;
    emit autoKeyChanged(on);
}

void Document::setCurrentTime(double seconds) {
    if (seconds == time_) return;
    time_ = seconds;
    emit timeChanged(time_);
}

void Document::newScene(Scene scene) {
    cancelLoading();
    replaceScene(std::move(scene));
    recovered_ = false;
    onHistoryIndex();
    path_.clear();
    reportWarnings({});
    emit fileChanged();
}

QString Document::open(const QString& path) {
    cancelLoading();
    try {
        applyOpened(path, readSceneFile(path, importOptions_));
        return {};
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
}

QString Document::recover(const QString& autosaveFile, const QString& originalPath) {
    cancelLoading();
    try {
        applyRecovered(originalPath, readSceneFile(autosaveFile, importOptions_));
        return {};
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
}

void Document::applyOpened(const QString& path, LoadResult result) {
    replaceScene(std::move(result.scene));
    recovered_ = false;
    onHistoryIndex();
    // Imported formats are not saved back in place: the document starts untitled.
    path_ = isNativeScene(path) ? QFileInfo(path).absoluteFilePath() : QString();
    reportWarnings(warningLines(result.warnings));
    emit fileChanged();
}

void Document::applyRecovered(const QString& original, LoadResult result) {
    replaceScene(std::move(result.scene));
    path_ = original.isEmpty() ? QString() : QFileInfo(original).absoluteFilePath();
    recovered_ = true;
    onHistoryIndex();
    reportWarnings(warningLines(result.warnings));
    emit fileChanged();
}

QString Document::save() {
    if (path_.isEmpty()) return tr("The scene has no file name yet: use Save As.");
    return saveAs(path_);
}

QString Document::saveAs(const QString& path) {
    QString target = path;
    if (!target.toLower().endsWith(".gltf") && !target.toLower().endsWith(".glb")) target += ".gltf";
    SaveReport report;
    try {
        // Relative paths (the environment image) resolve beside the current file: a save into
        // another folder copies what they name, as textures are copied.
        SaveOptions options;
        options.sourceFolder = folder();
        report = saveScene(scene_, toPath(target), options);
        reportWarnings(warningLines(report.dropped));
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    history_.setClean();
    recovered_ = false;
    onHistoryIndex();
    const QString absolute = QFileInfo(target).absoluteFilePath();
    if (absolute != path_) {
        path_ = absolute;
        emit fileChanged();
    }
    adoptSavedEnvironment(toPath(target), report.dropped); // resolves in the new folder from here on
    return {};
}

// An environment image outside the scene's folder (an absolute path chosen in an untitled scene)
// was copied beside the saved file under its own name: the document now names that copy, as the
// saved project file does, so the Scene tab, the viewport and the next save agree with the file.
void Document::adoptSavedEnvironment(const std::filesystem::path& savedFile, const Warnings& dropped) {
    const std::string& file = scene_.settings.environment.file;
    if (file.empty() || !std::filesystem::path(file).is_absolute()) return;
    for (const Warning& w : dropped)
        if (w.code.rfind("environment-", 0) == 0) return; // not copied: keep what the user chose
    const std::filesystem::path name = std::filesystem::path(file).filename();
    std::error_code error;
    if (!std::filesystem::is_regular_file(std::filesystem::absolute(savedFile).parent_path() / name, error)) return;
    relocateEnvironment(name.generic_string());
}

void Document::relocateEnvironment(const std::string& file) {
    if (scene_.settings.environment.file == file) return;
    scene_.settings.environment.file = file;
    ChangeSet changes;
    changes.add(Change::Environment);
    emit changed(changes);
}

QString Document::importFile(const QString& path) {
    cancelLoading();
    try {
        applyImported(path, readSceneFile(path, importOptions_));
        return {};
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
}

// Throws when a command does; the macro is closed either way, so nothing half-merged stays open.
void Document::applyImported(const QString& path, LoadResult result) {
    std::vector<CommandPtr> commands = mergeCommands(scene_, std::move(result.scene));
    const NodeId firstNew = scene_.peekNextNodeId();
    beginMacro(tr("Import %1").arg(QFileInfo(path).fileName()));
    try {
        for (CommandPtr& command : commands) push(std::move(command));
    } catch (...) {
        endMacro();
        throw;
    }
    endMacro();
    std::vector<NodeId> added;
    for (NodeId root : scene_.roots())
        if (root >= firstNew) added.push_back(root);
    setSelection(added);
    reportWarnings(warningLines(result.warnings));
}

void Document::setImportOptions(const ImportOptions& options) {
    importOptions_ = options;
    loader_.setImportOptions(options);
}

void Document::startOpen(const QString& path) { startLoad({LoadKind::Open, path, {}}); }

void Document::startRecover(const QString& autosaveFile, const QString& originalPath) {
    startLoad({LoadKind::Recover, autosaveFile, originalPath});
}

void Document::startImport(const QString& path) {
    if (inFlight_) {
        queued_.push_back({LoadKind::Import, path, {}});
        return;
    }
    startLoad({LoadKind::Import, path, {}});
}

void Document::startLoad(LoadRequest request) {
    const bool wasLoading = isLoading();
    if (request.kind != LoadKind::Import) {
        // A new document supersedes everything: the load in flight and the imports queued for
        // the document it would have replaced.
        queued_.clear();
        if (inFlight_) emit loadCancelled(inFlight_->kind, inFlight_->shownPath());
    }
    inFlight_ = request;
    revisionAtLoad_ = revision_;
    loader_.start(request.file);
    emit loadStarted(request.kind, request.shownPath());
    if (!wasLoading) emit loadingChanged(true);
}

void Document::cancelLoading() {
    if (!inFlight_) return;
    const LoadRequest request = *inFlight_;
    loader_.cancel();
    inFlight_.reset();
    queued_.clear();
    emit loadCancelled(request.kind, request.shownPath());
    emit loadingChanged(false);
}

void Document::startNext() {
    if (queued_.empty()) {
        emit loadingChanged(false);
        return;
    }
    LoadRequest next = std::move(queued_.front());
    queued_.pop_front();
    inFlight_ = next;
    revisionAtLoad_ = revision_;
    loader_.start(next.file);
    emit loadStarted(next.kind, next.shownPath());
}

void Document::onLoaded() {
    std::unique_ptr<LoadResult> result = loader_.take();
    const LoadRequest request = *inFlight_;
    inFlight_.reset();
    // The prompt about unsaved changes came before the load; edits made since then get their own.
    const bool replaces = request.kind != LoadKind::Import;
    if (replaces && revision_ != revisionAtLoad_ && isModified() && confirmReplace_ && !confirmReplace_()) {
        emit loadCancelled(request.kind, request.shownPath());
        startNext();
        return;
    }
    QString error;
    try {
        if (request.kind == LoadKind::Open) applyOpened(request.file, std::move(*result));
        else if (request.kind == LoadKind::Recover) applyRecovered(request.original, std::move(*result));
        else applyImported(request.file, std::move(*result));
    } catch (const std::exception& e) {
        error = QString::fromStdString(e.what());
    }
    if (error.isEmpty()) emit loaded(request.kind, request.shownPath());
    else emit loadFailed(request.kind, request.shownPath(), error);
    startNext();
}

void Document::onLoadFailed(const QString& message) {
    const LoadRequest request = *inFlight_;
    inFlight_.reset();
    emit loadFailed(request.kind, request.shownPath(), message);
    startNext();
}

std::filesystem::path Document::folder() const {
    return path_.isEmpty() ? std::filesystem::path() : toPath(QFileInfo(path_).absolutePath());
}

std::filesystem::path Document::environmentPath() const {
    const std::string& file = scene_.settings.environment.file;
    if (file.empty()) return {};
    const std::filesystem::path path(file);
    if (path.is_absolute()) return path.lexically_normal();
    if (folder().empty()) return {};
    return (folder() / path).lexically_normal();
}

QString Document::displayName() const {
    if (!scene_.name.empty()) return QString::fromStdString(scene_.name);
    if (!path_.isEmpty()) return QFileInfo(path_).fileName();
    return tr("Untitled");
}

void Document::onHistoryChanged(const ChangeSet& changes) {
    ++revision_;
    if (changes.has(Change::Structure)) pruneSelection();
    emit changed(changes);
}

void Document::onHistoryIndex() {
    // Selections recorded for commands that no longer exist must not come back.
    selectionBefore_.erase(selectionBefore_.upper_bound(history_.count()), selectionBefore_.end());
    emit historyIndexChanged();
    const bool clean = !isModified();
    if (clean == lastClean_) return;
    lastClean_ = clean;
    emit cleanChanged(clean);
}

void Document::replaceScene(Scene scene) {
    history_.clear();
    selectionBefore_.clear();
    scene_ = std::move(scene); // History keeps a reference to scene_: assign, never re-seat
    history_.setClean();
    selection_.clear();
    time_ = 0.0;
    ChangeSet everything;
    everything.flags = ~0u;
    emit changed(everything);
    emit selectionChanged();
    emit timeChanged(time_);
    onHistoryIndex();
    emit sceneReplaced();
}

void Document::pruneSelection() {
    std::vector<NodeId> kept;
    for (NodeId id : selection_)
        if (scene_.contains(id)) kept.push_back(id);
    if (kept.size() == selection_.size()) return;
    selection_ = std::move(kept);
    emit selectionChanged();
}

void Document::reportWarnings(QStringList lines) {
    warnings_ = std::move(lines);
    if (!warnings_.isEmpty()) emit warningsReported(warnings_);
}

} // namespace glint::editor
