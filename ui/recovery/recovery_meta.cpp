#include "ui/recovery/recovery_meta.h"

#include "ui/adapters/local_path.h"

#include <QByteArray>
#include <QDateTime>

namespace fieldsight::ui {

std::string stringAt(const nlohmann::json& meta, const std::string& key)
{
    const auto it = meta.find(key);
    return it != meta.end() && it->is_string() ? it->get<std::string>() : std::string();
}

void putPath(nlohmann::ordered_json& meta, const std::string& key, const QString& path)
{
    const std::string bytes = toLocalPath(path);
    meta[key] = bytes;
    meta[key + "_bytes"] = QByteArray::fromStdString(bytes).toPercentEncoding("/").toStdString();
}

QString pathAt(const nlohmann::json& meta, const std::string& key)
{
    if (const std::string encoded = stringAt(meta, key + "_bytes"); !encoded.empty())
        return fromLocalPath(
            QByteArray::fromPercentEncoding(QByteArray::fromStdString(encoded)).toStdString());
    return fromLocalPath(stringAt(meta, key));
}

std::string recoveryTimestamp()
{
    return QDateTime::currentDateTime().toString(Qt::ISODate).toStdString();
}

} // namespace fieldsight::ui
