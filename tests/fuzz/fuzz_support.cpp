#include "fuzz_support.h"

#include "visioncore/basics/colour_lut.h"
#include "visioncore/framework/control_wrapper.h"
#include "visioncore/datawrappers/stream_data_wrapper.h"
#include "visioncore/io/stream_reader.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace fieldsight::fuzz {

namespace {

/// Every class in bands of Y and Cb, so that decoded frames reach every stage.
std::shared_ptr<const ColourLut> bandedLut()
{
    static const auto lut = [] {
        auto table = std::make_shared<ColourLut>();
        for (std::size_t i = 0; i < ColourLut::kCells; ++i)
            table->setCell(i, Colour(((i >> 14) / 12 + (i >> 7 & 127) / 40) % kColourCount));
        return std::shared_ptr<const ColourLut>(table);
    }();
    return lut;
}

/// readStream without the check of what is printed.
void readFrames(const std::string& spec)
{
    auto reader = openStream(spec);
    if (!reader)
        return;
    const std::size_t count = reader.value()->info().frame_count;
    StreamDataWrapper data(std::move(reader).value(), bandedLut());
    ControlWrapper core(data);
    for (std::size_t index : {std::size_t(0), std::size_t(1), count - 1}) {
        if (index >= count || !data.seek(index))
            continue;
        const cv::Mat& image = data.image();
        if (image.empty() || image.type() != CV_8UC3)
            __builtin_trap();
        (void)core.runFrame();
    }
}

void removeScratch()
{
    std::error_code ignored;
    std::filesystem::remove_all(scratchDir(), ignored);
}

} // namespace

const std::string& scratchDir()
{
    // Never destroyed: removeScratch() reads it at exit, after static destructors may have run.
    static const std::string& dir = *new std::string([] {
        std::string pattern =
            std::filesystem::is_directory("/dev/shm")
                ? "/dev/shm/fieldsight-fuzz-XXXXXX"
                : (std::filesystem::temp_directory_path() / "fieldsight-fuzz-XXXXXX").string();
        if (!::mkdtemp(pattern.data()))
            throw std::runtime_error("cannot make a scratch folder for the fuzz inputs");
        std::atexit(removeScratch);
        return pattern;
    }());
    return dir;
}

std::string writeInput(const std::string& name, const std::string& bytes)
{
    const std::string path = scratchDir() + "/" + name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    return path;
}

std::string tiled(const std::uint8_t* data, std::size_t size, std::size_t target)
{
    std::string out(target, '\0');
    if (size == 0 || target == 0)
        return out;
    // One copy of the input, then the filled part doubles: log2(target / size) block copies, so
    // the loop costs almost nothing next to the reader it feeds.
    std::size_t filled = std::min(size, target);
    std::memcpy(out.data(), data, filled);
    while (filled < target) {
        const std::size_t block = std::min(filled, target - filled);
        std::memcpy(out.data() + filled, out.data(), block);
        filled += block;
    }
    return out;
}

void readStream(const std::string& spec)
{
    // What the libraries print through std::cerr (OpenCV's decoders do on damaged images) is
    // kept and makes a crash: the user must see Fieldsight's one line, not theirs.
    std::ostringstream printed;
    std::streambuf* const console = std::cerr.rdbuf(printed.rdbuf());
    readFrames(spec);
    std::cerr.rdbuf(console);
    if (!printed.str().empty()) {
        std::cerr << "printed on stderr while reading " << spec << ":\n" << printed.str();
        __builtin_trap();
    }
}

} // namespace fieldsight::fuzz
