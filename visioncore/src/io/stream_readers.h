// The concrete stream readers behind openStream(): one factory per kind of source.
#pragma once

#include "visioncore/io/stream_reader.h"

#include <memory>
#include <string>

namespace fieldsight::io {

using ReaderResult = Result<std::unique_ptr<StreamReader>>;

/// A reader that decodes into the caller's frame: read() is readInto() into a new one.
class InPlaceReader : public StreamReader
{
public:
    Result<Frame> read(std::size_t index) final;
    Status readInto(std::size_t index, Frame& frame) override = 0;
};

/// A folder of .png/.jpg/.jpeg/.bmp frames with an optional stream.json manifest.
ReaderResult openImageFolder(const std::string& folder, const std::string& spec);
/// An original NUbots image stream (.strm), indexed on open; pixels are read on demand.
ReaderResult openStrm(const std::string& path, const std::string& spec);
/// A video file, random access by frame number.
ReaderResult openVideo(const std::string& path, const std::string& spec);
/// A live camera, read sequentially.
ReaderResult openCamera(int device, const std::string& spec);

/// `spec` as stored: the pictures as they are in the files, unturned (openStream without the
/// orientation).
ReaderResult openStored(const std::string& spec);
/// `stored` serving its frames, and their horizons, turned by `orientation` (its info says so,
/// with the size turned).
std::unique_ptr<StreamReader> orientReader(std::unique_ptr<StreamReader> stored,
                                           Orientation orientation);

/// Largest accepted frame side, px. Bigger (or zero) sizes mean a corrupt or wrong file.
inline constexpr int kMaxFrameSide = 8192;
inline bool isSaneFrameSize(long long width, long long height)
{
    return width > 0 && height > 0 && width <= kMaxFrameSide && height <= kMaxFrameSide;
}

/// "frame_000042", the name of frames that have no file of their own.
std::string indexedFrameName(std::size_t index);

} // namespace fieldsight::io
