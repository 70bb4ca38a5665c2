// File names between the operating system's bytes and QString without loss. Linux names are bytes,
// not always UTF-8; Qt decodes a bad byte as U+FFFD, so "caf\xe9" would open "caf\xef\xbf\xbd".
// Here each byte that is not part of valid UTF-8 becomes the lone surrogate U+DC80..U+DCFF (as
// Python's surrogateescape does) and turns back into the same byte on the way out.
#pragma once

#include <QString>
#include <QStringList>

#include <string>
#include <string_view>

namespace fieldsight::ui {

/// `bytes` as a QString: valid UTF-8 decoded, any other byte b kept as U+DC00 + b.
QString fromLocalPath(std::string_view bytes);
/// The bytes fromLocalPath() came from (other text: UTF-8).
std::string toLocalPath(const QString& path);
/// Whether something exists at `path`'s exact bytes (QFileInfo would ask about its UTF-8 form).
bool localPathExists(const QString& path);
/// Whether `path` is a folder, by its exact bytes.
bool isLocalFolder(const QString& path);
/// Makes the folder `path` and its parents, by its exact bytes; false if it cannot.
bool makeLocalFolder(const QString& path);
/// argv[0..argc) through fromLocalPath(), in place of Qt's lossy decoding.
QStringList argumentsOf(int argc, char** argv);

} // namespace fieldsight::ui
