#include "ui/document/frame_recorder.h"

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
        return Error{m_path.toStdString() + ": already recording"};
    if (!QDir().mkpath(folder))
        return Error{folder.toStdString() + ": cannot make the folder"};
    const QString path = QDir(folder).filePath(QStringLiteral("recording.strm"));
    if (QFileInfo::exists(path))
        return Error{path.toStdString() + ": a recording is already there (choose another folder)"};
    if (Status s = lut.save(QDir(folder).filePath(QStringLiteral("default.lut")).toStdString()); !s)
        return s;
    auto writer = StrmWriter::create(path.toStdString());
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
