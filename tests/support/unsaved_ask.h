// The ask about a document's unsaved edits, the same for every document: Save, Discard or Cancel,
// when the window closes and when another stream opens. A suite supplies its document's edit and
// file; the answer's effect on the window and the stream is checked here once.
#pragma once

#include "support/scripted_dialogs.h"
#include "support/window_waits.h"

#include <QFileInfo>
#include <QMessageBox>
#include <QSignalSpy>
#include <QtTest>

#include <functional>

namespace fieldsight::test {

/// The rows of an ask test: each answer, on opening another stream and on closing the window.
inline void addUnsavedAskRows()
{
    QTest::addColumn<QMessageBox::StandardButton>("answer");
    QTest::addColumn<bool>("close"); // closing the window instead of opening another stream
    for (bool close : {false, true}) {
        const char* when = close ? "close" : "open";
        QTest::addRow("%s, Save", when) << QMessageBox::Save << close;
        QTest::addRow("%s, Discard", when) << QMessageBox::Discard << close;
        QTest::addRow("%s, Cancel", when) << QMessageBox::Cancel << close;
    }
}

/// The row's data tag as part of a file name ("open_Save").
inline QString unsavedAskTag()
{
    return QString::fromLatin1(QTest::currentDataTag()).replace(", ", "_");
}

/// What an ask test knows of its document.
struct UnsavedDocument
{
    QString question;                     ///< the ask's title
    std::function<bool()> holds_edit;     ///< the document still holds the edit, modified
    std::function<bool()> file_has_edit;  ///< its file holds the edit (after Save)
    std::function<bool()> file_as_before; ///< its file is as it was before the edit
    std::function<bool()> has_recovery;   ///< a recovery file of the edit is there
    std::function<bool()> shows_other;    ///< after the other stream opened: its document, unedited
};

/// With `w` showing stream `a` whose document holds an edit, closes `w` (`close`) or opens `b` by
/// File > Open stream folder, answers the ask with `answer`, and checks what follows: Cancel keeps
/// the window, the stream, the edit and its recovery file and writes nothing; Save writes the
/// edit, Discard leaves the file, and both drop the recovery file; then the window is closed or
/// shows `b`. A failure is recorded as the test's (QTest::currentTestFailed()).
inline void answerUnsavedAsk(MainWindow& w, ScriptedDialogs& dialogs, const UnsavedDocument& doc,
                             QMessageBox::StandardButton answer, bool close, const QString& a,
                             const QString& b)
{
    const auto canonical = [](const QString& path) { return QFileInfo(path).canonicalFilePath(); };
    dialogs.answers.push_back(answer);
    QSignalSpy opened(&w.files(), &ui::FileCommands::streamOpened);
    bool closed = false;
    if (close) {
        closed = w.close();
    } else {
        dialogs.paths.push_back(b);
        QTest::keyClick(&w, Qt::Key_O, Qt::ControlModifier); // File > Open stream folder
    }
    QCOMPARE(dialogs.asked.value(dialogs.asked.size() - 1), doc.question);
    QVERIFY(dialogs.unanswered.isEmpty());

    if (answer == QMessageBox::Cancel) {
        // Nothing goes: the window, the stream, the edit and its recovery file stay.
        QVERIFY(!opened.wait(300));
        QVERIFY(!closed && w.isVisible());
        QCOMPARE(canonical(w.session().stream().streamSpec()), canonical(a));
        QVERIFY(doc.holds_edit());
        QVERIFY(w.isWindowModified());
        QVERIFY(doc.file_as_before());
        QVERIFY(doc.has_recovery());
        return;
    }
    if (answer == QMessageBox::Save)
        QVERIFY(doc.file_has_edit());
    else
        QVERIFY(doc.file_as_before());
    QVERIFY(!doc.has_recovery()); // saved or discarded: not offered again
    if (close) {
        QVERIFY(closed && !w.isVisible());
        return;
    }
    QVERIFY(opened.wait(10000));
    QVERIFY(opened.front().front().toBool());
    QCOMPARE(canonical(w.session().stream().streamSpec()), canonical(b));
    QVERIFY(doc.shows_other());
    QVERIFY(!w.isWindowModified());
}

} // namespace fieldsight::test
