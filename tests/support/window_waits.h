// Waiting, in offscreen GUI tests, for the main window to show a frame or a stream.
#pragma once

#include "ui/frame_view/frame_view.h"
#include "ui/main_window.h"
#include "ui/panels/detections_panel.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QtTest>

namespace fieldsight::test {

using ui::MainWindow;

/// Waits until the document answered its newest request with frame `index`, and the view and the
/// panels show it.
inline bool waitForFrame(MainWindow& w, std::size_t index)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 10000) {
        const auto& out = w.document().current();
        if (!w.document().waiting() && out && out->index == index &&
            (!w.view().isVisible() || w.view().paintedSerial() == out->serial) &&
            w.detectionsPanel().shownSerial() == out->serial)
            return true;
        QTest::qWait(2);
    }
    return false;
}

inline bool openAndWait(MainWindow& w, const QString& stream)
{
    QSignalSpy opened(&w, &MainWindow::streamOpened);
    w.openStream(stream);
    if (!opened.wait(10000) || !opened.front().front().toBool())
        return false;
    return waitForFrame(w, 0);
}

} // namespace fieldsight::test
