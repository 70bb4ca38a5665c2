// What the window remembers between sessions, read and written in this one place (QSettings):
// its geometry and docks, the view's layers and mode, playback, the recent streams, the last
// stream and table, and the LUT tools' settings.
#pragma once

#include "visioncore/services/layers.h"
#include "visioncore/services/lut_editing.h"
#include "visioncore/services/param_tuning.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <optional>

namespace fieldsight::ui {

struct WindowSettings
{
    QByteArray geometry; ///< empty on the first run
    QByteArray state;
    std::optional<LayerSet> layers; ///< none: the pipeline's defaults
    int mode = 0;                   ///< a ViewMode
    bool labels = true;
    bool follow_light = false; ///< View > Follow the light
    int fps = 30;
    bool loop = false;
    QStringList recent;       ///< newest first
    QList<int> recent_frames; ///< the frame each recent stream was last on
    QString stream;           ///< the last session's stream (empty: none)
    QString lut;              ///< and its table (empty: the stream's own)
    QString tool;             ///< the active tool's id
    Tolerance tolerance{8, 4, 4};
    int brush_radius = 2;
    bool keep_others = false;
    bool soft_classes = false;
    bool preview = true;
    int propagate_frames = 10; ///< how far the last propagation of an object went
    int fit_budget =
        kDefaultTuneBudget; ///< the evaluations Pipeline > Fit to annotations was given last
    /// Why the settings were not read (the window then starts with its defaults), or empty.
    QString problem;

    /// Never waits: a settings file that is a FIFO or a device (which reading would wait on,
    /// keeping the window from ever appearing) is left alone, and `problem` says so.
    static WindowSettings load();
    /// Not when the settings file is not a regular file (nothing is written over it).
    void save() const;
    /// Why the settings file (or one QSettings would also read) cannot be used, or empty.
    static QString unusableFile();
};

} // namespace fieldsight::ui
