// The automatic first table (lut_auto.h). Placeholder while the method is written: it reads the
// frames and leaves the table empty, so callers can be built against the interface.
#include "visioncore/services/lut_auto.h"

namespace fieldsight {

Result<AutoLut> buildAutoLut(StreamReader& reader, const AutoLutOptions& options,
                             const AutoLutProgress& progress)
{
    AutoLut out;
    const std::size_t total = reader.info().frame_count;
    const std::size_t n = options.frames == 0 ? total : std::min(total, options.frames);
    for (std::size_t i = 0; i < n; ++i) {
        auto frame = reader.read(i * total / std::max<std::size_t>(n, 1));
        if (!frame)
            return frame.error();
        ++out.frames;
        if (progress && !progress(i + 1, n)) {
            out.cancelled = true;
            break;
        }
    }
    out.notes.push_back("the automatic table is not written yet");
    return out;
}

} // namespace fieldsight
