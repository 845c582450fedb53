#pragma once
// The Materials dock: every material of the scene with its path-traced swatch and users count, a
// search box, and New (from presets), Duplicate, Rename, Delete unused and Assign to selection,
// each one undoable step. Materials drag out of the list onto nodes in the outliner (and the
// viewport) to assign them.
#include "scene/core/ids.h"

#include <QWidget>

class QLineEdit;
class QListView;
class QMenu;
class QSortFilterProxyModel;
class QToolButton;

namespace glint::editor {

class Document;
class MaterialListModel;
class SwatchRenderer;

class MaterialsPanel : public QWidget {
    Q_OBJECT
public:
    // `renderSwatches` false: no path tracer (tests of the panel alone on the offscreen platform).
    explicit MaterialsPanel(Document& document, QWidget* parent = nullptr, bool renderSwatches = true);
    ~MaterialsPanel() override;

    MaterialListModel& model() { return *model_; }
    QListView& view() { return *view_; }
    QLineEdit& search() { return *search_; }
    SwatchRenderer* swatches() { return swatches_; }
    QMenu* newMenu() const { return newMenu_; }

    // The material selected in the list (none when nothing is).
    MaterialId currentMaterial() const;
    void selectMaterial(MaterialId id);

    // The buttons' actions, for menus and tests. Each reports failures through message().
    void createFromPreset(const QString& presetId);
    void duplicateCurrent();
    void renameCurrent(); // starts editing the name in the list
    void deleteUnused();
    void assignToSelection();

signals:
    void message(const QString& text);

private:
    void updateButtons();

    Document& document_;
    SwatchRenderer* swatches_ = nullptr;
    MaterialListModel* model_ = nullptr;
    QSortFilterProxyModel* proxy_ = nullptr;
    QListView* view_ = nullptr;
    QLineEdit* search_ = nullptr;
    QMenu* newMenu_ = nullptr;
    QToolButton* duplicate_ = nullptr;
    QToolButton* rename_ = nullptr;
    QToolButton* deleteUnused_ = nullptr;
    QToolButton* assign_ = nullptr;
};

} // namespace glint::editor
