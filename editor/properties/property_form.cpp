#include "property_form.h"

#include "editor/document/document.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QCoreApplication>
#include <QGroupBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QKeyEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace glint::editor {
namespace {
constexpr int kSliderSteps = 1000;
}

QComboBox* newFormComboBox(QWidget* parent) {
    auto* combo = new QComboBox(parent);
    combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    combo->setMinimumContentsLength(8);
    return combo;
}

float srgbToLinear(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float linear) {
    linear = std::clamp(linear, 0.0f, 1.0f);
    return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

QColor toQColor(float r, float g, float b) {
    return QColor::fromRgbF(linearToSrgb(r), linearToSrgb(g), linearToSrgb(b));
}

glm::vec3 toLinear(const QColor& color) {
    return {srgbToLinear(float(color.redF())), srgbToLinear(float(color.greenF())), srgbToLinear(float(color.blueF()))};
}

FloatField::FloatField(double min, double max, int decimals, QWidget* parent)
    : QWidget(parent), min_(min), max_(max) {
    slider_ = new QSlider(Qt::Horizontal, this);
    slider_->setRange(0, kSliderSteps);
    spin_ = new QDoubleSpinBox(this);
    spin_->setDecimals(decimals);
    spin_->setRange(-1e9, 1e9); // typing may go past the slider's range
    spin_->setSingleStep((max - min) / 100.0);
    spin_->setKeyboardTracking(false);
    // The spin box is as wide as the numbers the slider spans need (its range, which typing may
    // exceed, would make it hundreds of pixels wide and crush the slider into a stub); the slider
    // takes the rest of the row.
    QDoubleSpinBox widest;
    widest.setDecimals(decimals);
    widest.setRange(-std::max(std::abs(min), std::abs(max)) * 10.0, std::max(std::abs(min), std::abs(max)) * 10.0);
    spin_->setMinimumWidth(widest.sizeHint().width());
    spin_->setMaximumWidth(widest.sizeHint().width() + 24);
    spin_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    slider_->setMinimumWidth(80); // narrower, the form puts the field under its label
    slider_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(slider_, 1);
    layout->addWidget(spin_, 0);

    connect(slider_, &QSlider::sliderPressed, this, &FloatField::dragStarted);
    connect(slider_, &QSlider::sliderReleased, this, &FloatField::dragFinished);
    connect(slider_, &QSlider::valueChanged, this, [this](int position) {
        if (updating_) return;
        const double v = fromSlider(position);
        {
            QSignalBlocker block(spin_);
            spin_->setValue(v);
        }
        emit edited(v);
    });
    connect(spin_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (updating_) return;
        {
            QSignalBlocker block(slider_);
            slider_->setValue(toSlider(v));
        }
        emit edited(v);
    });
}

int FloatField::toSlider(double value) const {
    const double t = (value - min_) / (max_ - min_);
    return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * kSliderSteps));
}

double FloatField::fromSlider(int position) const { return min_ + (max_ - min_) * position / kSliderSteps; }

void FloatField::setValue(double value) {
    updating_ = true;
    if (!slider_->isSliderDown()) slider_->setValue(toSlider(value));
    spin_->setValue(value);
    updating_ = false;
}

double FloatField::value() const { return spin_->value(); }

ColorField::ColorField(QWidget* parent) : QWidget(parent) {
    button_ = new QPushButton(this);
    button_->setMinimumWidth(60);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(button_);
    layout->addStretch();
    connect(button_, &QPushButton::clicked, this, &ColorField::pick);
}

void ColorField::setColor(const QColor& color) {
    color_ = color;
    button_->setStyleSheet(QStringLiteral("background-color: %1").arg(color.name()));
    const glm::vec3 linear = toLinear(color);
    button_->setToolTip(tr("%1 (sRGB); stored linear: %2, %3, %4")
                            .arg(color.name().toUpper())
                            .arg(double(linear.x), 0, 'f', 3)
                            .arg(double(linear.y), 0, 'f', 3)
                            .arg(double(linear.z), 0, 'f', 3));
}

void ColorField::pick() {
    const QColor chosen = QColorDialog::getColor(color_, this, tr("Choose a colour"));
    if (!chosen.isValid() || chosen == color_) return;
    setColor(chosen);
    emit edited(chosen);
}

PropertyForm::PropertyForm(Document& document, const QString& title, QWidget* parent)
    : QWidget(parent), document_(document) {
    auto* box = new QGroupBox(title, this);
    layout_ = new QFormLayout(box);
    layout_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    layout_->setRowWrapPolicy(QFormLayout::WrapLongRows); // a narrow dock puts fields under their labels
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(box);
}

namespace {

constexpr const char* kUncommitted = "_glint_uncommitted"; // a line edit's typing not yet applied

// Whether the field holds typing that Enter (or leaving it) has not applied yet.
bool uncommitted(QObject* field) {
    if (auto* spin = qobject_cast<QDoubleSpinBox*>(field)) return spin->cleanText() != spin->textFromValue(spin->value());
    if (auto* spin = qobject_cast<QSpinBox*>(field)) {
        QString shown = spin->locale().toString(spin->value()); // QSpinBox::textFromValue, which is protected
        if (!spin->isGroupSeparatorShown()) shown.remove(spin->locale().groupSeparator());
        return spin->cleanText() != shown;
    }
    return field->property(kUncommitted).toBool();
}

} // namespace

bool PropertyForm::eventFilter(QObject* watched, QEvent* event) {
    // The wheel scrolls the panel; it edits a field only once the field was clicked or tabbed to
    // (scrolling through the Scene tab switched TAA clipping and tonemappers on the way).
    if (event->type() == QEvent::Wheel) {
        auto* field = static_cast<QWidget*>(watched);
        if (field->hasFocus()) return false;
        for (QWidget* up = field->parentWidget(); up; up = up->parentWidget())
            if (auto* area = qobject_cast<QAbstractScrollArea*>(up)) {
                QCoreApplication::sendEvent(area->verticalScrollBar(), event);
                break;
            }
        return true;
    }
    if (event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        const bool undoKey = key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo);
        if (undoKey && !uncommitted(watched)) {
            // Not taken by the field: the window's Undo/Redo run. A text field lets go of the focus,
            // as after Enter in Blender, so it shows the value the undo brings back.
            if (auto* edit = qobject_cast<QLineEdit*>(watched)) edit->clearFocus();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void PropertyForm::addWidget(const QString& label, QWidget* widget, std::function<void()> refresh) {
    widget->setAccessibleName(label);
    // Text fields and spin boxes leave the document's undo keys to the window once applied.
    QList<QWidget*> fields = widget->findChildren<QWidget*>();
    fields << widget;
    for (QWidget* field : fields) {
        if (auto* edit = qobject_cast<QLineEdit*>(field); edit && !qobject_cast<QAbstractSpinBox*>(edit->parentWidget())) {
            connect(edit, &QLineEdit::textEdited, edit, [edit] { edit->setProperty(kUncommitted, true); });
            connect(edit, &QLineEdit::editingFinished, edit, [edit] { edit->setProperty(kUncommitted, false); });
            edit->installEventFilter(this);
        } else if (qobject_cast<QAbstractSpinBox*>(field)) {
            field->installEventFilter(this);
        }
        if (qobject_cast<QAbstractSpinBox*>(field) || qobject_cast<QComboBox*>(field) || qobject_cast<QAbstractSlider*>(field)) {
            field->setFocusPolicy(Qt::StrongFocus); // not focused by the wheel either
            field->installEventFilter(this);
        }
    }
    layout_->addRow(label, widget);
    if (refresh) {
        refresh();
        refreshers_.push_back(std::move(refresh));
    }
}

void PropertyForm::addNote(const QString& text) {
    auto* note = new QLabel(text, this);
    note->setWordWrap(true);
    note->setTextFormat(Qt::PlainText);
    note->setAccessibleName(text);
    layout_->addRow(note);
}

FloatField* PropertyForm::addFloat(const QString& label, double min, double max, int decimals,
                                   std::function<double()> get, FloatSetter set) {
    auto* field = new FloatField(min, max, decimals, this);
    field->slider()->setAccessibleName(label);
    field->spinBox()->setAccessibleName(label);
    // The drag's serial lives with the field: every value of one drag carries it.
    auto interaction = std::make_shared<std::uint64_t>(0);
    connect(field, &FloatField::dragStarted, this, [this, interaction] { *interaction = document_.beginInteraction(); });
    connect(field, &FloatField::dragFinished, this, [interaction] { *interaction = 0; });
    connect(field, &FloatField::edited, this, [set, interaction](double v) { set(v, *interaction); });
    addWidget(label, field, [field, get] { field->setValue(get()); });
    return field;
}

ColorField* PropertyForm::addColor(const QString& label, std::function<QColor()> get,
                                   std::function<void(const QColor&)> set) {
    auto* field = new ColorField(this);
    connect(field, &ColorField::edited, this, [set](const QColor& c) { set(c); });
    addWidget(label, field, [field, get] { field->setColor(get()); });
    return field;
}

void PropertyForm::addCheck(const QString& label, std::function<bool()> get, std::function<void(bool)> set) {
    auto* box = new QCheckBox(this);
    connect(box, &QCheckBox::toggled, this, [set](bool on) { set(on); });
    addWidget(label, box, [box, get] {
        QSignalBlocker block(box);
        box->setChecked(get());
    });
}

void PropertyForm::addChoice(const QString& label, const QStringList& items, std::function<int()> get,
                             std::function<void(int)> set) {
    auto* combo = newFormComboBox(this);
    combo->addItems(items);
    connect(combo, &QComboBox::activated, this, [set](int i) { set(i); });
    addWidget(label, combo, [combo, get] {
        QSignalBlocker block(combo);
        combo->setCurrentIndex(get());
    });
}

QLineEdit* PropertyForm::addText(const QString& label, std::function<QString()> get, std::function<void(const QString&)> set) {
    auto* edit = new QLineEdit(this);
    connect(edit, &QLineEdit::editingFinished, this, [edit, set] { set(edit->text()); });
    // Not while the user types into it; once applied (Enter) it follows undo and redo too.
    addWidget(label, edit, [edit, get] {
        if (!edit->hasFocus() || !uncommitted(edit)) edit->setText(get());
    });
    return edit;
}

QSpinBox* PropertyForm::addInt(const QString& label, int min, int max, std::function<int()> get, std::function<void(int)> set) {
    auto* spin = new QSpinBox(this);
    spin->setRange(min, max);
    spin->setKeyboardTracking(false);
    connect(spin, &QSpinBox::valueChanged, this, [set](int v) { set(v); });
    addWidget(label, spin, [spin, get] {
        QSignalBlocker block(spin);
        spin->setValue(get());
    });
    return spin;
}

void PropertyForm::refresh() {
    for (const auto& r : refreshers_) r();
}

} // namespace glint::editor
