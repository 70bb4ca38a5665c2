#include "ui/actions/annotations_file.h"

#include "ui/actions/disk_conflict.h"
#include "ui/adapters/local_path.h"
#include "ui/dialogs/dialogs.h"
#include "ui/document/editing_session.h"
#include "ui/widgets/message_bar.h"
#include "visioncore/basics/output_guard.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QFontMetrics>
#include <QLocale>

namespace fieldsight::ui {

namespace {

QString fromStd(const std::string& s)
{
    return QString::fromStdString(s);
}

} // namespace

AnnotationsFile::AnnotationsFile(const MenuTarget& target, OfferBar& recovery_bar)
    : QObject(target.parent), m_target(target), m_recovery_bar(recovery_bar)
{
    // A recovery is offered only when the stream it belongs to is open.
    connect(&m_target.session.stream(), &StreamDocument::streamChanged, this,
            &AnnotationsFile::offerRecovery);
    connect(&m_recovery_bar, &OfferBar::accepted, this, &AnnotationsFile::recover);
    connect(&m_recovery_bar, &OfferBar::declined, this, &AnnotationsFile::discardRecovery);
}

AnnotationsDocument& AnnotationsFile::doc()
{
    return m_target.session.annotations();
}

bool AnnotationsFile::save()
{
    AnnotationsDocument& d = doc();
    if (!m_target.session.stream().hasStream()) {
        m_target.showMessage(tr("Open a stream first: annotations belong to a stream"));
        return false;
    }
    if (!d.loadProblem().isEmpty()) {
        // The damaged file is never written over unasked: another file, or that one chosen.
        m_target.showMessage(tr("%1 could not be read when the stream opened, so Save does not "
                                "write over it: choose a file for the annotations")
                                 .arg(d.path()));
        return saveAs();
    }
    if (d.path().isEmpty())
        return saveAs();
    bool overwrite = false; // chosen over another writer's change: saveAs() writes anyway
    if (const auto ended = settleDiskChange(
            m_target, d.changedOnDisk(), tr("the annotations"), d.path(), overwrite,
            [this] { return reload(); }, [this] { return saveAs(); }))
        return *ended;
    if (Status s = overwrite ? d.saveAs(d.path()) : d.save(); !s) {
        m_target.showMessage(tr("The annotations were not saved (the edits are kept): %1")
                                 .arg(fromStd(s.error().message)));
        return false;
    }
    m_target.showMessage(tr("Saved the annotations to %1").arg(d.path()), false);
    return true;
}

bool AnnotationsFile::reload()
{
    AnnotationsDocument& d = doc();
    if (Status s = d.reload(m_target.session.stream().frameCount()); !s) {
        m_target.showMessage(tr("The annotations were not reloaded (the edits are kept): %1")
                                 .arg(fromStd(s.error().message)));
        return false;
    }
    // Frames the stream lacks are named as when the stream opened: eval refuses them.
    const QString missing = m_target.session.missingAnnotatedFrames();
    m_target.showMessage(tr("Reloaded the annotations from %1 (Edit > Undo brings your edits "
                            "back)")
                                 .arg(d.path()) +
                             (missing.isEmpty() ? QString() : QStringLiteral(". ") + missing),
                         !missing.isEmpty());
    return true;
}

bool AnnotationsFile::saveAs(const QString& given)
{
    AnnotationsDocument& d = doc();
    const StreamDocument& stream = m_target.session.stream();
    if (!stream.hasStream()) {
        m_target.showMessage(tr("Open a stream first: annotations belong to a stream"));
        return false;
    }
    const QFileInfo spec(stream.streamSpec());
    const QString folder = spec.isDir() ? spec.absoluteFilePath() : spec.absolutePath();
    QString path = given;
    if (path.isEmpty()) {
        QString suggestion =
            d.path().isEmpty() ? folder + QStringLiteral("/annotations.json") : d.path();
        if (!d.loadProblem().isEmpty()) // another name than the file that could not be read
            suggestion = QFileInfo(suggestion).absolutePath() + QLatin1Char('/') +
                         QFileInfo(suggestion).completeBaseName() + QStringLiteral(".new.json");
        path = Dialogs::current().saveFile(m_target.parent, tr("Save annotations as"), suggestion,
                                           tr("Fieldsight annotations (*.json)"));
        if (path.isEmpty())
            return false;
    }
    if (!path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive))
        path += QStringLiteral(".json");
    // Never over what the window reads: the stream's file or manifest, the table.
    if (Status s = checkNotAnInput("Save annotations as", toLocalPath(path),
                                   {toLocalPath(spec.isDir() ? QString() : stream.streamSpec()),
                                    toLocalPath(folder + QStringLiteral("/stream.json")),
                                    toLocalPath(m_target.session.lut().path())});
        !s) {
        m_target.showMessage(fromStd(s.error().message));
        return false;
    }
    if (Status s = d.saveAs(path); !s) {
        m_target.showMessage(tr("The annotations were not saved (the edits are kept): %1")
                                 .arg(fromStd(s.error().message)));
        return false;
    }
    m_target.showMessage(tr("Saved the annotations to %1").arg(path), false);
    return true;
}

bool AnnotationsFile::confirmChanges()
{
    AnnotationsDocument& d = doc();
    if (!d.modified())
        return true;
    const auto answer = Dialogs::current().question(
        m_target.parent, tr("Unsaved annotations"),
        tr("The annotations of %1 have edits that are not saved. Save them first?")
            .arg(QFileInfo(d.stream()).fileName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel)
        return false;
    if (answer == QMessageBox::Save)
        return save();
    // Before the revert: reading the file again puts a recovery file there back on offer, and
    // edits recovered from it and now discarded must not be offered again at the next start.
    d.discardOwnRecovery();
    revert();
    return true;
}

void AnnotationsFile::revert()
{
    AnnotationsDocument& d = doc();
    Annotations annotations;
    QString problem;
    if (!d.path().isEmpty() && localPathExists(d.path())) {
        auto loaded = Annotations::load(toLocalPath(d.path()), d.kinds(),
                                        m_target.session.stream().frameCount());
        if (loaded)
            annotations = std::move(loaded).value();
        else
            problem = fromStd(loaded.error().message);
    }
    d.adopt(d.stream(), d.path(), std::move(annotations), problem);
}

void AnnotationsFile::offerRecovery()
{
    OfferBar& bar = m_recovery_bar;
    const std::optional<AnnotationsRecovery> r =
        m_target.session.stream().hasStream() ? doc().findRecovery() : std::nullopt;
    if (!r) {
        bar.hide();
        return;
    }
    const QFontMetrics metrics(bar.font());
    const QString file = r->path.isEmpty() ? tr("(no file yet)") : r->path;
    const QDateTime saved = QDateTime::fromString(r->saved_at, Qt::ISODate);
    const QString when = saved.isValid() ? QLocale().toString(saved, QLocale::ShortFormat)
                                         : tr("at a time not recorded");
    bar.offer(
        tr("Unsaved annotation edits of this stream (%n annotated frame(s), for %1) were "
           "kept when a session ended (%2). Recover them?",
           nullptr, int(r->frames))
            .arg(metrics.elidedText(file, Qt::ElideMiddle, metrics.averageCharWidth() * 48), when),
        tr("Annotations: %1\nStream: %2\nKept in: %3\nAt: %4").arg(file, r->stream, r->file, when));
}

bool AnnotationsFile::recover()
{
    AnnotationsDocument& d = doc();
    const std::optional<AnnotationsRecovery> r = d.findRecovery();
    m_recovery_bar.hide();
    if (!r)
        return false;
    if (d.modified() &&
        Dialogs::current().question(
            m_target.parent, tr("Recover annotations"),
            tr("Recovering replaces the annotation edits made since the stream opened. Recover "
               "anyway?"),
            QMessageBox::Yes | QMessageBox::No, QMessageBox::No) != QMessageBox::Yes)
        return false;
    if (Status s = d.recover(*r); !s) {
        m_target.showMessage(fromStd(s.error().message));
        return false;
    }
    m_target.showMessage(tr("Recovered the annotation edits of %1 (%n annotated frame(s)); save "
                            "them with Ctrl+Alt+S",
                            nullptr, int(r->frames))
                             .arg(QFileInfo(r->stream).fileName()),
                         false);
    return true;
}

void AnnotationsFile::discardRecovery()
{
    doc().discardRecovery();
    m_recovery_bar.hide();
}

} // namespace fieldsight::ui
