#pragma once
// Preferences: appearance (theme), language, autosave interval and the keymap (one shortcut
// per action, conflicts refused).
#include "preferences.h"

#include <QDialog>
#include <QList>

class QAction;
class QComboBox;
class QSpinBox;
class QTableWidget;

namespace glint::editor {

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    PreferencesDialog(const Preferences& current, const QList<QAction*>& actions, QWidget* parent = nullptr);

    Preferences result() const;

private:
    QWidget* makeGeneralPage();
    QWidget* makeKeymapPage();
    bool checkConflicts();
    void accept() override;

    Preferences initial_;
    QList<QAction*> actions_;
    QComboBox* theme_ = nullptr;
    QComboBox* language_ = nullptr;
    QSpinBox* autosave_ = nullptr;
    QSpinBox* viewportSamples_ = nullptr;
    QTableWidget* keymap_ = nullptr;
};

} // namespace glint::editor
