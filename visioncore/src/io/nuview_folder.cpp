// NUView log folders: which .strm of the folder is the image stream.
#include "io/nuview_folder.h"

#include "io/file_names.h"

#include <algorithm>
#include <string>
#include <system_error>
#include <vector>

namespace fieldsight::io {

namespace fs = std::filesystem;

std::optional<fs::path> findImageStrm(const fs::path& folder)
{
    std::vector<fs::path> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
        const std::string name = lowercase(entry.path().filename().string());
        if (name.size() >= 10 && name.compare(name.size() - 10, 10, "image.strm") == 0)
            found.push_back(entry.path());
    }
    if (found.empty())
        return std::nullopt;
    std::sort(found.begin(), found.end(), [](const fs::path& a, const fs::path& b) {
        return naturalLess(a.filename().string(), b.filename().string());
    });
    return found.front();
}

} // namespace fieldsight::io
