// Recording a live camera into a stream folder, to calibrate on what the robot sees at the
// venue: every camera frame the window shows is appended to <folder>/recording.strm (an original
// NUbots image stream, SPEC §4), and the LUT in use is saved beside it as default.lut, so the
// folder opens as a stream with its table.
#pragma once

#include "ui/document/stream_document.h"

#include <QObject>
#include <QString>

#include <optional>

namespace fieldsight::ui {

class FrameRecorder : public QObject
{
    Q_OBJECT
public:
    explicit FrameRecorder(StreamDocument& doc, QObject* parent = nullptr);
    ~FrameRecorder() override;

    /// Starts recording into `folder` (made if missing) with `lut` saved beside the frames.
    /// Errors name the file and the problem.
    Status start(const QString& folder, const ColourLut& lut);
    /// Stops and closes the file (an Error when the last write failed).
    Status stop();
    bool recording() const { return m_writer.has_value(); }
    std::size_t frames() const { return m_frames; }
    QString path() const { return m_path; }

signals:
    void stateChanged(bool recording);
    /// A write failed: recording stopped.
    void problem(const QString& message);

private:
    void onFrame();

    StreamDocument& m_doc;
    std::optional<StrmWriter> m_writer;
    QString m_path;
    std::size_t m_frames = 0;
    std::uint64_t m_last_serial = 0;
};

} // namespace fieldsight::ui
