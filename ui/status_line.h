// The window's status bar fields: what the last edit did over the stream (the edit effect), the
// frame's annotation status, the core's and the worker's time for the frame and the zoom; and the
// tool's preview line while the tool has one (the editor's own line may be out of sight).
#pragma once

#include <QObject>
#include <QString>

class QLabel;
class QStatusBar;

namespace fieldsight::ui {

class EditingSession;
class FrameView;
class Timeline;
class ToolManager;

class StatusLine : public QObject
{
    Q_OBJECT
public:
    /// Adds the fields to `bar`, which owns them.
    StatusLine(QStatusBar& bar, EditingSession& session, const Timeline& timeline, FrameView& view,
               ToolManager& tools);

private:
    void showTimes();
    void showPreview();

    QStatusBar& m_bar;
    EditingSession& m_session;
    ToolManager& m_tools;
    QLabel* m_effect = nullptr;
    QLabel* m_time = nullptr;
    QString m_preview_shown; ///< the tool's preview line in the status bar, if any
};

} // namespace fieldsight::ui
