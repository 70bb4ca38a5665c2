// NUView log folders: a folder of no images that holds the robot's image stream as a .strm file.
#pragma once

#include <filesystem>
#include <optional>

namespace fieldsight::io {

/// A NUView log folder holds "image.strm" or "N_image.strm"; the first such file, if any.
std::optional<std::filesystem::path> findImageStrm(const std::filesystem::path& folder);

} // namespace fieldsight::io
