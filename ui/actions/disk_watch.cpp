#include "ui/actions/disk_watch.h"

#include "ui/actions/annotations_file.h"
#include "ui/actions/session_files.h"
#include "ui/adapters/local_path.h"
#include "ui/document/editing_session.h"
#include "ui/widgets/message_bar.h"

#include <QEvent>
#include <QFileInfo>
#include <QGuiApplication>

namespace fieldsight::ui {

DiskWatch::DiskWatch(const MenuTarget& target, AnnotationsFile& annotations, SessionFiles& files,
                     OfferBar& bar)
    : QObject(target.parent), m_target(target), m_bar(bar)
{
    EditingSession& s = m_target.session;
    m_watched.push_back({tr("the annotations"),
                         [&s] { return s.annotations().path(); },
                         [&s] { return s.annotations().changedOnDisk(); },
                         [a = &annotations] { a->reload(); },
                         [] {},
                         {}});
    m_watched.push_back({tr("the LUT"),
                         [&s] { return s.lut().path(); },
                         [&s] { return s.lut().changedOnDisk(); },
                         [f = &files] { f->reloadLut(); },
                         [] {},
                         {}});
    m_watched.push_back({tr("the bookmarks"),
                         [&s] { return s.bookmarks().path(); },
                         [&s] { return s.bookmarks().changedOnDisk(); },
                         [this, &s] { say(s.bookmarks().reload()); },
                         [&s] { s.bookmarks().overwrite(); },
                         {}});
    m_watched.push_back({tr("the LUT samples"),
                         [&s] { return s.samples().path(); },
                         [&s] { return s.samples().changedOnDisk(); },
                         [this, &s] { say(s.samples().reload()); },
                         [&s] { s.samples().overwrite(); },
                         {}});

    connect(&m_bar, &OfferBar::accepted, this, &DiskWatch::reloadChanged);
    connect(&m_bar, &OfferBar::declined, this, &DiskWatch::keepMine);
    // Checked after the event that brought it: a save's own rename is remembered by then.
    const auto later = [this] {
        QMetaObject::invokeMethod(this, &DiskWatch::check, Qt::QueuedConnection);
    };
    connect(&m_files, &QFileSystemWatcher::fileChanged, this, later);
    connect(&m_files, &QFileSystemWatcher::directoryChanged, this, later);
    connect(qGuiApp, &QGuiApplication::applicationStateChanged, this,
            [later](Qt::ApplicationState state) {
                if (state == Qt::ApplicationActive)
                    later();
            });
    // Another window of this process activated and left: no application state change.
    m_target.parent->installEventFilter(this);
    connect(&s.stream(), &StreamDocument::streamChanged, this, &DiskWatch::watchPaths);
    connect(&s.lut(), &LutDocument::modifiedChanged, this, &DiskWatch::watchPaths);
    connect(&s.annotations(), &AnnotationsDocument::modifiedChanged, this, &DiskWatch::watchPaths);
}

bool DiskWatch::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_target.parent && event->type() == QEvent::WindowActivate)
        QMetaObject::invokeMethod(this, &DiskWatch::check, Qt::QueuedConnection);
    return false;
}

void DiskWatch::watchPaths()
{
    // The files and their folders: an atomic save replaces the file (a folder change), and a
    // file absent when read shows up only in its folder.
    QStringList paths;
    for (const Watched& w : m_watched) {
        const QString path = w.path();
        if (path.isEmpty())
            continue;
        if (localPathExists(path))
            paths << path;
        const QString folder = QFileInfo(path).absolutePath();
        if (isLocalFolder(folder))
            paths << folder;
    }
    paths.removeDuplicates();
    QStringList old = m_files.files() + m_files.directories();
    for (const QString& p : paths)
        old.removeAll(p);
    if (!old.isEmpty())
        m_files.removePaths(old);
    QStringList added;
    for (const QString& p : paths)
        if (!m_files.files().contains(p) && !m_files.directories().contains(p))
            added << p;
    if (!added.isEmpty())
        m_files.addPaths(added);
}

void DiskWatch::say(const Status& reloaded)
{
    if (!reloaded)
        m_target.showMessage(QString::fromStdString(reloaded.error().message));
}

bool DiskWatch::pending(const Watched& w) const
{
    return w.changed() && !(fingerprintFile(toLocalPath(w.path())) == w.declined);
}

QStringList DiskWatch::changed() const
{
    QStringList names;
    for (const Watched& w : m_watched)
        if (pending(w))
            names << w.name;
    return names;
}

void DiskWatch::check()
{
    watchPaths(); // a file made since is watched from now on
    OfferBar& bar = m_bar;
    QStringList names;
    QStringList files;
    for (const Watched& w : m_watched)
        if (pending(w)) {
            names << w.name;
            files << w.path();
        }
    if (names.isEmpty()) {
        bar.hide();
        return;
    }
    bar.offer(tr("Another window or a program changed %1 on disk since this window read them. "
                 "Reload drops this window's unsaved changes of them (Edit > Undo brings the "
                 "LUT's and the annotations' back); Keep mine keeps them (a save asks first).")
                  .arg(names.join(tr(", "))),
              files.join('\n'));
}

void DiskWatch::reloadChanged()
{
    for (Watched& w : m_watched)
        if (pending(w))
            w.reload();
    check();
}

void DiskWatch::keepMine()
{
    for (Watched& w : m_watched)
        if (pending(w)) {
            w.declined = fingerprintFile(toLocalPath(w.path()));
            w.keepMine();
        }
}

} // namespace fieldsight::ui
