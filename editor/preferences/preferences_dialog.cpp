#include "preferences_dialog.h"

#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QKeySequenceEdit>
#include <QLabel>
#include <QMessageBox>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

namespace glint::editor {

PreferencesDialog::PreferencesDialog(const Preferences& current, const QList<QAction*>& actions, QWidget* parent)
    : QDialog(parent), initial_(current), actions_(actions) {
    setWindowTitle(tr("Preferences"));
    auto* tabs = new QTabWidget(this);
    tabs->addTab(makeGeneralPage(), tr("General"));
    tabs->addTab(makeKeymapPage(), tr("Keymap"));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &PreferencesDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(tabs);
    layout->addWidget(buttons);
    resize(560, 480);
}

QWidget* PreferencesDialog::makeGeneralPage() {
    auto* page = new QWidget(this);
    auto* form = new QFormLayout(page);
    theme_ = new QComboBox(page);
    theme_->addItem(tr("System"), "system");
    theme_->addItem(tr("Light"), "light");
    theme_->addItem(tr("Dark"), "dark");
    theme_->setCurrentIndex(std::max(0, theme_->findData(initial_.theme)));
    theme_->setAccessibleName(tr("Theme"));
    form->addRow(tr("Theme"), theme_);

    language_ = new QComboBox(page);
    for (const auto& [code, name] : availableLanguages()) language_->addItem(name, code);
    language_->setCurrentIndex(std::max(0, language_->findData(initial_.language)));
    language_->setAccessibleName(tr("Language"));
    form->addRow(tr("Language"), language_);

    autosave_ = new QSpinBox(page);
    autosave_->setRange(0, 120);
    autosave_->setSuffix(tr(" min"));
    autosave_->setSpecialValueText(tr("Off"));
    autosave_->setValue(initial_.autosaveMinutes);
    autosave_->setAccessibleName(tr("Autosave interval"));
    form->addRow(tr("Autosave every"), autosave_);

    viewportSamples_ = new QSpinBox(page);
    viewportSamples_->setRange(0, 1 << 20);
    viewportSamples_->setSpecialValueText(tr("No limit"));
    viewportSamples_->setValue(initial_.viewportSamples);
    viewportSamples_->setAccessibleName(tr("Viewport samples"));
    viewportSamples_->setToolTip(tr("The viewport stops adding samples per pixel here (renders use the Scene panel's samples)"));
    form->addRow(tr("Viewport samples"), viewportSamples_);
    return page;
}

QWidget* PreferencesDialog::makeKeymapPage() {
    keymap_ = new QTableWidget(static_cast<int>(actions_.size()), 2, this);
    keymap_->setHorizontalHeaderLabels({tr("Command"), tr("Shortcut")});
    keymap_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    keymap_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    keymap_->verticalHeader()->hide();
    keymap_->setAccessibleName(tr("Keymap"));
    for (int row = 0; row < actions_.size(); ++row) {
        QAction* action = actions_[row];
        auto* name = new QTableWidgetItem(action->text().remove('&'));
        name->setFlags(Qt::ItemIsEnabled);
        keymap_->setItem(row, 0, name);
        auto* edit = new QKeySequenceEdit(action->shortcut(), keymap_);
        edit->setAccessibleName(tr("Shortcut for %1").arg(name->text()));
        keymap_->setCellWidget(row, 1, edit);
    }
    return keymap_;
}

bool PreferencesDialog::checkConflicts() {
    QMap<QKeySequence, QString> used;
    for (int row = 0; row < actions_.size(); ++row) {
        const QKeySequence seq = static_cast<QKeySequenceEdit*>(keymap_->cellWidget(row, 1))->keySequence();
        if (seq.isEmpty()) continue;
        const QString name = keymap_->item(row, 0)->text();
        if (used.contains(seq)) {
            QMessageBox::warning(this, tr("Shortcut conflict"),
                                 tr("%1 is used by both \"%2\" and \"%3\".")
                                     .arg(seq.toString(QKeySequence::NativeText), used[seq], name));
            return false;
        }
        used[seq] = name;
    }
    return true;
}

void PreferencesDialog::accept() {
    if (!checkConflicts()) return;
    QDialog::accept();
}

Preferences PreferencesDialog::result() const {
    Preferences p = initial_;
    p.theme = theme_->currentData().toString();
    p.language = language_->currentData().toString();
    p.autosaveMinutes = autosave_->value();
    p.viewportSamples = viewportSamples_->value();
    p.keymap.clear();
    for (int row = 0; row < actions_.size(); ++row) {
        const QKeySequence seq = static_cast<QKeySequenceEdit*>(keymap_->cellWidget(row, 1))->keySequence();
        p.keymap[actions_[row]->objectName()] = seq;
    }
    return p;
}

} // namespace glint::editor
