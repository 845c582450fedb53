#pragma once
// The timeline's node rows under the ruler: one row per node with transform keys (and one for the
// selected node, ready to be keyed), its keys as diamonds at the ruler's times. A click selects a
// key, a drag moves it (one undo step per drag, snapped to frames), and the panel's actions key,
// delete, copy and paste keys and set a row's interpolation. Every edit is an undoable
// Add/Set/RemoveAsset of the node's Animation (scene/anim/node_keys.h).
#include "scene/core/ids.h"

#include <QWidget>

#include <cstdint>
#include <optional>
#include <vector>

namespace glint::editor {

class Document;
class TimeRuler;

struct NodeKey {
    NodeId node;
    double time = 0.0;
    friend bool operator==(const NodeKey&, const NodeKey&) = default;
};

class NodeKeyTracks : public QWidget {
    Q_OBJECT
public:
    NodeKeyTracks(Document& document, const TimeRuler& ruler, QWidget* parent = nullptr);

    // The rows shown: animated nodes in scene order, then the current node when it has no keys.
    std::vector<NodeId> rows() const;
    static constexpr int kRowHeight = 20;
    double rowCentreY(std::size_t row) const { return (double(row) + 0.5) * kRowHeight; }

    std::optional<NodeKey> selectedKey() const { return selected_; }
    void setSelectedKey(std::optional<NodeKey> key);
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return {100, kRowHeight}; }

signals:
    void keySelected(std::optional<NodeKey> key);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    std::optional<NodeKey> keyAt(QPointF at) const;
    void refresh();

    Document& document_;
    const TimeRuler& ruler_;
    std::optional<NodeKey> selected_;
    std::optional<NodeKey> dragged_;
    std::uint64_t dragInteraction_ = 0;
};

// The edits, one undo step each; none happens (and false comes back) where there is nothing to do.
// Keys every given node's local transform at time t (a new animation for a node without one).
bool keyNodes(Document& document, const std::vector<NodeId>& nodes, double t);
bool deleteNodeKey(Document& document, const NodeKey& key); // the animation goes when its last key does
bool moveNodeKey(Document& document, const NodeKey& key, double to, std::uint64_t interaction = 0);
bool setNodeInterpolation(Document& document, NodeId node, int interpolation); // Interpolation's value
// Keys `node` at t with the transform `key` holds (copy and paste).
bool pasteNodeKey(Document& document, const NodeKey& copied, NodeId node, double t);

} // namespace glint::editor
