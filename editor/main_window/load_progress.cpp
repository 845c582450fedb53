#include "load_progress.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QToolButton>

namespace glint::editor {

LoadProgress::LoadProgress(QWidget* parent) : QWidget(parent) {
    setObjectName("LoadProgress");
    label_ = new QLabel(this);
    bar_ = new QProgressBar(this);
    bar_->setRange(0, 0); // busy: neither the glTF reader nor the importer says how far it is
    bar_->setMaximumWidth(120);
    bar_->setMaximumHeight(14);
    bar_->setTextVisible(false);
    cancel_ = new QToolButton(this);
    cancel_->setObjectName("LoadProgress.cancel");
    cancel_->setAutoRaise(true);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(label_);
    layout->addWidget(bar_);
    layout->addWidget(cancel_);
    connect(cancel_, &QToolButton::clicked, this, &LoadProgress::cancelRequested);
    clock_.setInterval(1000);
    connect(&clock_, &QTimer::timeout, this, &LoadProgress::showText);
    retranslate();
    hide();
}

void LoadProgress::begin(const QString& text) {
    text_ = text;
    stage_.clear();
    elapsed_.start();
    clock_.start();
    showText();
    show();
}

void LoadProgress::setStage(const QString& stage) {
    stage_ = stage;
    showText();
}

void LoadProgress::end() {
    text_.clear();
    stage_.clear();
    clock_.stop();
    hide();
}

void LoadProgress::showText() {
    QString text = stage_.isEmpty() ? text_ : tr("%1 (%2)").arg(text_, stage_);
    const qint64 seconds = elapsed_.isValid() ? elapsed_.elapsed() / 1000 : 0;
    if (seconds > 0) text = tr("%1, %2 s").arg(text).arg(seconds);
    label_->setText(text);
}

QString LoadProgress::text() const { return label_->text(); }

void LoadProgress::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange) retranslate();
}

void LoadProgress::retranslate() {
    cancel_->setText(tr("Cancel"));
    cancel_->setToolTip(tr("Stop reading the file; the open scene stays as it is"));
    bar_->setAccessibleName(tr("Loading progress"));
    if (!text_.isEmpty()) showText();
}

} // namespace glint::editor
