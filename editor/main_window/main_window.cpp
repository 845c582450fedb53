#include "main_window.h"

#include "autosave.h"
#include "load_progress.h"
#include "recent_files.h"
#include "recovery_bar.h"
#include "theme.h"

#include "editor/document/document.h"
#include "editor/history_view/history_panel.h"
#include "editor/log/log_panel.h"
#include "editor/outliner/node_names.h"
#include "editor/outliner/outliner_panel.h"
#include "editor/preferences/retranslate.h"
#include "editor/properties/configuration_names.h"
#include "editor/properties/properties_panel.h"

#include "editor/timeline/timeline_panel.h"
#include "editor/materials/material_operations.h"
#include "editor/materials/materials_panel.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/view_camera.h"
#include "editor/viewport/viewport.h"

#include <algorithm>

#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QVBoxLayout>

namespace glint::editor {

MainWindow::MainWindow(Options options, QWidget* parent) : QMainWindow(parent), options_(std::move(options)) {
    setObjectName("MainWindow");
    setAcceptDrops(true);
    setDockNestingEnabled(true);
    document_ = new Document(this);
    autosave_ = new Autosave(*document_, options_.autosaveFolder, this);
    preferences_ = Preferences::load();

    createCentralView();
    createDocks();
    createActions();
    createMenus();
    createToolBar();
    createStatusBar();
    rememberDefaultShortcuts();
    applyPreferences();
    restoreLayout();

    connect(document_, &Document::fileChanged, this, &MainWindow::updateTitle);
    connect(document_, &Document::cleanChanged, this, &MainWindow::updateTitle);
    connect(document_, &Document::changed, this, &MainWindow::updateStatus);
    // Changes inside a macro come while it is open (nothing to undo yet): the index signal follows its end.
    connect(document_, &Document::historyIndexChanged, this, &MainWindow::updateUndoActions);
    connect(document_, &Document::selectionChanged, this, &MainWindow::updateStatus);
    connect(document_, &Document::selectionChanged, this, &MainWindow::updateUndoActions);
    connect(document_, &Document::warningsReported, log_, &LogPanel::warnings);
    connect(autosave_, &Autosave::failed, this, [this](const QString& m) { log_->warning(tr("Autosave failed: %1").arg(m)); });
    connectLoading();
    connect(recoveryBar_, &RecoveryBar::recoverClicked, this, [this] {
        if (const auto leftover = autosave_->leftover()) recover(*leftover);
    });
    connect(recoveryBar_, &RecoveryBar::discardClicked, this, [this] {
        if (const auto leftover = autosave_->leftover()) autosave_->discard(*leftover);
        refreshRecovery();
    });
    connect(recoveryBar_, &RecoveryBar::dismissed, this, [this] { recoveryDismissed_ = true; });
    // "Newer than the file" depends on the file shown.
    connect(document_, &Document::fileChanged, this, [this] {
        if (recoveryBar_->isVisible()) refreshRecovery();
    });
    updateTitle();
    updateStatus();
    updateUndoActions();
}

MainWindow::~MainWindow() {
    // The panels refer to the document: they go first (children die in creation order, and the
    // document was created first).
    qDeleteAll(findChildren<QWidget*>(Qt::FindDirectChildrenOnly));
    delete autosave_;
}

// The viewport (or a placeholder) under the recovery bar, which shows only when there is work to
// recover.
void MainWindow::createCentralView() {
    auto* central = new QWidget(this);
    auto* layout = new QVBoxLayout(central);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    recoveryBar_ = new RecoveryBar(central);
    layout->addWidget(recoveryBar_);
    setCentralWidget(central);
    if (options_.createViewport) {
        createViewport();
        layout->addWidget(viewport_, 1);
        return;
    }
    // No viewport wanted (no OpenGL 4.1, or tests of the panels alone): say so where it would be.
    auto* placeholder = new QLabel(central);
    keepTranslated(placeholder, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("The viewport is not available in this build."));
    placeholder->setAlignment(Qt::AlignCenter);
    keepTranslated(placeholder, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Viewport"));
    layout->addWidget(placeholder, 1);
}

void MainWindow::createViewport() {
    auto* viewport = new Viewport(*document_, centralWidget());
    viewport_ = viewport;
    keepTranslated(viewport, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Viewport"));
    viewportActions_ = viewport->allActions();
    // The gizmo modes answer W/E/R anywhere in the window (text fields keep their letters), with
    // Blender's G (grab) and S (scale) as aliases; Blender's R (rotate) is taken by scale here.
    const std::pair<const char*, QList<QKeySequence>> gizmoKeys[] = {
        {"view.gizmo.move", {QKeySequence(Qt::Key_W), QKeySequence(Qt::Key_G)}},
        {"view.gizmo.rotate", {QKeySequence(Qt::Key_E)}},
        {"view.gizmo.scale", {QKeySequence(Qt::Key_R), QKeySequence(Qt::Key_S)}}};
    for (QAction* action : viewport->gizmoActions()) {
        for (const auto& [id, keys] : gizmoKeys)
            if (action->objectName() == QLatin1String(id)) action->setShortcuts(keys);
        action->setShortcutContext(Qt::WindowShortcut);
        addAction(action);
    }
    // While the view flies (right drag), W/A/S/D/Q/E move the camera: the view keeps its keys.
    viewport->view().installEventFilter(this);
    connect(viewport, &Viewport::statusMessage, this, [this](const QString& text) { renderLabel_->setText(text); });
}

QDockWidget* MainWindow::addDock(QWidget* widget, const char* title, const QString& name, Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(this);
    keepTranslated(dock, TextRole::Title, staticMetaObject.className(), title);
    dock->setObjectName(name); // saveState() keys the layout by object name
    dock->setWidget(widget);
    keepTranslated(widget, TextRole::AccessibleName, staticMetaObject.className(), title);
    addDockWidget(area, dock);
    return dock;
}

void MainWindow::createDocks() {
    outliner_ = new OutlinerPanel(*document_, this);
    properties_ = new PropertiesPanel(*document_, false, this);
    sceneSettings_ = new PropertiesPanel(*document_, true, this);
    history_ = new HistoryPanel(*document_, this);
    log_ = new LogPanel(this);
    auto* outlinerDock = addDock(outliner_, QT_TR_NOOP("Outliner"), "OutlinerDock", Qt::LeftDockWidgetArea);
    auto* historyDock = addDock(history_, QT_TR_NOOP("Undo history"), "HistoryDock", Qt::LeftDockWidgetArea);
    auto* propertiesDock = addDock(properties_, QT_TR_NOOP("Properties"), "PropertiesDock", Qt::RightDockWidgetArea);
    auto* sceneDock = addDock(sceneSettings_, QT_TR_NOOP("Scene"), "SceneDock", Qt::RightDockWidgetArea);
    materials_ = new MaterialsPanel(*document_, this);
    auto* materialsDock = addDock(materials_, QT_TR_NOOP("Materials"), "MaterialsDock", Qt::RightDockWidgetArea);
    auto* logDock = addDock(log_, QT_TR_NOOP("Log"), "LogDock", Qt::BottomDockWidgetArea);
    timeline_ = new TimelinePanel(*document_, this);
    if (viewport_) {
        // New keys take the viewport's pose; a scene without a camera gets one from the view.
        timeline_->setKeySource([this](double t) { return keyFromView(viewport_->view().camera(), t); });
        timeline_->setCameraMaker([this] { return viewport_->makeSceneCamera(); });
    }
    auto* timelineDock = addDock(timeline_, QT_TR_NOOP("Timeline"), "TimelineDock", Qt::BottomDockWidgetArea);
    tabifyDockWidget(logDock, timelineDock);
    timelineDock->raise();
    splitDockWidget(outlinerDock, historyDock, Qt::Vertical);
    if (viewport_) {
        sceneSettings_->setViewportControls({[this] { return preferences_.viewportSamples; },
                                             [this](int samples) {
                                                 preferences_.viewportSamples = samples;
                                                 preferences_.save();
                                                 viewport_->setSampleCap(samples);
                                             },
                                             viewport_->pauseAction()});
    }
    tabifyDockWidget(propertiesDock, sceneDock);
    tabifyDockWidget(propertiesDock, materialsDock);
    propertiesDock->raise();
    for (auto* panel : {static_cast<QObject*>(outliner_), static_cast<QObject*>(properties_),
                        static_cast<QObject*>(sceneSettings_), static_cast<QObject*>(history_), static_cast<QObject*>(materials_)})
        connect(panel, SIGNAL(message(QString)), log_, SLOT(warning(QString)));
}

void MainWindow::restoreLayout() {
    QSettings settings;
    if (!restoreGeometry(settings.value("window/geometry").toByteArray())) fitToScreen();
    if (!restoreState(settings.value("window/state").toByteArray())) fitDocks();
}

// The viewport gets most of the room until the user's own layout is restored: the side docks take
// a share of the window's width and the bottom ones of its height, so a small screen (a laptop at
// 1024x640) still leaves the view more than half of the window.
void MainWindow::fitDocks() {
    auto dock = [this](const char* name) { return findChild<QDockWidget*>(QLatin1String(name)); };
    auto share = [](int whole, double fraction, int least, int most) {
        return std::clamp(int(whole * fraction), least, most);
    };
    resizeDocks({dock("OutlinerDock"), dock("PropertiesDock")},
                {share(width(), 0.17, 160, 260), share(width(), 0.24, 220, 440)}, Qt::Horizontal);
    resizeDocks({dock("LogDock")}, {share(height(), 0.2, 110, 200)}, Qt::Vertical);
}

// The first start: most of the screen, centred (Qt's default is two thirds of it or less).
void MainWindow::fitToScreen() {
    const QScreen* screen = QGuiApplication::primaryScreen();
    if (!screen) return;
    const QRect available = screen->availableGeometry();
    const QSize size = (available.size() * 0.9).expandedTo(minimumSizeHint()).boundedTo(available.size());
    resize(size);
    move(available.center() - QPoint(size.width() / 2, size.height() / 2));
}

void MainWindow::saveLayout() {
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
}

void MainWindow::rememberDefaultShortcuts() {
    for (QAction* action : keymapActions()) {
        Q_ASSERT_X(!action->objectName().isEmpty() && !defaultShortcuts_.contains(action->objectName()),
                   "MainWindow", "every keymap action needs an object name of its own");
        defaultShortcuts_[action->objectName()] = action->shortcuts();
    }
}

void MainWindow::applyPreferences() {
    if (auto* app = qobject_cast<QApplication*>(QCoreApplication::instance()))
        applyTheme(*app, themeFromName(preferences_.theme), options_.systemPalette);
    autosave_->setIntervalMinutes(preferences_.autosaveMinutes);
    if (viewport_) viewport_->setSampleCap(preferences_.viewportSamples);
    if (sceneSettings_) sceneSettings_->refresh(); // its Viewport samples field shows the preference
    // An override replaces the action's shortcuts; without one the defaults (aliases too) apply.
    for (QAction* action : keymapActions()) {
        auto it = preferences_.keymap.find(action->objectName());
        if (it != preferences_.keymap.end()) action->setShortcut(it.value());
        else action->setShortcuts(defaultShortcuts_.value(action->objectName()));
    }
}

void MainWindow::updateTitle() {
    // "[*]" is where Qt puts the modified marker; the file name follows the scene name.
    QString title = document_->displayName() + QStringLiteral("[*]");
    if (!document_->filePath().isEmpty()) title += QStringLiteral(" (%1)").arg(QFileInfo(document_->filePath()).fileName());
    setWindowTitle(title + QStringLiteral(" - Glint"));
    setWindowModified(document_->isModified());
}

void MainWindow::updateStatus() {
    const Scene& scene = document_->scene();
    std::size_t triangles = 0;
    for (const auto& [id, mesh] : scene.meshes) triangles += mesh.triangleCount();
    const std::size_t selected = document_->selection().size();
    if (selected == 0) selectionLabel_->setText(tr("Nothing selected"));
    else if (selected == 1) selectionLabel_->setText(tr("Selected: %1").arg(nodeDisplayName(scene, document_->currentNode())));
    else selectionLabel_->setText(tr("%n nodes selected", nullptr, static_cast<int>(selected)));
    sceneLabel_->setText(tr("%1, %2, configuration: %3")
                             .arg(countText(staticMetaObject.className(), QT_TR_N_NOOP("%n nodes"), "%n node",
                                            static_cast<int>(scene.nodeCount())),
                                  countText(staticMetaObject.className(), QT_TR_N_NOOP("%n triangles"), "%n triangle",
                                            static_cast<int>(triangles)),
                                  configurationTitle(scene.settings.render.configuration)));
}

void MainWindow::createStatusBar() {
    selectionLabel_ = new QLabel(this);
    sceneLabel_ = new QLabel(this);
    renderLabel_ = new QLabel(this);
    keepTranslated(selectionLabel_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Selection"));
    keepTranslated(sceneLabel_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Scene statistics"));
    keepTranslated(renderLabel_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Render progress"));
    statusBar()->addWidget(selectionLabel_);
    statusBar()->addWidget(sceneLabel_);
    statusBar()->addPermanentWidget(renderLabel_);
    loadProgress_ = new LoadProgress(this);
    statusBar()->addPermanentWidget(loadProgress_);
}

void MainWindow::report(const QString& message) {
    log_->error(message);
    statusBar()->showMessage(message, 8000);
}

void MainWindow::newFromTemplate(SceneTemplate kind) {
    if (!maybeSave()) return;
    try {
        document_->newScene(buildTemplate(kind));
    } catch (const std::exception& e) {
        QMessageBox::warning(this, tr("New scene"), QString::fromStdString(e.what()));
    }
}

bool MainWindow::maybeSave() {
    if (!document_->isModified()) return true;
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved changes"), tr("\"%1\" has unsaved changes. Save them first?").arg(document_->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel) return false;
    if (answer == QMessageBox::Save) return save();
    return true;
}

bool MainWindow::save() {
    if (document_->filePath().isEmpty()) return saveAs();
    const QString error = document_->save();
    if (!error.isEmpty()) {
        report(tr("Cannot save: %1").arg(error));
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(document_->filePath()), 4000);
    return true;
}

bool MainWindow::saveAs(const QString& path) {
    QString target = path;
    if (target.isEmpty())
        target = QFileDialog::getSaveFileName(this, tr("Save scene"), document_->filePath(),
                                              tr("glTF scenes (*.gltf *.glb)"));
    if (target.isEmpty()) return false;
    const QString error = document_->saveAs(target);
    if (!error.isEmpty()) {
        report(tr("Cannot save %1: %2").arg(target, error));
        return false;
    }
    RecentFiles().add(document_->filePath());
    rebuildRecentMenu();
    statusBar()->showMessage(tr("Saved %1").arg(document_->filePath()), 4000);
    return true;
}

bool MainWindow::offerRecovery() {
    recoveryDismissed_ = false;
    refreshRecovery();
    if (options_.askBeforeRecovery) return false;
    const auto leftover = autosave_->leftover();
    return leftover && recover(*leftover);
}

bool MainWindow::recover(const Autosave::Leftover& leftover) {
    if (!maybeSave()) return false;
    recovering_ = leftover;
    document_->startRecover(leftover.copy, leftover.original);
    return true;
}

namespace {

QString leftoverName(const Autosave::Leftover& leftover) {
    return leftover.original.isEmpty() ? MainWindow::tr("an untitled scene") : QFileInfo(leftover.original).fileName();
}

} // namespace

// The bar shows the newest copy; File > Recover lists them all. Both follow what is left over now.
void MainWindow::refreshRecovery() {
    const QList<Autosave::Leftover> leftovers = autosave_->leftovers();
    recoverMenu_->clear();
    for (const Autosave::Leftover& leftover : leftovers) {
        const QString when = QLocale().toString(leftover.saved, QLocale::ShortFormat);
        const QString title = leftover.superseded ? tr("%1 (autosaved %2, older than the file)") : tr("%1 (autosaved %2)");
        QAction* action = recoverMenu_->addAction(title.arg(leftoverName(leftover), when), this, [this, leftover] { recover(leftover); });
        action->setToolTip(leftover.original);
    }
    if (!leftovers.isEmpty()) {
        recoverMenu_->addSeparator();
        recoverMenu_->addAction(tr("Discard all autosaved copies"), this, [this] {
            for (const Autosave::Leftover& leftover : autosave_->leftovers()) autosave_->discard(leftover);
            refreshRecovery();
        });
    } else {
        recoverMenu_->addAction(tr("Nothing to recover"))->setEnabled(false);
    }
    const std::optional<Autosave::Leftover> pending = autosave_->leftover(); // the bar offers no superseded copy
    if (!pending || recoveryDismissed_ || recovering_) {
        recoveryBar_->hide();
        return;
    }
    const Autosave::Leftover& newest = *pending;
    const QString when = QLocale().toString(newest.saved, QLocale::ShortFormat);
    const bool thisFile = !newest.original.isEmpty() && QFileInfo(newest.original) == QFileInfo(document_->filePath());
    QString text = thisFile ? tr("Glint did not close normally: the copy of %1 autosaved at %2 is newer than the file.").arg(leftoverName(newest), when)
                            : tr("Glint did not close normally: unsaved work on %1 was autosaved at %2.").arg(leftoverName(newest), when);
    if (leftovers.size() > 1)
        text += QLatin1Char(' ') + countText(staticMetaObject.className(), QT_TR_N_NOOP("%n more in File > Recover."),
                                             "%n more in File > Recover.", static_cast<int>(leftovers.size()) - 1);
    recoveryBar_->setText(text);
    recoveryBar_->show();
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    saveLayout();
    document_->cancelLoading(); // an import's child is killed; nothing arrives after the window
    autosave_->discard(); // a normal exit: nothing to recover next time
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls() || event->mimeData()->hasFormat(kMaterialMimeType)) event->acceptProposedAction();
}

// Materials from the Materials panel land on the node under the cursor in the viewport.
NodeId MainWindow::materialDropTarget(QPoint windowPos) {
    if (!viewport_) return {};
    RenderView& view = viewport_->view();
    const QPoint at = view.mapFrom(this, windowPos);
    if (!view.rect().contains(at)) return {};
    const NodeId node = view.pickAt(QPointF(at));
    return takesMaterial(document_->scene(), node) ? node : NodeId{};
}

void MainWindow::dragMoveEvent(QDragMoveEvent* event) {
    if (!event->mimeData()->hasFormat(kMaterialMimeType)) {
        if (event->mimeData()->hasUrls()) event->acceptProposedAction();
        return;
    }
    if (materialDropTarget(event->position().toPoint())) event->acceptProposedAction();
    else event->ignore();
}

void MainWindow::dropEvent(QDropEvent* event) {
    if (event->mimeData()->hasFormat(kMaterialMimeType)) {
        const std::vector<MaterialId> materials = decodeMaterials(event->mimeData());
        const NodeId node = materialDropTarget(event->position().toPoint());
        if (materials.empty() || !node) return event->ignore();
        const QString error = assignMaterial(*document_, materials.front(), {node});
        if (!error.isEmpty()) log_->warning(error);
        event->acceptProposedAction();
        return;
    }
    // Ctrl held while dropping merges the files into the open scene.
    openDropped(event->mimeData()->urls(), event->modifiers().testFlag(Qt::ControlModifier));
    event->acceptProposedAction();
}

void MainWindow::openDropped(const QList<QUrl>& urls, bool merge) {
    for (const QUrl& url : urls) {
        if (!url.isLocalFile()) continue;
        const QString path = url.toLocalFile();
        const QString lower = path.toLower();
        const bool native = lower.endsWith(".gltf") || lower.endsWith(".glb") || lower.endsWith(".glint.json");
        if (native && !merge) {
            if (maybeSave()) beginOpen(path);
        } else {
            beginImport(path); // after an open of the same drop: merged into the opened scene
        }
    }
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride && viewport_ && watched == &viewport_->view() &&
        viewport_->view().tools().tool() == Tool::Fly) {
        event->accept(); // the key goes to the view, not to a shortcut
        return true;
    }
    return QMainWindow::eventFilter(watched, event);
}

void MainWindow::changeEvent(QEvent* event) {
    QMainWindow::changeEvent(event);
    if (event->type() == QEvent::LanguageChange) retranslate();
}

// Every widget gets the LanguageChange too: panels that build texts from data rebuild themselves;
// here the kept texts of the whole window (menus, actions, docks, tool bars, the viewport's and
// open dialogs') and the window's own texts built from data.
void MainWindow::retranslate() {
    retranslateTree(this);
    updateTitle();
    updateStatus();
    updateUndoActions();
    rebuildRecentMenu();
    refreshRecovery();
}

} // namespace glint::editor
