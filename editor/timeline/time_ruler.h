#pragma once
// The timeline's ruler: seconds and frame ticks, the camera path's keys as diamonds and the
// playhead. Click or drag on the ruler scrubs (Document::setCurrentTime, snapped to frames);
// dragging a key moves it in time (MoveCameraKey, one undo step per drag); a click selects a key.
#include "editor/timeline/time_ruler_math.h"
#include "scene/core/ids.h"

#include <QWidget>

#include <cstdint>
#include <optional>

namespace glint::editor {

class Document;

class TimeRuler : public QWidget {
    Q_OBJECT
public:
    TimeRuler(Document& document, QWidget* parent = nullptr);

    void setCamera(NodeId camera);
    NodeId camera() const { return camera_; }
    TimeRange range() const;
    std::optional<std::size_t> selectedKey() const { return selectedKey_; }
    void setSelectedKey(std::optional<std::size_t> key);
    double xAt(double time) const;
    double timeAt(double x) const;
    QSize sizeHint() const override { return {400, 48}; }

signals:
    void keySelected(std::optional<std::size_t> key);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    std::optional<std::size_t> keyAt(double x) const;
    double fps() const;
    void scrubTo(double x);

    Document& document_;
    NodeId camera_{};
    std::optional<std::size_t> selectedKey_;
    std::optional<std::size_t> draggedKey_;
    std::uint64_t dragInteraction_ = 0;
    bool scrubbing_ = false;
};

} // namespace glint::editor
