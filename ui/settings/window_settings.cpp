#include "ui/settings/window_settings.h"

#include "ui/adapters/local_path.h"
#include "visioncore/basics/atomic_file.h"

#include <QCoreApplication>
#include <QSettings>
#include <QStandardPaths>

#include <algorithm>

#include <sys/stat.h>

namespace fieldsight::ui {

namespace {

/// A path as a setting: its exact bytes, since settings files store text as UTF-8.
QVariant pathSetting(const QString& path)
{
    return QByteArray::fromStdString(toLocalPath(path));
}

/// A path read back from pathSetting() (or a plain string, as older settings hold it).
QString pathFromSetting(const QVariant& value)
{
    return value.typeId() == QMetaType::QByteArray
               ? fromLocalPath(value.toByteArray().toStdString())
               : value.toString();
}

} // namespace

QString WindowSettings::unusableFile()
{
    // The files QSettings reads for this application, user's and system's, as
    // QSettings::NativeFormat names them on Unix (<config>/<organisation>/<application>.conf and
    // <config>/<organisation>.conf): checked before QSettings opens one, since opening a FIFO
    // waits for a writer.
    const QString organisation = QCoreApplication::organizationName();
    const QString application = QCoreApplication::applicationName();
    QStringList names{organisation + QStringLiteral(".conf")};
    if (!application.isEmpty())
        names.prepend(organisation + QLatin1Char('/') + application + QStringLiteral(".conf"));
    for (const QString& folder :
         QStandardPaths::standardLocations(QStandardPaths::GenericConfigLocation)) {
        for (const QString& name : names) {
            const QString path = folder + QLatin1Char('/') + name;
            struct stat st
            {
            };
            if (::stat(toLocalPath(path).c_str(), &st) == 0 && !S_ISREG(st.st_mode))
                return QCoreApplication::translate("WindowSettings",
                                                   "The settings file %1 is %2, not a regular "
                                                   "file; the window starts with its defaults "
                                                   "and does not save its settings")
                    .arg(path, QString::fromStdString(fileKindName(st.st_mode)));
        }
    }
    return {};
}

WindowSettings WindowSettings::load()
{
    WindowSettings w;
    w.problem = unusableFile();
    if (!w.problem.isEmpty())
        return w;
    const QSettings s;
    w.geometry = s.value(QStringLiteral("window/geometry")).toByteArray();
    w.state = s.value(QStringLiteral("window/state")).toByteArray();
    if (s.contains(QStringLiteral("view/layers"))) {
        LayerSet layers;
        for (const QString& id : s.value(QStringLiteral("view/layers")).toStringList())
            layers.insert(id.toStdString());
        w.layers = std::move(layers);
    }
    w.mode = std::clamp(s.value(QStringLiteral("view/mode"), 0).toInt(), 0, 3);
    w.labels = s.value(QStringLiteral("view/labels"), true).toBool();
    w.follow_light = s.value(QStringLiteral("view/follow_light"), false).toBool();
    w.fps = s.value(QStringLiteral("play/fps"), 30).toInt();
    w.loop = s.value(QStringLiteral("play/loop"), false).toBool();
    for (const QVariant& path : s.value(QStringLiteral("recent/streams")).toList())
        w.recent << pathFromSetting(path);
    for (const QVariant& frame : s.value(QStringLiteral("recent/frames")).toList())
        w.recent_frames << std::max(0, frame.toInt());
    w.stream = pathFromSetting(s.value(QStringLiteral("session/stream")));
    w.lut = pathFromSetting(s.value(QStringLiteral("session/lut")));
    w.tool = s.value(QStringLiteral("tools/active")).toString();
    w.tolerance = {s.value(QStringLiteral("tools/tolerance_y"), 8).toInt(),
                   s.value(QStringLiteral("tools/tolerance_cb"), 4).toInt(),
                   s.value(QStringLiteral("tools/tolerance_cr"), 4).toInt()};
    w.brush_radius = s.value(QStringLiteral("tools/brush_radius"), 2).toInt();
    w.keep_others = s.value(QStringLiteral("tools/keep_others"), false).toBool();
    w.propagate_frames =
        std::clamp(s.value(QStringLiteral("tools/propagate_frames"), 10).toInt(), 1, 100000);
    w.fit_budget = std::clamp(
        s.value(QStringLiteral("pipeline/fit_budget"), kDefaultTuneBudget).toInt(), 10, 100000);
    w.soft_classes = s.value(QStringLiteral("tools/soft_classes"), false).toBool();
    w.preview = s.value(QStringLiteral("tools/preview"), true).toBool();
    return w;
}

void WindowSettings::save() const
{
    if (!unusableFile().isEmpty())
        return;
    QSettings s;
    s.setValue(QStringLiteral("window/geometry"), geometry);
    s.setValue(QStringLiteral("window/state"), state);
    if (layers) {
        QStringList list;
        for (const std::string& id : *layers)
            list << QString::fromStdString(id);
        s.setValue(QStringLiteral("view/layers"), list);
    }
    s.setValue(QStringLiteral("view/mode"), mode);
    s.setValue(QStringLiteral("view/labels"), labels);
    s.setValue(QStringLiteral("view/follow_light"), follow_light);
    s.setValue(QStringLiteral("play/fps"), fps);
    s.setValue(QStringLiteral("play/loop"), loop);
    QVariantList paths;
    for (const QString& path : recent)
        paths << pathSetting(path);
    s.setValue(QStringLiteral("recent/streams"), paths);
    QVariantList frames;
    for (int frame : recent_frames)
        frames << frame;
    s.setValue(QStringLiteral("recent/frames"), frames);
    if (!stream.isEmpty()) {
        s.setValue(QStringLiteral("session/stream"), pathSetting(stream));
        s.setValue(QStringLiteral("session/lut"), pathSetting(lut));
    }
    s.setValue(QStringLiteral("tools/active"), tool);
    s.setValue(QStringLiteral("tools/tolerance_y"), tolerance.y);
    s.setValue(QStringLiteral("tools/tolerance_cb"), tolerance.cb);
    s.setValue(QStringLiteral("tools/tolerance_cr"), tolerance.cr);
    s.setValue(QStringLiteral("tools/brush_radius"), brush_radius);
    s.setValue(QStringLiteral("tools/keep_others"), keep_others);
    s.setValue(QStringLiteral("tools/propagate_frames"), propagate_frames);
    s.setValue(QStringLiteral("pipeline/fit_budget"), fit_budget);
    s.setValue(QStringLiteral("tools/soft_classes"), soft_classes);
    s.setValue(QStringLiteral("tools/preview"), preview);
}

} // namespace fieldsight::ui
