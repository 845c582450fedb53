#pragma once
// The outliner dock: a filter box, an "Add" menu and the tree of nodes. Its selection and the
// document's selection follow each other both ways.
#include <QWidget>

class QLineEdit;
class QMenu;
class QSortFilterProxyModel;
class QTreeView;

namespace glint::editor {

class Document;
class OutlinerModel;

class OutlinerPanel : public QWidget {
    Q_OBJECT
public:
    explicit OutlinerPanel(Document& document, QWidget* parent = nullptr);

    OutlinerModel& model() { return *model_; }
    QTreeView& view() { return *view_; }
    QLineEdit& filter() { return *filter_; }
    // The menu of shapes, lights and cameras to add; the main window shows it too.
    QMenu* addMenu() const { return addMenu_; }

signals:
    void message(const QString& text);

protected:
    void changeEvent(QEvent* event) override;

private:
    void buildAddMenu();
    void syncFromDocument();
    void syncToDocument();
    void showContextMenu(const QPoint& pos);

    Document& document_;
    OutlinerModel* model_ = nullptr;
    QSortFilterProxyModel* proxy_ = nullptr;
    QTreeView* view_ = nullptr;
    QLineEdit* filter_ = nullptr;
    QMenu* addMenu_ = nullptr;
    bool syncing_ = false;
};

} // namespace glint::editor
