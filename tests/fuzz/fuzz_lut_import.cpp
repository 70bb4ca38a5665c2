// One colour-table format through importLut (built once per format; FUZZ_SUFFIX names it). For
// formats of a fixed size, an input whose first byte is odd is repeated to that size so that the
// per-cell checks are reached.
#include "fuzz_support.h"

#include "visioncore/io/lut_import.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace fieldsight;
    std::string bytes(reinterpret_cast<const char*>(data), size);
    if (FUZZ_FIXED_SIZE > 0 && size > 1 && (data[0] & 1))
        bytes = fuzz::tiled(data + 1, size - 1, FUZZ_FIXED_SIZE);
    const auto lut = importLut(fuzz::writeInput(std::string("table") + FUZZ_SUFFIX, bytes));
    if (lut) {
        // A table that loads must classify every cell as a known class.
        for (std::size_t i = 0; i < ColourLut::kCells; i += 4099)
            if (int(lut.value().cell(i)) >= kColourCount)
                __builtin_trap();
    }
    return 0;
}
