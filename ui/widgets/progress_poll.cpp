#include "ui/widgets/progress_poll.h"

#include <QProgressDialog>
#include <QTimer>

#include <algorithm>
#include <climits>

namespace fieldsight::ui {

QProgressDialog* showProgress(QWidget* parent, const QString& label, const QString& name,
                              ProgressPoll poll)
{
    auto* dialog = new QProgressDialog(label, QProgressDialog::tr("Cancel"), 0, 0, parent);
    dialog->setObjectName(name);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setMinimumDuration(300);
    if (poll.cancel)
        QObject::connect(dialog, &QProgressDialog::canceled, dialog, poll.cancel);
    auto* timer = new QTimer(dialog);
    QObject::connect(timer, &QTimer::timeout, dialog, [dialog, poll, parent] {
        if (!poll.running || !poll.running()) {
            // The keys go back to the window the run was started from.
            const bool active = dialog->isActiveWindow();
            dialog->close();
            if (active && parent)
                parent->window()->activateWindow();
            return;
        }
        if (dialog->wasCanceled())
            return; // hidden by the cancel: a new value would show it again
        std::pair<std::size_t, std::size_t> count;
        if (poll.progress)
            count = poll.progress();
        dialog->setMaximum(int(std::min<std::size_t>(count.second, INT_MAX)));
        dialog->setValue(int(std::min<std::size_t>(count.first, INT_MAX)));
    });
    timer->start(100);
    return dialog;
}

} // namespace fieldsight::ui
