// The media module found beside the executable, as installed (FIELDSIGHT_MEDIA_RELDIR from the
// binary folder) or as built (lib/fieldsight in the build folder, one or two levels up).
#include "io/media.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/io/image_files.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>

#ifndef FIELDSIGHT_MEDIA_RELDIR
#define FIELDSIGHT_MEDIA_RELDIR "../lib/fieldsight"
#endif

namespace fieldsight::io {

namespace {

constexpr const char* kModuleFile = "libfieldsight_media.so";

Result<const MediaApi*> loadMediaApi()
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    const fs::path bin = ec ? fs::current_path(ec) : exe.parent_path();
    std::string looked;
    std::string why;
    for (const char* dir : {FIELDSIGHT_MEDIA_RELDIR, "../lib/fieldsight", "../../lib/fieldsight"}) {
        const fs::path candidate = (bin / dir / kModuleFile).lexically_normal();
        if (looked.find(candidate.string()) != std::string::npos)
            continue;
        looked += (looked.empty() ? "" : ", ") + candidate.string();
        if (!fs::exists(candidate, ec))
            continue;
        void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            why = dlerror();
            continue;
        }
        const auto entry = reinterpret_cast<MediaApiEntry>(dlsym(handle, kMediaApiSymbol));
        const MediaApi* api = entry ? entry() : nullptr;
        if (api && api->version == kMediaApiVersion)
            return api; // kept loaded for the process's life
        why = candidate.string() + " is not this build's media module";
        dlclose(handle);
    }
    return Error{"cannot load the media module " + std::string(kModuleFile) +
                 " (OpenCV's video and image codecs): " + (why.empty() ? "not found" : why) +
                 "; looked for " + looked};
}

} // namespace

Result<const MediaApi*> mediaApi()
{
    static std::once_flag once;
    static Result<const MediaApi*> api{Error{""}};
    std::call_once(once, [] { api = loadMediaApi(); });
    return api;
}

} // namespace fieldsight::io

namespace fieldsight {

Result<cv::Mat> decodeImage(const unsigned char* data, std::size_t size, int flags,
                            const std::string& source)
{
    auto api = io::mediaApi();
    if (!api)
        return Error{"cannot read " + source + ": " + api.error().message};
    cv::Mat out;
    std::string error;
    if (!api.value()->decode(data, size, flags, out, error))
        return Error{"cannot read " + source + ": the decoder failed (" + error + ")"};
    return out;
}

Result<std::vector<unsigned char>> encodeImage(const std::string& extension, const cv::Mat& image,
                                               const std::vector<int>& params)
{
    auto api = io::mediaApi();
    if (!api)
        return api.error();
    std::vector<unsigned char> out;
    std::string error;
    if (!api.value()->encode(extension.c_str(), image, params, out, error))
        return Error{"cannot encode " + extension + ": " + error};
    return out;
}

Result<cv::Mat> readImage(const std::string& path, int flags)
{
    auto bytes = readWholeFile(path); // a FIFO or a device is refused, not read
    if (!bytes)
        return bytes.error();
    if (bytes.value().empty())
        return Error{"cannot read " + path + ": the file is empty"};
    auto image = decodeImage(reinterpret_cast<const unsigned char*>(bytes.value().data()),
                             bytes.value().size(), flags, path);
    if (image && image.value().empty())
        return Error{"cannot read " + path + ": not a decodable image"};
    return image;
}

Status writeImage(const std::string& path, const cv::Mat& image, const std::vector<int>& params)
{
    auto bytes = encodeImage(std::filesystem::path(path).extension().string(), image, params);
    if (!bytes)
        return Error{path + ": " + bytes.error().message};
    return writeFileAtomically(path, bytes.value().data(), bytes.value().size());
}

Status writeVideo(const std::string& path, const std::string& fourcc, double fps,
                  const std::vector<cv::Mat>& frames)
{
    auto api = io::mediaApi();
    if (!api)
        return Error{path + ": " + api.error().message};
    std::string error;
    if (!api.value()->writeVideo(path.c_str(), fourcc.c_str(), fps, frames, error))
        return Error{path + ": cannot write the video: " + error};
    return {};
}

} // namespace fieldsight
