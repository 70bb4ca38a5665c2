// Importers for other teams' colour tables: B-Human .c64, rUNSWift .nnmc(.bz2), UPenn .raw.
#include "visioncore/io/lut_import.h"

#include "visioncore/basics/atomic_file.h"

#include <bzlib.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <memory>
#include <optional>
#include <utility>

namespace fieldsight {

namespace {

constexpr std::size_t kCells64 = 64 * 64 * 64;

std::string lowercase(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

bool endsWith(const std::string& s, std::string_view suffix)
{
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Fills a 128^3 table from a 64^3 one indexed (Y>>2)<<12 | (Cb>>2)<<6 | (Cr>>2): each source
/// cell covers 2 x 2 x 2 of ours.
ColourLut fromTable64(const std::array<Colour, kCells64>& table)
{
    ColourLut lut;
    for (std::size_t y = 0; y < 128; ++y)
        for (std::size_t cb = 0; cb < 128; ++cb)
            for (std::size_t cr = 0; cr < 128; ++cr)
                lut.setCell(y << 14 | cb << 7 | cr,
                            table[(y >> 1) << 12 | (cb >> 1) << 6 | (cr >> 1)]);
    return lut;
}

// --- B-Human 2009 coltable.c64 ----------------------------------------------------------------

/// B-Human 2009 ColorClasses: none, orange, yellow, blue, white, green, black, red, robotBlue.
constexpr std::array<Colour, 9> kBHumanClasses = {
    Colour::Unclassified, Colour::Orange,       Colour::Yellow, Colour::Blue,       Colour::White,
    Colour::Green,        Colour::ShadowObject, Colour::Pink,   Colour::ShadowBlue,
};

/// A class byte: a plain class 0-8, or with bit 0x80 a mask of several (bit k-1 = class k), of
/// which the most specific one wins (ball, goals, lines before the field).
std::optional<Colour> bhumanColour(std::uint8_t value)
{
    if (!(value & 0x80))
        return value < kBHumanClasses.size() ? std::optional(kBHumanClasses[value]) : std::nullopt;
    constexpr int kPriority[] = {1, 2, 3, 4, 5, 7, 8, 6}; // ball, goals, lines, field, robots
    for (int c : kPriority)
        if (value & (1u << (c - 1)))
            return kBHumanClasses[std::size_t(c)];
    return Colour::Unclassified;
}

Result<ColourLut> importC64(const std::string& path, const std::string& bytes)
{
    auto table = std::make_unique<std::array<Colour, kCells64>>();
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    std::size_t offset = 0;
    std::size_t filled = 0;
    for (;;) {
        if (offset + 4 > bytes.size())
            return Error{path + ": truncated at byte offset " + std::to_string(offset) +
                         " (expected a run length or the end marker)"};
        std::uint32_t run = 0;
        std::memcpy(&run, data + offset, 4); // little-endian, as written on x86
        if (run == 0) {
            offset += 4;
            break;
        }
        if (offset + 5 > bytes.size())
            return Error{path + ": truncated at byte offset " + std::to_string(offset + 4) +
                         " (run without a class byte)"};
        const std::uint8_t value = data[offset + 4];
        const auto colour = bhumanColour(value);
        if (!colour)
            return Error{path + ": unknown colour class " + std::to_string(int(value)) +
                         " at byte offset " + std::to_string(offset + 4)};
        if (run > kCells64 - filled)
            return Error{path + ": run-length data overruns the 64x64x64 table at byte offset " +
                         std::to_string(offset) + " (run of " + std::to_string(run) + " after " +
                         std::to_string(filled) + " cells)"};
        std::fill_n(table->begin() + std::ptrdiff_t(filled), run, *colour);
        filled += run;
        offset += 5;
    }
    if (filled != kCells64)
        return Error{path + ": run-length data ends after " + std::to_string(filled) + " of " +
                     std::to_string(kCells64) + " cells"};
    if (offset != bytes.size())
        return Error{path + ": " + std::to_string(bytes.size() - offset) +
                     " unexpected bytes after the end marker at byte offset " +
                     std::to_string(offset - 4)};
    return fromTable64(*table);
}

// --- rUNSWift 2014 .nnmc(.bz2) ----------------------------------------------------------------

/// rUNSWift Colour enum: 0 ball, 1 blue, 2 yellow, 3 (unused), 4 red robot, 5 field green,
/// 6 white, 7 black, 8 background, 9 unclassified, 10 body part.
constexpr std::array<Colour, 11> kRunswiftClasses = {
    Colour::Orange,       Colour::Blue,         Colour::Yellow,       Colour::Unclassified,
    Colour::Pink,         Colour::Green,        Colour::White,        Colour::ShadowObject,
    Colour::Unclassified, Colour::Unclassified, Colour::Unclassified,
};

Result<ColourLut> importNnmcTable(const std::string& path, const unsigned char* table,
                                  std::size_t size)
{
    if (size != ColourLut::kCells)
        return Error{path + ": wrong size: " + std::to_string(size) + " bytes" +
                     (endsWith(lowercase(path), ".bz2") ? " unpacked" : "") + ", expected " +
                     std::to_string(ColourLut::kCells) + " (128x128x128)"};
    ColourLut lut;
    // rUNSWift's index is (V>>1)<<14 | (U>>1)<<7 | (Y>>1): Cr slowest, Y fastest.
    for (std::size_t cr = 0; cr < 128; ++cr)
        for (std::size_t cb = 0; cb < 128; ++cb)
            for (std::size_t y = 0; y < 128; ++y) {
                const std::size_t source = cr << 14 | cb << 7 | y;
                const std::uint8_t value = table[source];
                if (value >= kRunswiftClasses.size())
                    return Error{path + ": unknown colour class " + std::to_string(int(value)) +
                                 " at offset " + std::to_string(source)};
                lut.setCell(y << 14 | cb << 7 | cr, kRunswiftClasses[value]);
            }
    return lut;
}

std::string bzip2Problem(int code)
{
    switch (code) {
    case BZ_DATA_ERROR_MAGIC:
        return "not bzip2 data";
    case BZ_DATA_ERROR:
        return "corrupt bzip2 data";
    case BZ_UNEXPECTED_EOF:
        return "truncated bzip2 data";
    case BZ_MEM_ERROR:
        return "out of memory while unpacking";
    default:
        return "bzip2 error " + std::to_string(code);
    }
}

Result<ColourLut> importNnmcBz2(const std::string& path, const std::string& bytes)
{
    // One byte of room beyond the expected size, so a larger table is detected as such.
    std::vector<char> unpacked(ColourLut::kCells + 1);
    unsigned int size = static_cast<unsigned int>(unpacked.size());
    const int code =
        BZ2_bzBuffToBuffDecompress(unpacked.data(), &size, const_cast<char*>(bytes.data()),
                                   static_cast<unsigned int>(bytes.size()), 0, 0);
    if (code == BZ_OUTBUFF_FULL)
        return Error{path + ": wrong size: more than " + std::to_string(ColourLut::kCells) +
                     " bytes unpacked, expected " + std::to_string(ColourLut::kCells) +
                     " (128x128x128)"};
    if (code != BZ_OK)
        return Error{path + ": " + bzip2Problem(code)};
    return importNnmcTable(path, reinterpret_cast<const unsigned char*>(unpacked.data()), size);
}

// --- UPennalizers 2012 .raw -------------------------------------------------------------------

Result<ColourLut> importUpennRaw(const std::string& path, const std::string& bytes)
{
    if (bytes.size() != kCells64)
        return Error{path + ": wrong size: " + std::to_string(bytes.size()) + " bytes, expected " +
                     std::to_string(kCells64) + " (64x64x64)"};
    // Bit flags; when several are set the most specific class wins.
    constexpr std::pair<std::uint8_t, Colour> kFlags[] = {
        {1, Colour::Orange}, {2, Colour::Yellow}, {4, Colour::Blue},
        {16, Colour::White}, {8, Colour::Green},
    };
    auto table = std::make_unique<std::array<Colour, kCells64>>();
    for (std::size_t i = 0; i < kCells64; ++i) {
        const auto value = static_cast<std::uint8_t>(bytes[i]);
        Colour colour = Colour::Unclassified;
        for (const auto& [flag, c] : kFlags)
            if (value & flag) {
                colour = c;
                break;
            }
        (*table)[i] = colour;
    }
    return fromTable64(*table);
}

} // namespace

std::vector<std::string_view> importableLutSuffixes()
{
    return {".lut", ".c64", ".nnmc.bz2", ".nnmc", ".raw"};
}

Result<ColourLut> importLut(const std::string& path)
{
    const std::string name = lowercase(path);
    if (endsWith(name, ".lut"))
        return ColourLut::load(path);
    const bool known = endsWith(name, ".c64") || endsWith(name, ".nnmc.bz2") ||
                       endsWith(name, ".nnmc") || endsWith(name, ".raw");
    // A folder, FIFO or device is refused as such first: the name is the smaller problem.
    if (struct stat st{}; !known && ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        return notARegularFile(path, st.st_mode);
    if (!known)
        return Error{path + ": unknown colour table format (expected .lut, .c64, .nnmc.bz2, "
                            ".nnmc or .raw)"};
    auto bytes = readWholeFile(path);
    if (!bytes)
        return bytes.error();
    if (endsWith(name, ".c64"))
        return importC64(path, bytes.value());
    if (endsWith(name, ".nnmc.bz2"))
        return importNnmcBz2(path, bytes.value());
    if (endsWith(name, ".nnmc"))
        return importNnmcTable(path, reinterpret_cast<const unsigned char*>(bytes.value().data()),
                               bytes.value().size());
    return importUpennRaw(path, bytes.value());
}

} // namespace fieldsight
