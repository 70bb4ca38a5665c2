// Noticing, while the window is open, that another window or a program wrote a file of an open
// document (the annotations, the LUT, the bookmarks, the LUT samples): when the window or the
// application is activated again or the file system says a file or its folder changed, a bar above
// the view offers to reload it. Keeping one's own leaves the annotations and the LUT to ask again
// at the next save; the bookmarks and samples (saved at every change) are then written over.
#pragma once

#include "ui/actions/menus.h"
#include "visioncore/basics/file_fingerprint.h"
#include "visioncore/basics/result.h"

#include <QFileSystemWatcher>
#include <QObject>
#include <QStringList>

#include <functional>
#include <vector>

namespace fieldsight::ui {

class AnnotationsFile;
class OfferBar;
class SessionFiles;

class DiskWatch : public QObject
{
    Q_OBJECT
public:
    /// Reloads through `annotations` and `files` (which ask and report as File > Save does),
    /// offers in `bar`, and looks again whenever `target`'s window is activated.
    DiskWatch(const MenuTarget& target, AnnotationsFile& annotations, SessionFiles& files,
              OfferBar& bar);

    /// Looks at every document's file now: offers to reload those changed and not yet declined.
    void check();
    /// The files changed on disk, as the bar names them.
    QStringList changed() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct Watched
    {
        QString name;                   ///< as the bar says it ("the annotations")
        std::function<QString()> path;  ///< the document's file
        std::function<bool()> changed;  ///< changed on disk since read or saved
        std::function<void()> reload;   ///< Reload chosen
        std::function<void()> keepMine; ///< Keep mine chosen
        FileFingerprint declined;       ///< the change the user chose to keep theirs over
    };
    bool pending(const Watched& w) const;
    /// A reload that could not read the file says why in the window.
    void say(const Status& reloaded);
    void reloadChanged();
    void keepMine();
    void watchPaths();

    MenuTarget m_target;
    OfferBar& m_bar;
    std::vector<Watched> m_watched;
    QFileSystemWatcher m_files;
};

} // namespace fieldsight::ui
