#pragma once
// The undo history dock: the command labels of the document's History; clicking a row jumps
// there (undoing or redoing every step in between).
#include <QWidget>

class QListView;

namespace glint::editor {

class Document;
class HistoryModel;

class HistoryPanel : public QWidget {
    Q_OBJECT
public:
    explicit HistoryPanel(Document& document, QWidget* parent = nullptr);

    HistoryModel& model() { return *model_; }
    QListView& view() { return *view_; }

signals:
    void message(const QString& text);

protected:
    void changeEvent(QEvent* event) override;

private:
    void selectCurrent();

    Document& document_;
    HistoryModel* model_ = nullptr;
    QListView* view_ = nullptr;
};

} // namespace glint::editor
