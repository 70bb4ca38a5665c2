// A 1280x720 stream in the real main window, offscreen (issue 33): each step forward shows the
// frame asked for, at its full size, with the ball and posts its truth has found by the default
// parameters (lengths in px follow the frame's width), whether the frame came from the frames
// read ahead or was read on request.
#include "support/test_suite.h"
#include "support/test_files.h"
#include "support/window_waits.h"
#include "synth/synth.h"
#include "ui/main_window.h"
#include "ui/stream_navigator/stream_navigator.h"
#include "visioncore/io/annotations.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/goalpost.h"

#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace fieldsight;
using fieldsight::ui::MainWindow;

namespace {
constexpr int kHdFrames = 3;
}

class TestHdWindow : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_hd_window", m_dir), QString());
        QSettings().clear();
        synth::SynthOptions options;
        options.scenario = synth::Scenario::Lab2;
        options.frames = kHdFrames;
        options.width = 1280;
        options.height = 720;
        options.out_dir = m_dir.filePath("hd").toStdString();
        QVERIFY(synth::generateStream(options).ok());
        auto truth = Annotations::load(options.out_dir + "/annotations.json",
                                       Pipeline::standard().perceptKinds());
        QVERIFY(truth.ok());
        m_truth = std::move(truth).value();
    }

    void stepsThroughHdFramesAtFullSizeWithTheirDetections()
    {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(test::openAndWait(w, m_dir.filePath("hd")));
        for (int i = 0; i < kHdFrames; ++i) {
            if (i > 0) {
                QTest::keyClick(&w, Qt::Key_Right);
                QVERIFY(test::waitForFrame(w, std::size_t(i)));
            }
            const auto& out = w.session().stream().current();
            QVERIFY(out);
            QVERIFY2(out->error.isEmpty(), qPrintable(out->error));
            QCOMPARE(out->index, std::size_t(i));
            QCOMPARE(out->frame.ycbcr.cols, 1280);
            QCOMPARE(out->frame.ycbcr.rows, 720);
            QCOMPARE(out->raw.size(), QSize(1280, 720));
            QCOMPARE(out->classified.size(), QSize(1280, 720));

            // The ball where the truth has it, within a few px at 320 wide (x4 here).
            const auto it = m_truth.frames.find(out->frame.name);
            QVERIFY2(it != m_truth.frames.end(), out->frame.name.c_str());
            const auto* true_balls = it->second.truth.find<Ball>();
            QVERIFY(true_balls && !true_balls->empty());
            const auto* balls = out->result.percepts.find<Ball>();
            QVERIFY(balls);
            QCOMPARE(balls->size(), std::size_t(1));
            const Ball& found = balls->front();
            const Ball& truth = true_balls->front();
            QVERIFY2(std::hypot(found.x - truth.x, found.y - truth.y) < 4 * 3.0,
                     qPrintable(QStringLiteral("frame %1: ball at (%2, %3), truth (%4, %5)")
                                    .arg(i)
                                    .arg(found.x)
                                    .arg(found.y)
                                    .arg(truth.x)
                                    .arg(truth.y)));
            const auto* posts = out->result.percepts.find<Goalpost>();
            const auto* true_posts = it->second.truth.find<Goalpost>();
            QVERIFY(posts && true_posts);
            QCOMPARE(posts->size(), true_posts->size());
        }
    }

private:
    QTemporaryDir m_dir;
    Annotations m_truth;
};

FIELDSIGHT_TEST_SUITE(TestHdWindow, Widgets)

#include "test_hd_window.moc"
