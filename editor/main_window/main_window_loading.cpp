// Opening, importing and recovering files in the background: the status bar's progress, what
// is reported when a load ends, and which actions a load in flight disables.
#include "main_window.h"

#include "autosave.h"
#include "load_progress.h"
#include "recent_files.h"

#include "editor/log/log_panel.h"

#include <QAction>
#include <QFileInfo>
#include <QMessageBox>
#include <QStatusBar>

namespace glint::editor {

namespace {

// The importer (Assimp) speaks in its own terms ("Validation failed: aiScene::mNumMeshes is 0"):
// the common cases in words, with the file's name; anything else as it came (empty: no better words).
QString importProblemInWords(const QString& file, const QString& message) {
    const QString name = QFileInfo(file).fileName();
    const auto has = [&](const char* text) { return message.contains(QLatin1String(text), Qt::CaseInsensitive); };
    if (has("mNumMeshes is 0")) return MainWindow::tr("There are no meshes in %1: nothing to import.").arg(name);
    if (has("contains no faces") || has("contains no vertices"))
        return MainWindow::tr("%1 holds a mesh without any faces, so it cannot be imported.").arg(name);
    if (has("No suitable reader found") || has("unsupported-format"))
        return MainWindow::tr("%1 is in no format Glint imports (glTF, OBJ, PLY, STL, FBX, DAE, 3DS).").arg(name);
    if (has("unexpected end of file") || has("unexpected EOF") || has("truncated"))
        return MainWindow::tr("%1 ends too early: the file is damaged or was not copied completely.").arg(name);
    if (has("Unable to open file") || has("no such file")) return MainWindow::tr("%1 cannot be read.").arg(name);
    if (has("the file is empty")) return MainWindow::tr("%1 is empty.").arg(name);
    return {};
}

} // namespace

void MainWindow::connectLoading() {
    connect(document_, &Document::loadStarted, this, &MainWindow::onLoadStarted);
    connect(document_, &Document::loadProgress, loadProgress_, &LoadProgress::setStage);
    connect(document_, &Document::loaded, this, &MainWindow::onLoaded);
    connect(document_, &Document::loadFailed, this, &MainWindow::onLoadFailed);
    connect(document_, &Document::loadCancelled, this, &MainWindow::onLoadCancelled);
    connect(document_, &Document::loadingChanged, this, [this](bool loading) {
        if (!loading) loadProgress_->end();
        updateLoadActions();
    });
    connect(loadProgress_, &LoadProgress::cancelRequested, document_, &Document::cancelLoading);
    // Edits made while an open was read get their own unsaved-changes prompt before it replaces them.
    document_->setReplaceConfirmation([this] { return maybeSave(); });
}

void MainWindow::beginOpen(const QString& path) { document_->startOpen(path); }

void MainWindow::beginImport(const QString& path) { document_->startImport(path); }

bool MainWindow::openFile(const QString& path) {
    const QString error = document_->open(path);
    if (!error.isEmpty()) onLoadFailed(Document::LoadKind::Open, path, error);
    else onLoaded(Document::LoadKind::Open, path);
    return error.isEmpty();
}

void MainWindow::onLoadStarted(Document::LoadKind kind, const QString& path) {
    const QString name = QFileInfo(path).fileName();
    switch (kind) {
    case Document::LoadKind::Open: loadProgress_->begin(tr("Opening %1").arg(name)); break;
    case Document::LoadKind::Import: loadProgress_->begin(tr("Importing %1").arg(name)); break;
    case Document::LoadKind::Recover:
        loadProgress_->begin(name.isEmpty() ? tr("Recovering an untitled scene") : tr("Recovering %1").arg(name));
        break;
    }
    updateLoadActions();
}

void MainWindow::onLoaded(Document::LoadKind kind, const QString& path) {
    switch (kind) {
    case Document::LoadKind::Open:
        RecentFiles().add(path);
        rebuildRecentMenu();
        log_->info(tr("Opened %1").arg(path));
        statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(path).fileName()), 4000);
        break;
    case Document::LoadKind::Import:
        log_->info(tr("Imported %1").arg(path));
        statusBar()->showMessage(tr("Imported %1").arg(QFileInfo(path).fileName()), 4000);
        break;
    case Document::LoadKind::Recover:
        log_->info(tr("Recovered the autosaved copy of %1").arg(path.isEmpty() ? tr("an untitled scene") : path));
        if (recovering_) autosave_->adopt(*recovering_);
        recovering_.reset();
        refreshRecovery();
        break;
    }
}

// The document is as it was: only the log, the status bar and (for an open) a message box say why.
void MainWindow::onLoadFailed(Document::LoadKind kind, const QString& path, const QString& message) {
    switch (kind) {
    case Document::LoadKind::Open:
        report(tr("Cannot open %1: %2").arg(path, message));
        QMessageBox::warning(this, tr("Open"), tr("Cannot open %1:\n%2").arg(QFileInfo(path).fileName(), message));
        break;
    case Document::LoadKind::Import: {
        // Where the user looks (the log may be behind the timeline), in words, as for an open.
        const QString words = importProblemInWords(path, message);
        report(words.isEmpty() ? tr("Cannot import %1: %2").arg(path, message) : tr("%1 (%2)").arg(words, message));
        QMessageBox box(QMessageBox::Warning, tr("Import"),
                        words.isEmpty() ? tr("Cannot import %1:\n%2").arg(QFileInfo(path).fileName(), message) : words,
                        QMessageBox::Ok, this);
        if (!words.isEmpty()) box.setDetailedText(message); // the importer's own words, for a bug report
        box.exec();
        break;
    }
    case Document::LoadKind::Recover:
        report(tr("Cannot recover the autosaved copy: %1").arg(message));
        recovering_.reset();
        refreshRecovery();
        break;
    }
}

void MainWindow::onLoadCancelled(Document::LoadKind kind, const QString& path) {
    const QString name = QFileInfo(path).fileName();
    const QString text = kind == Document::LoadKind::Import ? tr("Import of %1 cancelled").arg(name)
                                                            : tr("Opening %1 cancelled").arg(name);
    log_->info(text);
    statusBar()->showMessage(text, 4000);
    if (kind == Document::LoadKind::Recover) {
        recovering_.reset();
        refreshRecovery();
    }
}

// Open stays available (a new open supersedes the one in flight) and so does Save (it saves the
// scene shown, which a load leaves alone until it arrives). Import is off while an open runs:
// it is not clear whether the user means the scene shown or the one about to replace it.
void MainWindow::updateLoadActions() {
    const bool opening = document_->isLoading() && document_->loadingKind() != Document::LoadKind::Import;
    import_->setEnabled(!opening);
}

} // namespace glint::editor
