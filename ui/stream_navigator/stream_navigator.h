// Frame-accurate stream navigation by frame index: first/previous/next/last, ±10 and ±100, a
// slider over every frame, go to frame, play/pause with speed and loop; every one an action with
// a shortcut.
#pragma once

#include "ui/document/stream_document.h"

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

class QAction;
class QComboBox;
class QLabel;
class QSlider;

namespace fieldsight::ui {

class StreamNavigator : public QWidget
{
    Q_OBJECT
public:
    explicit StreamNavigator(StreamDocument& document, QWidget* parent = nullptr);

    /// The navigation actions, in menu order (separators included).
    const QList<QAction*>& navigationActions() const { return m_actions; }
    QAction* loopAction() const { return m_loop; }

    /// Moves `delta` frames (clamped to the stream).
    void step(long long delta);
    void goToFrame(std::size_t index);
    /// Asks for a frame number (1-based as shown) and goes there.
    void askGoTo();

    bool playing() const { return m_playing; }
    void setPlaying(bool on);
    /// Frames per second while playing; 0 means as fast as frames are done.
    int speed() const { return m_fps; }
    void setSpeed(int fps);
    QSlider* slider() const { return m_slider; }
    /// Puts `strip` just above the slider, the same width, so its frames line up with it.
    void addTimelineStrip(QWidget* strip);

signals:
    void playingChanged(bool playing);

private:
    QAction* makeAction(const QString& text, const QKeySequence& key, std::function<void()> run,
                        const QString& name);
    void tick();
    void refresh();
    void showFrameInfo();

    StreamDocument& m_doc;
    QList<QAction*> m_actions;
    QAction* m_play = nullptr;
    QAction* m_loop = nullptr;
    QSlider* m_slider = nullptr;
    QLabel* m_label = nullptr;
    QComboBox* m_speed_box = nullptr;
    QTimer m_timer; ///< paces play at a set speed; "fastest" steps on every finished frame
    bool m_playing = false;
    int m_fps = 30;
    QElapsedTimer m_fps_clock;
    int m_fps_frames = 0;
    double m_measured_fps = 0; ///< frames shown per second over the last second of play
};

} // namespace fieldsight::ui
