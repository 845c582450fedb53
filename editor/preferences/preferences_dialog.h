#pragma once
// Preferences: appearance (theme), language, autosave interval, the viewport's sample cap and the
// keymap (one shortcut per action, conflicts refused). The keymap stores only what differs from
// the defaults, so an action left alone keeps its default shortcuts (aliases included).
#include "preferences.h"

#include <QDialog>
#include <QKeySequence>
#include <QList>
#include <QMap>

class QAction;
class QComboBox;
class QSpinBox;
class QTableWidget;

namespace glint::editor {

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    // `defaults`: each action's default shortcuts by object name (the first is the one edited).
    PreferencesDialog(const Preferences& current, const QList<QAction*>& actions,
                      const QMap<QString, QList<QKeySequence>>& defaults, QWidget* parent = nullptr);

    Preferences result() const;

private:
    QWidget* makeGeneralPage();
    QWidget* makeKeymapPage();
    QKeySequence editedShortcut(int row) const;
    // The shortcuts a row would have: its defaults (aliases too) while the first is kept.
    QList<QKeySequence> effectiveShortcuts(int row) const;
    bool checkConflicts();
    void resetKeymap();
    void accept() override;

    Preferences initial_;
    QList<QAction*> actions_;
    QMap<QString, QList<QKeySequence>> defaults_;
    QComboBox* theme_ = nullptr;
    QComboBox* language_ = nullptr;
    QSpinBox* autosave_ = nullptr;
    QSpinBox* viewportSamples_ = nullptr;
    QTableWidget* keymap_ = nullptr;
};

// The name the keymap lists an action under: its own text without mnemonics, never what it says
// at the moment (the Undo action's menu text names the step it would undo).
QString keymapName(const QAction* action);

} // namespace glint::editor
