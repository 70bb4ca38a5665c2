// The NUbots image stream (.strm): its index, its records and the frames decoded from them.
#include "fuzz_support.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace fieldsight;
    fuzz::readStream(
        fuzz::writeInput("image.strm", std::string(reinterpret_cast<const char*>(data), size)));
    return 0;
}
