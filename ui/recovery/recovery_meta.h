// What the documents' recovery files share (Document runs the autosave that writes them): paths
// written so they are found again byte for byte, and fields read without ever throwing on a
// damaged file.
#pragma once

#include <QString>
#include <QStandardPaths>

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

} // namespace fieldsight::ui
