#pragma once
// The warnings/log panel: every loader, importer, save and renderer warning the editor sees is
// listed here with its time and level, so nothing a file or the GPU reports is lost silently.
#include <QWidget>

class QListWidget;

namespace glint::editor {

class LogPanel : public QWidget {
    Q_OBJECT
public:
    enum class Level { Info, Warning, Error };

    explicit LogPanel(QWidget* parent = nullptr);

    int count() const;
    QString line(int row) const;

public slots:
    void append(glint::editor::LogPanel::Level level, const QString& text);
    void info(const QString& text) { append(Level::Info, text); }
    void warning(const QString& text) { append(Level::Warning, text); }
    void error(const QString& text) { append(Level::Error, text); }
    void warnings(const QStringList& lines);
    void clear();

signals:
    // Emitted for warnings and errors, so the main window can flag them in the status bar.
    void problemLogged(const QString& text);

private:
    QListWidget* list_ = nullptr;
};

} // namespace glint::editor
