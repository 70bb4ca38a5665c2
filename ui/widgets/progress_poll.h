// The progress of a background job the window started (a build from samples, the automatic
// table): a modeless dialog with Cancel that reads the job's count ten times a second and closes
// itself when the job stops, so the window goes on answering while it runs.
#pragma once

#include <QString>

#include <cstddef>
#include <functional>
#include <utility>

class QProgressDialog;
class QWidget;

namespace fieldsight::ui {

/// What the dialog asks of its job (any of these is called on the GUI thread only).
struct ProgressPoll
{
    /// Done of total (a total of 0 shows a busy bar).
    std::function<std::pair<std::size_t, std::size_t>()> progress;
    std::function<bool()> running;
    /// Cancel or Escape.
    std::function<void()> cancel;
};

/// A progress dialog named `name` over `parent`, seen once the job has run 300 ms; deleted when
/// the job stops running or is cancelled.
QProgressDialog* showProgress(QWidget* parent, const QString& label, const QString& name,
                              ProgressPoll poll);

} // namespace fieldsight::ui
