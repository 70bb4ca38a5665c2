#include "ui/scans/auto_lut_run.h"

#include <QtConcurrent/QtConcurrentRun>

namespace fieldsight::ui {

AutoLutRun::AutoLutRun(QObject* parent) : QObject(parent), m_builder(&buildAutoLut)
{
    connect(&m_watcher, &QFutureWatcher<Result<AutoLut>>::finished, this, [this] {
        Result<AutoLut> result = m_watcher.result();
        // A cancel that came after the last frame was read still leaves the table unused.
        if (result && m_cancel)
            result.value().cancelled = true;
        emit finished(result);
    });
}

AutoLutRun::~AutoLutRun()
{
    m_cancel = true;
    m_watcher.waitForFinished();
}

bool AutoLutRun::start(Opener open, AutoLutOptions options)
{
    if (running() || !open)
        return false;
    m_cancel = false;
    m_done = 0;
    m_total = 0;
    m_watcher.setFuture(QtConcurrent::run(
        [this, open = std::move(open), options, builder = m_builder]() -> Result<AutoLut> {
            auto reader = open();
            if (!reader)
                return reader.error();
            return builder(*reader.value(), options, [this](std::size_t done, std::size_t total) {
                m_done = done;
                m_total = total;
                return !m_cancel;
            });
        }));
    return true;
}

} // namespace fieldsight::ui
