#include "ui/actions/session_files.h"

#include "ui/actions/annotations_file.h"
#include "ui/actions/disk_conflict.h"
#include "ui/adapters/local_path.h"
#include "ui/dialogs/dialogs.h"
#include "ui/dialogs/lut_compare_dialog.h"
#include "ui/document/editing_session.h"
#include "ui/frame_view/frame_view.h"
#include "ui/settings/window_settings.h"
#include "ui/widgets/message_bar.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/output_guard.h"
#include "visioncore/io/lut_import.h"
#include "visioncore/io/orientation.h"

#include <QApplication>
#include <QBuffer>
#include <QClipboard>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QFontMetrics>
#include <QLocale>
#include <QMenu>
#include <QProgressDialog>
#include <QStandardPaths>

#include <algorithm>
#include <filesystem>
#include <utility>

namespace fieldsight::ui {

namespace {

constexpr int kMaxRecent = 10;

QString errorText(const std::string& s)
{
    return QString::fromStdString(s);
}

/// The same stream, wherever it was named from (links and relative paths resolved).
bool sameStream(const QString& a, const QString& b)
{
    if (a.isEmpty() || b.isEmpty())
        return false;
    if (a == b)
        return true;
    const QString ca = QFileInfo(a).canonicalFilePath(), cb = QFileInfo(b).canonicalFilePath();
    return !ca.isEmpty() && ca == cb;
}

bool isLutFile(const QString& path)
{
    const QString lower = path.toLower();
    for (std::string_view suffix : importableLutSuffixes())
        if (lower.endsWith(QString::fromLatin1(suffix.data(), qsizetype(suffix.size()))))
            return true;
    return false;
}

} // namespace

SessionFiles::SessionFiles(const MenuTarget& target, AnnotationsFile& annotations, FrameView& view,
                           OfferBar& recovery_bar)
    : QObject(target.parent), m_target(target), m_annotations(annotations), m_view(view),
      m_recovery_bar(recovery_bar)
{
    connect(&m_recovery_bar, &OfferBar::accepted, this, &SessionFiles::recoverLut);
    connect(&m_recovery_bar, &OfferBar::declined, this, &SessionFiles::discardRecovery);
    connect(&m_target.session, &EditingSession::opened, this, &SessionFiles::onOpened);
}

void SessionFiles::onOpened(bool ok, bool cancelled, const QString& error)
{
    if (m_progress) {
        m_progress->reset();
        m_progress->deleteLater();
        m_progress = nullptr;
    }
    const std::optional<LutRecovery> recovery = std::exchange(m_recover_after_open, {});
    if (!ok) {
        m_target.showMessage(recovery ? tr("%1. The LUT edits recovered for it were not "
                                           "applied; they are kept in %2")
                                            .arg(error, recovery->lut_file)
                                      : error,
                             !cancelled);
        emit streamOpened(false);
        return;
    }
    rememberRecent(m_target.session.stream().streamSpec());
    // Back on the frame the stream was last left on.
    StreamDocument& stream = m_target.session.stream();
    if (const int frame = m_frames.value(recentKey(stream.streamSpec()), 0);
        frame > 0 && std::size_t(frame) < stream.frameCount())
        stream.setCurrentIndex(std::size_t(frame));
    // Remembered now, not only on a clean quit: after a crash the next start reopens it.
    emit settingsToSave();
    QObject::disconnect(m_until_classified);
    if (const QStringList warnings = m_target.session.warnings(); !warnings.isEmpty()) {
        const QString shown = warnings.join('\n');
        m_target.showMessage(shown);
        if (m_target.session.stream().lutProblem())
            hideWhenClassified(shown);
    } else {
        m_target.clearMessage();
    }
    if (recovery)
        applyRecovery(*recovery);
    emit streamOpened(true);
}

bool SessionFiles::openStream(const QString& spec, const QString& lut)
{
    if (!confirmLutChanges() || !m_annotations.confirmChanges())
        return false;
    rememberFrame();
    EditingSession& session = m_target.session;
    if (!session.openStream(spec, lut)) {
        m_target.showMessage(
            tr("Still opening %1; wait or cancel it first").arg(session.openingSpec()));
        return false;
    }
    m_progress =
        new QProgressDialog(tr("Opening %1…").arg(spec), tr("Cancel"), 0, 0, m_target.parent);
    m_progress->setWindowTitle(tr("Opening stream"));
    m_progress->setMinimumDuration(400);
    m_progress->setWindowModality(Qt::WindowModal);
    connect(m_progress, &QProgressDialog::canceled, &session, &EditingSession::cancelOpening);
    return true;
}

bool SessionFiles::openLut(const QString& path)
{
    if (!confirmLutChanges())
        return false;
    if (Status s = m_target.session.openLut(path); !s) {
        m_target.showMessage(errorText(s.error().message));
        return false;
    }
    return true;
}

void SessionFiles::openPath(const QString& path)
{
    if (isLutFile(path))
        openLut(path);
    else
        openStream(path);
}

LutCompareDialog* SessionFiles::compareLut(const QString& path)
{
    auto other = importLut(toLocalPath(path));
    if (!other) {
        m_target.showMessage(errorText(other.error().message));
        return nullptr;
    }
    auto* dialog = new LutCompareDialog(m_target.session.lut(), std::move(other).value(), path,
                                        m_target.parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &LutCompareDialog::cellsChosen, this, &SessionFiles::compareCellsChosen);
    dialog->show();
    return dialog;
}

void SessionFiles::openLastSession(const QString& stream, const QString& lut)
{
    if (localPathExists(stream)) {
        openStream(stream, localPathExists(lut) ? lut : QString());
        return;
    }
    QString problem;
    const QString sample = sampleStreamCopy(&problem);
    if (sample.isEmpty()) {
        m_target.showMessage(tr("The bundled sample stream was not found; open a stream with "
                                "File > Open stream folder"));
        return;
    }
    openStream(sample);
    if (!problem.isEmpty())
        m_target.showMessage(problem);
}

bool SessionFiles::newLut()
{
    if (!confirmLutChanges())
        return false;
    m_target.session.lut().reset(std::make_shared<const ColourLut>(), {});
    const QString shown = tr("A new, empty table: every pixel is unclassified until you classify "
                             "some (Save LUT As names it)");
    m_target.showMessage(shown, false);
    hideWhenClassified(shown);
    return true;
}

void SessionFiles::hideWhenClassified(const QString& shown)
{
    QObject::disconnect(m_until_classified);
    LutDocument& lut = m_target.session.lut();
    m_until_classified = connect(&lut, &LutDocument::changed, this, [this, shown] {
        const ColourLut& table = m_target.session.lut().table();
        const std::uint8_t* cells = table.data();
        if (std::all_of(cells, cells + ColourLut::kCells, [](std::uint8_t c) { return c == 0; }))
            return;
        QObject::disconnect(m_until_classified);
        if (m_target.shownMessage() == shown)
            m_target.clearMessage();
    });
}

bool SessionFiles::saveAll()
{
    const bool annotations = m_target.session.annotations().modified();
    bool ok = true;
    if (annotations)
        ok = m_annotations.save();
    if (m_target.session.lut().modified() || !annotations)
        ok = saveLut() && ok;
    return ok;
}

bool SessionFiles::saveLut()
{
    LutDocument& lut = m_target.session.lut();
    if (lut.path().isEmpty() || !lut.path().endsWith(QLatin1String(".lut")))
        return saveLutAs();
    bool overwrite = false; // chosen over another writer's change: saveAs() writes anyway
    if (const auto ended = settleDiskChange(
            m_target, lut.changedOnDisk(), tr("the LUT"), lut.path(), overwrite,
            [this] { return reloadLut(); }, [this] { return saveLutAs(); }))
        return *ended;
    if (Status s = overwrite ? lut.saveAs(lut.path()) : lut.save(); !s) {
        m_target.showMessage(
            tr("The LUT was not saved (the edits are kept): %1").arg(errorText(s.error().message)));
        return false;
    }
    m_target.showMessage(tr("Saved %1").arg(lut.path()), false);
    return true;
}

bool SessionFiles::reloadLut()
{
    LutDocument& lut = m_target.session.lut();
    if (Status s = lut.reload(); !s) {
        m_target.showMessage(tr("The LUT was not reloaded (the edits are kept): %1")
                                 .arg(errorText(s.error().message)));
        return false;
    }
    m_target.showMessage(
        tr("Reloaded %1 from disk (Edit > Undo brings your edits back)").arg(lut.path()), false);
    return true;
}

QString SessionFiles::streamFolder() const
{
    const QFileInfo spec(m_target.session.stream().streamSpec());
    return spec.isDir() ? spec.absoluteFilePath() : spec.absolutePath();
}

bool SessionFiles::saveLutAs(const QString& given)
{
    LutDocument& lut = m_target.session.lut();
    QString path = given;
    if (path.isEmpty()) {
        QString suggestion = lut.path();
        if (suggestion.isEmpty() || !suggestion.endsWith(QLatin1String(".lut")))
            suggestion = streamFolder() + QStringLiteral("/venue.lut");
        path = Dialogs::current().saveFile(m_target.parent, tr("Save LUT as"), suggestion,
                                           tr("Fieldsight LUT (*.lut)"));
        if (path.isEmpty())
            return false;
    }
    if (!path.endsWith(QLatin1String(".lut"), Qt::CaseInsensitive))
        path += QStringLiteral(".lut");
    if (Status s = lut.saveAs(path); !s) {
        m_target.showMessage(
            tr("The LUT was not saved (the edits are kept): %1").arg(errorText(s.error().message)));
        return false;
    }
    m_target.showMessage(tr("Saved %1").arg(path), false);
    if (given.isEmpty()) // chosen by the user in the dialog, not given by a caller
        offerAsStreamTable(path);
    return true;
}

bool SessionFiles::confirmLutChanges()
{
    LutDocument& lut = m_target.session.lut();
    if (!lut.modified())
        return true;
    const auto answer = Dialogs::current().question(
        m_target.parent, tr("Unsaved LUT edits"),
        tr("The LUT has edits that are not saved. Save them first?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel)
        return false;
    if (answer == QMessageBox::Save)
        return saveLut();
    lut.revert(); // discarded: what loads next replaces it
    lut.discardRecovery();
    return true;
}

void SessionFiles::offerRecovery()
{
    const std::optional<LutRecovery> r = m_target.session.lut().findRecovery();
    if (!r) {
        m_recovery_bar.hide();
        return;
    }
    // Paths shortened in the middle (the whole in the tooltip), the time in the user's format.
    const QFontMetrics metrics(m_recovery_bar.font());
    const auto shown = [&metrics](const QString& path) {
        return metrics.elidedText(path, Qt::ElideMiddle, metrics.averageCharWidth() * 48);
    };
    const QString table = r->path.isEmpty() ? tr("a new table") : r->path;
    const QString stream = r->stream.isEmpty() ? tr("(not named)") : r->stream;
    const QDateTime saved = QDateTime::fromString(r->saved_at, Qt::ISODate);
    const QString when = saved.isValid() ? QLocale().toString(saved, QLocale::ShortFormat)
                                         : tr("at a time not recorded");
    m_recovery_bar.offer(
        tr("Unsaved edits of %1 on the stream %2 were kept when a session ended (%3). Recover "
           "them? Recover opens that stream.")
            .arg(shown(table), shown(stream), when),
        tr("Table: %1\nStream: %2\nKept: %3").arg(table, stream, when));
}

bool SessionFiles::recoverLut()
{
    const std::optional<LutRecovery> r = m_target.session.lut().findRecovery();
    m_recovery_bar.hide();
    if (!r)
        return false;
    // Edits go back only to the stream and table they were made on.
    const QString current = m_target.session.stream().streamSpec();
    if (sameStream(current, r->stream))
        return applyRecovery(*r);
    if (r->stream.isEmpty() || r->stream.startsWith(QLatin1String("camera:")) ||
        !localPathExists(r->stream)) {
        m_target.showMessage(
            tr("The recovered LUT edits belong to the stream %1, which cannot be "
               "opened here; they were not applied to this one and are kept "
               "in %2")
                .arg(r->stream.isEmpty() ? tr("(not named)") : r->stream, r->lut_file));
        return false;
    }
    m_recover_after_open = *r;
    if (!openStream(r->stream, localPathExists(r->path) ? r->path : QString())) {
        m_recover_after_open.reset();
        m_target.showMessage(tr("%1 was not opened: the recovered LUT edits for it are kept in %2")
                                 .arg(r->stream, r->lut_file));
        return false;
    }
    return true;
}

bool SessionFiles::applyRecovery(const LutRecovery& recovery)
{
    if (Status s = m_target.session.lut().recover(recovery); !s) {
        m_target.showMessage(errorText(s.error().message));
        return false;
    }
    m_target.showMessage(
        tr("Recovered the LUT edits of %1 on %2; save them with Ctrl+S")
            .arg(recovery.path.isEmpty() ? tr("a new table") : recovery.path, recovery.stream),
        false);
    return true;
}

void SessionFiles::discardRecovery()
{
    m_target.session.lut().discardRecovery();
    m_recovery_bar.hide();
}

bool SessionFiles::saveSnapshot(const QString& path)
{
    // The same rule as the commands': never over a file of the stream or the table in use.
    if (Status s = checkNotAnInput("Save view as PNG", toLocalPath(path),
                                   {toLocalPath(m_target.session.stream().streamSpec()),
                                    toLocalPath(m_target.session.lut().path())});
        !s) {
        m_target.showMessage(errorText(s.error().message));
        return false;
    }
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (!m_view.grab().toImage().save(&buffer, "PNG")) {
        m_target.showMessage(tr("%1: cannot encode the view as PNG").arg(path));
        return false;
    }
    if (Status s = writeFileAtomically(toLocalPath(path), png.constData(), std::size_t(png.size()));
        !s) {
        m_target.showMessage(errorText(s.error().message));
        return false;
    }
    m_target.showMessage(tr("Saved the view to %1").arg(path), false);
    return true;
}

void SessionFiles::copySnapshot()
{
    QApplication::clipboard()->setImage(m_view.grab().toImage());
    m_target.showStatus(tr("The view is on the clipboard"), 4000);
}

void SessionFiles::setRecent(const QStringList& recent)
{
    m_recent = recent.mid(0, kMaxRecent);
    rebuildRecentMenu();
}

void SessionFiles::setRecentMenu(QMenu* menu)
{
    m_recent_menu = menu;
    rebuildRecentMenu();
}

QString SessionFiles::recentKey(const QString& spec)
{
    return spec.startsWith(QLatin1String("camera:")) ? spec : QFileInfo(spec).absoluteFilePath();
}

void SessionFiles::rememberFrame()
{
    const StreamDocument& stream = m_target.session.stream();
    if (stream.hasStream())
        m_frames[recentKey(stream.streamSpec())] = int(stream.currentIndex());
}

void SessionFiles::saveSettings(WindowSettings& w) const
{
    w.recent = m_recent;
    w.recent_frames = recentFrames();
    const StreamDocument& stream = m_target.session.stream();
    if (!stream.hasStream())
        return;
    w.stream = w.recent.value(0, stream.streamSpec());
    const QString lut = m_target.session.lut().path();
    w.lut = lut.isEmpty() ? QString() : QFileInfo(lut).absoluteFilePath();
}

void SessionFiles::restoreSettings(const WindowSettings& w)
{
    setRecent(w.recent);
    setRecentFrames(w.recent_frames);
}

QList<int> SessionFiles::recentFrames() const
{
    const StreamDocument& stream = m_target.session.stream();
    const QString open = stream.hasStream() ? recentKey(stream.streamSpec()) : QString();
    QList<int> frames;
    for (const QString& path : m_recent)
        frames << (path == open ? int(stream.currentIndex()) : m_frames.value(path, 0));
    return frames;
}

void SessionFiles::setRecentFrames(const QList<int>& frames)
{
    for (qsizetype i = 0; i < m_recent.size() && i < frames.size(); ++i)
        m_frames[m_recent[i]] = frames[i];
}

void SessionFiles::rememberRecent(const QString& spec)
{
    const QString path = recentKey(spec);
    m_recent.removeAll(path);
    m_recent.prepend(path);
    while (m_recent.size() > kMaxRecent)
        m_recent.removeLast();
    rebuildRecentMenu();
}

void SessionFiles::rebuildRecentMenu()
{
    if (!m_recent_menu)
        return;
    m_recent_menu->clear();
    for (const QString& path : m_recent)
        m_recent_menu->addAction(path, this, [this, path] { openStream(path); });
    m_recent_menu->setEnabled(!m_recent.isEmpty());
}

} // namespace fieldsight::ui
