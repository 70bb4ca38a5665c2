// The thin strip along the timeline that shows which frames are annotated (blue-grey) and done
// (green), and one line on the frame shown's annotation (done or not, its objects, the kinds
// reviewed) for the status bar. Click a frame to go there.
#pragma once

#include "visioncore/services/annotation_editing.h"

#include <QWidget>

class QSlider;

namespace fieldsight::ui {

class AnnotationsDocument;
class StreamDocument;

class AnnotationStrip : public QWidget
{
    Q_OBJECT
public:
    /// Frames are placed where `slider` puts them, so the strip lines up with it.
    AnnotationStrip(const AnnotationsDocument& annotations, const StreamDocument& stream,
                    const QSlider& slider, QWidget* parent = nullptr);

    /// Which frames of the open stream are annotated and done, by index.
    const FrameStates& states() const { return m_states; }
    /// The frame under x (widget px), or -1 when there are no frames.
    long long frameAt(int x) const;
    /// Frame `index`'s annotation in one line.
    QString frameStatus(std::size_t index) const;
    /// The frame shown's, with the count of frames done (empty without a stream of frames).
    QString currentStatus() const;

signals:
    void frameClicked(std::size_t frame);
    /// currentStatus() changed (another frame, an edit, another stream).
    void statusChanged(const QString& status);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    bool event(QEvent* event) override; ///< the tooltip of the frame under the mouse

private:
    void readNames();
    void refresh();
    std::pair<double, double> span() const;

    const AnnotationsDocument& m_doc;
    const StreamDocument& m_stream;
    const QSlider& m_slider;
    std::vector<std::string> m_names;
    FrameStates m_states;
    std::size_t m_done = 0;
};

} // namespace fieldsight::ui
