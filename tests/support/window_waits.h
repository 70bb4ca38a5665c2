// Waiting, in offscreen GUI tests, for the main window to show a frame or a stream, or to finish
// a scan.
#pragma once

#include "ui/document/edit_effect_scan.h"
#include "ui/frame_view/frame_view.h"
#include "ui/actions/file_commands.h"
#include "ui/main_window.h"
#include "ui/settings/window_settings.h"
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
        const auto& out = w.session().stream().current();
        if (!w.session().stream().waiting() && out && out->index == index &&
            (!w.view().isVisible() || w.view().paintedSerial() == out->serial) &&
            w.detectionsPanel().shownSerial() == out->serial)
            return true;
        QTest::qWait(2);
    }
    return false;
}

inline bool openAndWait(MainWindow& w, const QString& stream)
{
    QSignalSpy opened(&w.files(), &ui::FileCommands::streamOpened);
    w.files().openStream(stream);
    if (!opened.wait(10000) || !opened.front().front().toBool())
        return false;
    // The frame the stream was last left on in this window (0 the first time).
    return waitForFrame(w, w.session().stream().currentIndex());
}

/// Shows `w` at 1280x800, waits until it is the active window, then opens `stream`.
inline bool showAndOpen(MainWindow& w, const QString& stream)
{
    w.resize(1280, 800);
    w.show();
    return QTest::qWaitForWindowActive(&w) && openAndWait(w, stream);
}

/// Waits until the window's evaluation has finished a run with nothing pending (a report, or a
/// problem said).
inline bool waitForEvaluation(MainWindow& w, int ms = 60000)
{
    auto& scan = w.session().evaluation();
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms) {
        if (!scan.running() && !scan.pending() && (scan.report() || !scan.problem().isEmpty()))
            return true;
        QTest::qWait(5);
    }
    return false;
}

/// Waits until the whole-stream edit-effect scan has finished every frame with nothing running.
inline bool waitForScan(ui::EditEffectScan& scan, int ms = 20000)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms) {
        if (!scan.running() && !scan.effects().empty() &&
            scan.framesDone() == scan.effects().size())
            return true;
        QTest::qWait(5);
    }
    return false;
}

} // namespace fieldsight::test
