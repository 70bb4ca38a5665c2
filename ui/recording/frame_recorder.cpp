#include "ui/recording/frame_recorder.h"

#include "ui/adapters/local_path.h"
#include "visioncore/basics/output_guard.h"

#include <QDir>
#include <QFileInfo>

namespace fieldsight::ui {

FrameRecorder::FrameRecorder(StreamDocument& doc, QObject* parent) : QObject(parent), m_doc(doc)
{
    connect(&doc, &StreamDocument::frameReady, this, &FrameRecorder::onFrame);
    connect(&doc, &StreamDocument::streamChanged, this, [this] {
        if (recording())
            (void)stop(); // the camera it recorded is gone
    });
}

FrameRecorder::~FrameRecorder()
{
    if (m_writer)
        (void)m_writer->close();
}

Status FrameRecorder::start(const QString& folder, const ColourLut& lut)
{
    if (recording())
        return Error{toLocalPath(m_path) + ": already recording"};
    // A recording writes a stream of its own (frames and table): only into a new or empty folder.
    if (Status s = checkNewOrEmptyFolder("Record camera", toLocalPath(folder)); !s)
        return s;
    if (!makeLocalFolder(folder))
        return Error{toLocalPath(folder) + ": cannot make the folder"};
    const QString path = QDir(folder).filePath(QStringLiteral("recording.strm"));
    if (localPathExists(path))
        return Error{toLocalPath(path) + ": a recording is already there (choose another folder)"};
    if (Status s = lut.save(toLocalPath(QDir(folder).filePath(QStringLiteral("default.lut")))); !s)
        return s;
    auto writer = StrmWriter::create(toLocalPath(path));
    if (!writer)
        return writer.error();
    m_writer.emplace(std::move(writer).value());
    m_path = path;
    m_frames = 0;
    m_last_serial = m_doc.current() ? m_doc.current()->serial : 0;
    emit stateChanged(true);
    return {};
}

Status FrameRecorder::stop()
{
    if (!m_writer)
        return {};
    Status s = m_writer->close();
    m_writer.reset();
    emit stateChanged(false);
    return s;
}

void FrameRecorder::onFrame()
{
    const auto& out = m_doc.current();
    if (!m_writer || !m_doc.live() || !out || !out->error.isEmpty() ||
        out->serial == m_last_serial || out->frame.ycbcr.empty())
        return;
    m_last_serial = out->serial;
    if (Status s = m_writer->append(out->frame); !s) {
        (void)stop();
        emit problem(QString::fromStdString(s.error().message) + tr(" (recording stopped)"));
        return;
    }
    ++m_frames;
}

} // namespace fieldsight::ui
