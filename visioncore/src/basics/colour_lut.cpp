// The native .lut format (SPEC §3): 2,097,152 raw colour ids, validated on load, saved atomically.
#include "visioncore/basics/colour_lut.h"

#include "visioncore/basics/atomic_file.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__unix__)
#include <sys/mman.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <new>
#include <system_error>

namespace fieldsight {

namespace {

std::uint64_t newContent()
{
    static std::atomic<std::uint64_t> next{1};
    return next.fetch_add(1, std::memory_order_relaxed);
}

/// `__restrict`: the class bytes written never alias the pixels or the table, so the compiler need
/// not reload them after every store (uint8_t pointers may alias anything).
void lookupRun(const std::uint8_t* __restrict cells, const std::uint8_t* __restrict px,
               std::ptrdiff_t stride, int count, std::uint8_t* __restrict out)
{
#pragma GCC unroll 4
    for (int i = 0; i < count; ++i, px += stride)
        out[i] = cells[ColourLut::index(px[0], px[1], px[2])];
}

/// lookupRun through an input map's memo: the same loop over a table of class | kKnown bytes, 0
/// where the cell has not been read through the map yet. Relaxed loads: other threads may be
/// filling the memo (with the same values).
void memoRun(const std::uint8_t* __restrict memo, const std::uint8_t* __restrict px,
             std::ptrdiff_t stride, int count, std::uint8_t* __restrict out)
{
#pragma GCC unroll 4
    for (int i = 0; i < count; ++i, px += stride)
        out[i] = __atomic_load_n(memo + ColourLut::index(px[0], px[1], px[2]), __ATOMIC_RELAXED);
}

/// Whether every byte is a colour id (0 .. kColourCount - 1): eight bytes a step, adding to each
/// what takes an id past the last to 128 and looking at the top bits (a byte of 128 or more is
/// caught by its own top bit, whatever its sum carries into the next). 2 MB in about 1.3 M
/// instructions, where a byte-wise maximum took 14.7 M (every table loaded).
bool allValidColourIds(const std::uint8_t* bytes, std::size_t size)
{
    constexpr std::uint64_t kOnes = 0x0101010101010101ull;
    constexpr std::uint64_t kLift = kOnes * std::uint64_t(128 - kColourCount);
    constexpr std::uint64_t kTops = kOnes * 0x80;
    std::size_t i = 0;
    std::uint64_t tops = 0;
    for (; i + 8 <= size; i += 8) {
        std::uint64_t w;
        std::memcpy(&w, bytes + i, 8);
        tops |= (w + kLift) | w;
    }
    if (tops & kTops)
        return false;
    for (; i < size; ++i)
        if (!isValidColourId(bytes[i]))
            return false;
    return true;
}

} // namespace

ColourLut::ColourLut()
    : m_cells(kCells, std::uint8_t(Colour::Unclassified)), m_content(newContent())
{
}

ColourLut::ColourLut(std::vector<std::uint8_t> cells)
    : m_cells(std::move(cells)), m_content(newContent())
{
}

/// The memo of a table through a map: one byte per cell, in zeroed pages mapped from the system
/// (not calloc, which clears 2 MiB by hand once the allocator has pages to reuse): a page costs
/// time and memory only once a pixel reads one of its cells.
struct ColourLut::MapMemo
{
    MapMemo()
    {
#if defined(__unix__)
        void* p = mmap(nullptr, kCells, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        bytes = p == MAP_FAILED ? nullptr : static_cast<std::uint8_t*>(p);
#else
        bytes = static_cast<std::uint8_t*>(std::calloc(kCells, 1));
#endif
        if (!bytes)
            throw std::bad_alloc();
    }
    ~MapMemo()
    {
#if defined(__unix__)
        munmap(bytes, kCells);
#else
        std::free(bytes);
#endif
    }
    MapMemo(const MapMemo&) = delete;
    MapMemo& operator=(const MapMemo&) = delete;

    /// The memo of `content` through `map`: one made lately for them, or a new one. The tracker
    /// classifying its samples and every worker running the frame read the same cells.
    static std::shared_ptr<MapMemo> of(std::uint64_t content,
                                       const std::shared_ptr<const LutInputMap>& map)
    {
        static std::mutex mutex;
        static std::array<std::weak_ptr<MapMemo>, 8> recent;
        // The last few memos are kept even when no table holds them: a light that moves back to
        // a map it left a frame ago (a state on a key's edge) reads its cells again, not afresh.
        // Their memory is the pages their frames read, at most 2 MiB each.
        static std::array<std::shared_ptr<MapMemo>, 4> kept;
        static std::size_t next = 0;
        std::lock_guard lock(mutex);
        for (const std::weak_ptr<MapMemo>& made : recent)
            if (auto memo = made.lock(); memo && memo->content == content && memo->map == map)
                return memo;
        auto memo = std::make_shared<MapMemo>();
        memo->content = content;
        memo->map = map; // kept alive, so that no other map is made at its address meanwhile
        recent[next % recent.size()] = memo;
        kept[next % kept.size()] = memo;
        ++next;
        return memo;
    }

    std::uint8_t* bytes;
    std::uint64_t content = 0;
    std::shared_ptr<const LutInputMap> map;
};

void ColourLut::setInputMap(std::shared_ptr<const LutInputMap> map)
{
    if (map == m_map && (m_memo || !map))
        return;
    if (!m_content)
        m_content = newContent();
    m_map = std::move(map);
    m_memo = m_map ? MapMemo::of(m_content, m_map) : nullptr;
    m_memo_cells = m_memo ? m_memo->bytes : nullptr;
}

const std::uint8_t* ColourLut::noMemoCells()
{
    // Zero pages mapped read-only: reading them costs no memory.
    static const std::uint8_t* const cells = [] {
#if defined(__unix__)
        void* p = mmap(nullptr, kCells, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED)
            throw std::bad_alloc();
        return static_cast<const std::uint8_t*>(p);
#else
        static const std::vector<std::uint8_t> zeros(kCells, 0);
        return zeros.data();
#endif
    }();
    return cells;
}

void ColourLut::setCell(std::size_t i, Colour colour)
{
    m_cells[i] = std::uint8_t(colour);
    m_content = 0;
    if (m_memo) {
        m_memo.reset();
        m_memo_cells = noMemoCells();
    }
}

std::uint8_t ColourLut::fillMemo(std::size_t i) const
{
    const std::uint8_t c = readThroughMap(i);
    if (m_memo)
        __atomic_store_n(m_memo->bytes + i, std::uint8_t(c | kKnown), __ATOMIC_RELAXED);
    return c;
}

void ColourLut::classifyRun(const std::uint8_t* px, std::ptrdiff_t stride, int count,
                            std::uint8_t* out) const
{
    if (!m_map) {
        lookupRun(m_cells.data(), px, stride, count, out);
        return;
    }
    memoRun(m_memo_cells, px, stride, count, out);
    // Then the cells read for the first time (16 bytes at a time: most runs have none), and the
    // kKnown bit off.
    int i = 0;
#if defined(__SSE2__)
    const __m128i zero = _mm_setzero_si128();
    const __m128i low = _mm_set1_epi8(char(~kKnown));
    // The 16 bytes from `at`, those of `mask` looked at: the first reads filled, the bit off.
    const auto sixteen = [&](int at, unsigned mask) {
        __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(out + at));
        unsigned unknown = unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(v, zero))) & mask;
        if (unknown) {
            do {
                const int k = at + __builtin_ctz(unknown);
                out[k] = knownOrFilled(px + k * stride);
                unknown &= unknown - 1;
            } while (unknown);
            v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(out + at));
        }
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + at), _mm_and_si128(v, low));
    };
    for (; i + 16 <= count; i += 16)
        sixteen(i, 0xFFFFu);
    // The last bytes as the 16 that end the run: those already done have no kKnown bit, so only
    // the new ones are looked at, and taking the bit off again leaves the others as they are.
    if (i < count && count >= 16) {
        sixteen(count - 16, 0xFFFFu << unsigned(i - (count - 16)));
        i = count;
    }
#endif
    for (; i < count; ++i)
        out[i] = std::uint8_t((out[i] ? out[i] : knownOrFilled(px + i * stride)) & ~kKnown);
}

void ColourLut::classifyImage(const cv::Mat& ycbcr, cv::Mat& classes) const
{
    CV_Assert(ycbcr.type() == CV_8UC3);
    classes.create(ycbcr.rows, ycbcr.cols, CV_8UC1);
    for (int y = 0; y < ycbcr.rows; ++y)
        classifyRun(ycbcr.ptr<std::uint8_t>(y), 3, ycbcr.cols, classes.ptr<std::uint8_t>(y));
}

Result<ColourLut> ColourLut::fromBytes(std::vector<std::uint8_t> bytes, const std::string& source)
{
    if (bytes.size() != kCells)
        return Error{source + ": wrong size: " + std::to_string(bytes.size()) +
                     " bytes, expected " + std::to_string(kCells) + " (128x128x128)"};
    // Whether any id is bad first, eight cells a step; the first bad cell only when there is one.
    if (!allValidColourIds(bytes.data(), bytes.size())) {
        const auto bad = std::find_if(bytes.begin(), bytes.end(),
                                      [](std::uint8_t v) { return !isValidColourId(v); });
        const auto count =
            std::count_if(bad, bytes.end(), [](std::uint8_t v) { return !isValidColourId(v); });
        return Error{source + ": invalid colour id " + std::to_string(int(*bad)) + " at offset " +
                     std::to_string(bad - bytes.begin()) + " (ids are 0-10; " +
                     std::to_string(count) + " bad cells)"};
    }
    return ColourLut(std::move(bytes));
}

Result<ColourLut> ColourLut::load(const std::string& path)
{
    // Check the size before reading, so that pointing at a huge file fails fast.
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size != kCells)
        return Error{path + ": wrong size: " + std::to_string(size) + " bytes, expected " +
                     std::to_string(kCells) + " (128x128x128)"};
    auto text = readWholeFile(path);
    if (!text)
        return text.error();
    const std::string& s = text.value();
    std::vector<std::uint8_t> bytes(s.size());
    std::memcpy(bytes.data(), s.data(), s.size());
    return fromBytes(std::move(bytes), path);
}

Status ColourLut::save(const std::string& path) const
{
    return writeFileAtomically(path, m_cells.data(), m_cells.size());
}

} // namespace fieldsight
