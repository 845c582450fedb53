#pragma once
// The status bar's progress for a file being opened or imported in the background: what is being
// read, a busy bar (the readers report stages, not fractions) and a Cancel button. Non-modal, as
// in Qt Creator or Blender: the window stays usable while it shows.
#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

class QLabel;
class QProgressBar;
class QToolButton;

namespace glint::editor {

class LoadProgress : public QWidget {
    Q_OBJECT
public:
    explicit LoadProgress(QWidget* parent = nullptr);

    void begin(const QString& text); // shows the widget
    void setStage(const QString& stage);
    void end();                       // hides it
    QString text() const;

signals:
    void cancelRequested();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void showText();

    QLabel* label_ = nullptr;
    QProgressBar* bar_ = nullptr;
    QToolButton* cancel_ = nullptr;
    QString text_;
    QString stage_;
    QElapsedTimer elapsed_;
    QTimer clock_; // the seconds so far, once a load takes longer than a moment
};

} // namespace glint::editor
