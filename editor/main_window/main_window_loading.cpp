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
    case Document::LoadKind::Import: report(tr("Cannot import %1: %2").arg(path, message)); break;
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
