#include "document.h"

#include "scene_merge.h"

#include "scene/import/import.h"
#include "scene/io/scene_io.h"

#include <QFileInfo>

#include <algorithm>
#include <exception>

namespace glint::editor {
namespace {

std::filesystem::path toPath(const QString& path) { return std::filesystem::path(path.toStdString()); }

QStringList warningLines(const Warnings& warnings) {
    QStringList lines;
    for (const Warning& w : warnings) lines << QString::fromStdString(w.file + ": " + w.message);
    return lines;
}

bool isNativeScene(const QString& path) {
    const QString lower = path.toLower();
    return lower.endsWith(".gltf") || lower.endsWith(".glb") || lower.endsWith(".glint.json");
}

LoadResult readAnyScene(const QString& path) {
    if (isNativeScene(path)) return loadScene(toPath(path));
    if (isImportableFile(toPath(path))) return importScene(toPath(path));
    throw FileError(path.toStdString(), "unsupported-format", "not a scene file Glint can open or import");
}

} // namespace

Document::Document(QObject* parent) : QObject(parent), history_(scene_) {
    changeListener_ = history_.addChangeListener([this](const ChangeSet& c) { onHistoryChanged(c); });
    indexListener_ = history_.addIndexListener([this](std::size_t) { onHistoryIndex(); });
}

Document::~Document() {
    history_.removeListener(changeListener_);
    history_.removeListener(indexListener_);
}

ChangeSet Document::push(CommandPtr command) {
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

void Document::setCurrentTime(double seconds) {
    if (seconds == time_) return;
    time_ = seconds;
    emit timeChanged(time_);
}

void Document::newScene() {
    replaceScene(Scene{});
    recovered_ = false;
    onHistoryIndex();
    path_.clear();
    reportWarnings({});
    emit fileChanged();
}

QString Document::open(const QString& path) {
    try {
        LoadResult result = readAnyScene(path);
        replaceScene(std::move(result.scene));
        recovered_ = false;
        onHistoryIndex();
        // Imported formats are not saved back in place: the document starts untitled.
        path_ = isNativeScene(path) ? QFileInfo(path).absoluteFilePath() : QString();
        reportWarnings(warningLines(result.warnings));
        emit fileChanged();
        return {};
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
}

QString Document::recover(const QString& autosaveFile, const QString& originalPath) {
    try {
        LoadResult result = loadScene(toPath(autosaveFile));
        replaceScene(std::move(result.scene));
        path_ = originalPath.isEmpty() ? QString() : QFileInfo(originalPath).absoluteFilePath();
        recovered_ = true;
        onHistoryIndex();
        reportWarnings(warningLines(result.warnings));
        emit fileChanged();
        return {};
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
}

QString Document::save() {
    if (path_.isEmpty()) return tr("The scene has no file name yet: use Save As.");
    return saveAs(path_);
}

QString Document::saveAs(const QString& path) {
    QString target = path;
    if (!target.toLower().endsWith(".gltf") && !target.toLower().endsWith(".glb")) target += ".gltf";
    try {
        SaveReport report = saveScene(scene_, toPath(target));
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
    return {};
}

QString Document::importFile(const QString& path) {
    try {
        LoadResult result = readAnyScene(path);
        std::vector<CommandPtr> commands = mergeCommands(scene_, result.scene);
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
        return {};
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
}

QString Document::displayName() const {
    if (!scene_.name.empty()) return QString::fromStdString(scene_.name);
    if (!path_.isEmpty()) return QFileInfo(path_).fileName();
    return tr("Untitled");
}

void Document::onHistoryChanged(const ChangeSet& changes) {
    if (changes.has(Change::Structure)) pruneSelection();
    emit changed(changes);
}

void Document::onHistoryIndex() {
    // Selections recorded for commands that no longer exist must not come back.
    selectionBefore_.erase(selectionBefore_.upper_bound(history_.count()), selectionBefore_.end());
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
