// What the documents' recovery files share: the autosave that writes them, paths written so they
// are found again byte for byte, and fields read without ever throwing on a damaged file.
#pragma once

#include "visioncore/basics/result.h"

#include <QString>
#include <QStandardPaths>
#include <QTimer>
#include <QUndoStack>

#include <nlohmann/json.hpp>

#include <string>

namespace fieldsight::ui {

/// `meta[key]` when it is a string, else "" (a damaged recovery file is ignored, never thrown on).
std::string stringAt(const nlohmann::json& meta, const std::string& key);

/// A path in a recovery file: "<key>" for people (bad bytes shown as U+FFFD) and "<key>_bytes",
/// the file name's exact bytes percent-encoded, for finding it again.
void putPath(nlohmann::ordered_json& meta, const std::string& key, const QString& path);
QString pathAt(const nlohmann::json& meta, const std::string& key);

/// Now, as the recovery files' "saved_at" (ISO 8601, local time).
std::string recoveryTimestamp();

/// Where recovery files go unless a document is told otherwise: the app data folder.
inline QString defaultRecoveryDir()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
}

/// Wires `doc`'s autosave: `timer` fires once, 30 s (or its interval) after the first unsaved
/// edit, and writes the recovery file while `doc` is still modified (a failure goes to its
/// problem signal); undoing back to the saved state stops it and removes the recovery file.
template <class Document> void wireAutosave(Document& doc, QTimer& timer, QUndoStack& undo)
{
    timer.setSingleShot(true);
    timer.setInterval(30000);
    QObject::connect(&timer, &QTimer::timeout, &doc, [&doc] {
        if (!doc.modified())
            return;
        if (Status s = doc.writeRecovery(); !s)
            emit doc.problem(QString::fromStdString(s.error().message));
    });
    QObject::connect(&undo, &QUndoStack::cleanChanged, &doc, [&doc, &timer] {
        if (!doc.modified()) { // undone back to what was saved: nothing to recover
            timer.stop();
            doc.discardOwnRecovery();
        }
        emit doc.modifiedChanged(doc.modified());
    });
}

} // namespace fieldsight::ui
