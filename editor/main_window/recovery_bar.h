#pragma once
// The bar over the viewport that offers work an earlier session left unsaved (it crashed or was
// killed): the file asked for opens as usual and the recovery waits beside it, never in a modal
// dialog. The main window fills in the text; File > Recover lists every copy.
#include <QFrame>

class QLabel;
class QPushButton;

namespace glint::editor {

class RecoveryBar : public QFrame {
    Q_OBJECT
public:
    explicit RecoveryBar(QWidget* parent = nullptr);

    void setText(const QString& text);
    QString text() const;
    QPushButton* recoverButton() const { return recover_; }
    QPushButton* discardButton() const { return discard_; }

signals:
    void recoverClicked();
    void discardClicked();
    void dismissed(); // "Later": hidden until there is something new to offer

private:
    QLabel* label_ = nullptr;
    QPushButton* recover_ = nullptr;
    QPushButton* discard_ = nullptr;
};

} // namespace glint::editor
