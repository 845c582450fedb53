#pragma once
// One line per field (Tungsten's PropertyForm::addFloatProperty): a label, an editor, a getter
// that reads the document and a setter that pushes a command. refresh() re-reads every getter,
// so undo and redo show up in every panel. A slider drag takes one History interaction serial,
// so the whole drag merges into one undo step.
#include <QColor>

#include <glm/vec3.hpp>
#include <QWidget>

#include <cstdint>
#include <functional>
#include <vector>

class QComboBox;
class QFormLayout;
class QLineEdit;
class QSlider;
class QDoubleSpinBox;
class QPushButton;
class QSpinBox;

namespace glint::editor {

class Document;

// A float edited with a slider and a spin box side by side.
class FloatField : public QWidget {
    Q_OBJECT
public:
    FloatField(double min, double max, int decimals, QWidget* parent = nullptr);
    void setValue(double value); // from the document: emits nothing
    double value() const;
    QSlider* slider() const { return slider_; }
    QDoubleSpinBox* spinBox() const { return spin_; }

signals:
    void dragStarted();
    void edited(double value); // while dragging and after typing
    void dragFinished();

private:
    int toSlider(double value) const;
    double fromSlider(int position) const;

    QSlider* slider_ = nullptr;
    QDoubleSpinBox* spin_ = nullptr;
    double min_;
    double max_;
    bool updating_ = false;
};

// A colour swatch; clicking opens a colour dialog. The swatch and the dialog show and take sRGB,
// as every colour picker does; the document stores linear RGB (toQColor/toLinear convert).
class ColorField : public QWidget {
    Q_OBJECT
public:
    explicit ColorField(QWidget* parent = nullptr);
    void setColor(const QColor& color);
    QColor color() const { return color_; }

signals:
    void edited(const QColor& color);

private:
    void pick();
    QPushButton* button_ = nullptr;
    QColor color_;
};

class PropertyForm : public QWidget {
    Q_OBJECT
public:
    // `interaction` is the drag's serial, or 0 for a one-off edit.
    using FloatSetter = std::function<void(double value, std::uint64_t interaction)>;

    PropertyForm(Document& document, const QString& title, QWidget* parent = nullptr);

    FloatField* addFloat(const QString& label, double min, double max, int decimals, std::function<double()> get,
                         FloatSetter set);
    ColorField* addColor(const QString& label, std::function<QColor()> get, std::function<void(const QColor&)> set);
    void addCheck(const QString& label, std::function<bool()> get, std::function<void(bool)> set);
    void addChoice(const QString& label, const QStringList& items, std::function<int()> get, std::function<void(int)> set);
    QLineEdit* addText(const QString& label, std::function<QString()> get, std::function<void(const QString&)> set);
    QSpinBox* addInt(const QString& label, int min, int max, std::function<int()> get, std::function<void(int)> set);
    void addWidget(const QString& label, QWidget* widget, std::function<void()> refresh);
    // A sentence across the form's width: what a field-less thing is (the infinite ground plane).
    void addNote(const QString& text);

    void refresh();

protected:
    // Ctrl+Z / Ctrl+Shift+Z in a field whose text is committed (after Enter) undo the document, as
    // anywhere else in the window; while the user is typing they undo the typing.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    Document& document_;
    QFormLayout* layout_ = nullptr;
    std::vector<std::function<void()>> refreshers_;
};

// glTF's colour factors, lights and the environment colour are linear RGB; a swatch shows them
// sRGB-encoded, so the colour picked is the colour seen: #CC2222 is stored as (0.604, 0.016, 0.016).
QColor toQColor(float r, float g, float b); // linear in [0, 1] (clamped) -> the sRGB colour shown
glm::vec3 toLinear(const QColor& color);     // the sRGB colour picked -> linear
// A combo box for the forms, which wrap to the dock's width: it does not widen itself to its longest
// entry (a texture's or a material's name), which would push every field of the form out of view.
QComboBox* newFormComboBox(QWidget* parent);

float srgbToLinear(float encoded);
float linearToSrgb(float linear);

} // namespace glint::editor
