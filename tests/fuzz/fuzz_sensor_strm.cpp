// The sensor stream recorded beside a .strm (its Horizon sensor).
#include "fuzz_support.h"

#include "io/sensor_strm.h"

#include <cmath>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace fieldsight;
    const auto horizons = io::readSensorHorizons(
        fuzz::writeInput("sensor.strm", std::string(reinterpret_cast<const char*>(data), size)),
        320, 64);
    if (horizons) {
        if (horizons.value().size() > 64)
            __builtin_trap();
        for (const auto& horizon : horizons.value())
            if (horizon && !(std::isfinite(horizon->y_left) && std::isfinite(horizon->y_right)))
                __builtin_trap();
    }
    return 0;
}
