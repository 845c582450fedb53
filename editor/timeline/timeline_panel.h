#pragma once
// The timeline panel: a camera's path keys on a time ruler, with add key (from the current view),
// delete key, play/pause/loop at the project fps, the key's values, and the constant-speed mode;
// under it a row of transform keys per animated node (node_key_tracks.h) with key (K), copy,
// paste and the row's interpolation.
// Every edit is a command; scrubbing and playing only move the document's current time, and node
// animations play along because everything that draws follows Document::timeChanged.
#include "editor/timeline/node_key_tracks.h"
#include "scene/core/camera_path.h"
#include "scene/core/ids.h"

#include <QTimer>
#include <QWidget>

#include <functional>
#include <optional>

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace glint::editor {

class Document;
class TimeRuler;

class TimelinePanel : public QWidget {
    Q_OBJECT
public:
    TimelinePanel(Document& document, QWidget* parent = nullptr);

    // Where "add key" takes its pose from (the viewport: keyFromView), and how to get a camera
    // when the scene has none (the viewport's "make scene camera").
    void setKeySource(std::function<CameraKey(double time)> source) { keySource_ = std::move(source); }
    void setCameraMaker(std::function<NodeId()> maker) { cameraMaker_ = std::move(maker); }

    NodeId camera() const { return camera_; }
    void setCamera(NodeId camera);
    TimeRuler& ruler() { return *ruler_; }
    NodeKeyTracks& nodeTracks() { return *tracks_; }
    QComboBox* interpolationBox() const { return interpolation_; }
    bool playing() const { return timer_.isActive(); }
    double fps() const;

    QAction* addKeyAction() const { return addKey_; }
    QAction* deleteKeyAction() const { return deleteKey_; }
    QAction* playAction() const { return play_; }
    QAction* loopAction() const { return loop_; }
    QAction* constantSpeedAction() const { return constantSpeed_; }
    QAction* keyNodeAction() const { return keyNode_; }
    QAction* autoKeyAction() const { return autoKey_; }
    QAction* copyNodeKeyAction() const { return copyNodeKey_; }
    QAction* pasteNodeKeyAction() const { return pasteNodeKey_; }

public slots:
    void addKey();
    void deleteKey(); // the selected node key, else the selected camera key
    void setPlaying(bool on);
    void stepFrame(); // one playback tick: the next frame, looping or stopping at the end

private:
    void createActions();
    void createNodeKeyActions();
    QWidget* createInterpolationBox(QWidget* parent);
    void refreshInterpolation();
    QWidget* createKeyEditor();
    void refreshCameras();
    void refreshKeyEditor();
    void editSelectedKey();
    const CameraPath* path() const;

    Document& document_;
    NodeId camera_{};
    TimeRuler* ruler_ = nullptr;
    NodeKeyTracks* tracks_ = nullptr;
    QComboBox* interpolation_ = nullptr;
    QComboBox* cameras_ = nullptr;
    QLabel* timeLabel_ = nullptr;
    QDoubleSpinBox* keyFields_[7] = {}; // x y z, fov (degrees), focus, lens radius, time (read-only)
    QAction* addKey_ = nullptr;
    QAction* deleteKey_ = nullptr;
    QAction* play_ = nullptr;
    QAction* loop_ = nullptr;
    QAction* constantSpeed_ = nullptr;
    QAction* keyNode_ = nullptr;
    QAction* autoKey_ = nullptr;
    QAction* copyNodeKey_ = nullptr;
    QAction* pasteNodeKey_ = nullptr;
    std::optional<NodeKey> copied_;
    QTimer timer_;
    std::function<CameraKey(double)> keySource_;
    std::function<NodeId()> cameraMaker_;
    bool refreshing_ = false;
};

} // namespace glint::editor
