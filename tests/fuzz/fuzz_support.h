// Shared by the fuzz targets. The readers take paths (their boundary checks the file's kind and
// size first), so each input is written to a file in a scratch folder and read back through the
// reader's public function.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace fieldsight::fuzz {

/// The process's scratch folder (under /dev/shm where it exists), made on first use and removed
/// at exit.
const std::string& scratchDir();

/// Writes `bytes` to `name` in the scratch folder (replacing it) and returns its path.
std::string writeInput(const std::string& name, const std::string& bytes);

/// For formats of one fixed size: the input repeated to exactly `target` bytes, so that mutations
/// reach the per-value checks instead of stopping at the size check.
std::string tiled(const std::uint8_t* data, std::size_t size, std::size_t target);

/// Opens `spec` as a stream and, when it opens, reads its first, second and last frames through
/// the StreamDataWrapper and runs the core on each, as `fieldsight run` would. Traps when a frame
/// that reads is not what the reader promised (CV_8UC3, non-empty), and when a library prints
/// through std::cerr meanwhile (the user must see Fieldsight's one line only).
void readStream(const std::string& spec);

} // namespace fieldsight::fuzz
