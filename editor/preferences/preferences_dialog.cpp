#include "preferences_dialog.h"

#include "retranslate.h"

#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QKeySequenceEdit>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

namespace glint::editor {

PreferencesDialog::PreferencesDialog(const Preferences& current, const QList<QAction*>& actions,
                                     const QMap<QString, QList<QKeySequence>>& defaults, QWidget* parent)
    : QDialog(parent), initial_(current), actions_(actions), defaults_(defaults) {
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
    resize(680, 520);
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

QString keymapName(const QAction* action) {
    QString name = keptText(action, TextRole::Text);
    if (name.isEmpty()) name = action->text();
    return name.remove('&');
}

namespace {

QString shortcutsText(const QList<QKeySequence>& keys) {
    QStringList texts;
    for (const QKeySequence& key : keys)
        if (!key.isEmpty()) texts << key.toString(QKeySequence::NativeText);
    return texts.join(QStringLiteral(", "));
}

} // namespace

QWidget* PreferencesDialog::makeKeymapPage() {
    auto* page = new QWidget(this);
    keymap_ = new QTableWidget(static_cast<int>(actions_.size()), 3, page);
    keymap_->setHorizontalHeaderLabels({tr("Command"), tr("Shortcut"), tr("Default")});
    keymap_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    keymap_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    keymap_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    keymap_->verticalHeader()->hide();
    keymap_->setAccessibleName(tr("Keymap"));
    for (int row = 0; row < actions_.size(); ++row) {
        QAction* action = actions_[row];
        auto* name = new QTableWidgetItem(keymapName(action));
        name->setFlags(Qt::ItemIsEnabled);
        keymap_->setItem(row, 0, name);
        auto* edit = new QKeySequenceEdit(action->shortcut(), keymap_);
        edit->setClearButtonEnabled(true);
        edit->setAccessibleName(tr("Shortcut for %1").arg(name->text()));
        keymap_->setCellWidget(row, 1, edit);
        auto* fallback = new QTableWidgetItem(shortcutsText(defaults_.value(action->objectName())));
        fallback->setFlags(Qt::ItemIsEnabled);
        keymap_->setItem(row, 2, fallback);
    }
    auto* reset = new QPushButton(tr("Reset all to defaults"), page);
    connect(reset, &QPushButton::clicked, this, &PreferencesDialog::resetKeymap);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(keymap_);
    layout->addWidget(reset, 0, Qt::AlignRight);
    return page;
}

QKeySequence PreferencesDialog::editedShortcut(int row) const {
    return static_cast<QKeySequenceEdit*>(keymap_->cellWidget(row, 1))->keySequence();
}

QList<QKeySequence> PreferencesDialog::effectiveShortcuts(int row) const {
    const QKeySequence edited = editedShortcut(row);
    const QList<QKeySequence> defaults = defaults_.value(actions_[row]->objectName());
    if (edited == defaults.value(0)) return defaults;
    return {edited};
}

void PreferencesDialog::resetKeymap() {
    for (int row = 0; row < actions_.size(); ++row)
        static_cast<QKeySequenceEdit*>(keymap_->cellWidget(row, 1))
            ->setKeySequence(defaults_.value(actions_[row]->objectName()).value(0));
}

bool PreferencesDialog::checkConflicts() {
    QMap<QKeySequence, QString> used;
    for (int row = 0; row < actions_.size(); ++row) {
        const QString name = keymap_->item(row, 0)->text();
        for (const QKeySequence& seq : effectiveShortcuts(row)) {
            if (seq.isEmpty()) continue;
            if (used.contains(seq)) {
                QMessageBox::warning(this, tr("Shortcut conflict"),
                                     tr("%1 is used by both \"%2\" and \"%3\".")
                                         .arg(seq.toString(QKeySequence::NativeText), used[seq], name));
                return false;
            }
            used[seq] = name;
        }
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
        const QString id = actions_[row]->objectName();
        if (id.isEmpty()) continue; // no stable name: nothing to store it under
        const QKeySequence seq = editedShortcut(row);
        if (seq != defaults_.value(id).value(0)) p.keymap[id] = seq; // an empty one too: the user cleared it
    }
    return p;
}

} // namespace glint::editor
