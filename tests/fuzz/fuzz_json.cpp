// The JSON documents Fieldsight reads, one target per document (FUZZ_DOCUMENT names it): each
// goes through its public parser, and what parses must write back and parse again to the same.
#include "visioncore/framework/param_set.h"
#include "visioncore/framework/controller.h"
#include "visioncore/io/annotations.h"
#include "visioncore/services/lut_building.h"
#include "visioncore/services/results_json.h"

#include "ui/document/bookmarks.h"

#include <cstdint>
#include <cstdio>
#include <string>

namespace {

using namespace fieldsight;

#define FUZZ_ANNOTATIONS 1
#define FUZZ_RESULTS 2
#define FUZZ_PARAMS 3
#define FUZZ_LUT_SAMPLES 4
#define FUZZ_BOOKMARKS 5

template <typename Parse, typename Write>
void roundTrip(const std::string& text, Parse parse, Write write)
{
    auto first = parse(text);
    if (!first)
        return;
    const std::string written = write(first.value());
    auto second = parse(written);
    if (!second) {
        std::fprintf(stderr, "written:\n%s\ndoes not read back: %s\n", written.c_str(),
                     second.error().message.c_str());
        __builtin_trap();
    }
    const std::string again = write(second.value());
    if (again != written) {
        std::fprintf(stderr, "written:\n%s\nwritten again:\n%s\n", written.c_str(), again.c_str());
        __builtin_trap();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
#if FUZZ_DOCUMENT == FUZZ_ANNOTATIONS
    roundTrip(
        text,
        [](const std::string& t) {
            return Annotations::fromJson(t, "annotations.json",
                                         Pipeline::standard().perceptKinds());
        },
        [](const Annotations& a) { return a.toJson(Pipeline::standard().perceptKinds()); });
#elif FUZZ_DOCUMENT == FUZZ_RESULTS
    roundTrip(
        text, [](const std::string& t) { return readResults(t, "results.json"); },
        [](const ResultsFile& r) {
            return resultsJson(r.header, r.frames, Pipeline::standard().ids());
        });
#elif FUZZ_DOCUMENT == FUZZ_PARAMS
    const auto params = ParamSet::fromJson(text, "params.json");
    if (params)
        (void)params.value().check(Pipeline::standard());
    roundTrip(
        text, [](const std::string& t) { return ParamSet::fromJson(t, "params.json"); },
        [](const ParamSet& p) { return p.toJson(); });
#elif FUZZ_DOCUMENT == FUZZ_LUT_SAMPLES
    roundTrip(
        text, [](const std::string& t) { return lutSamplesFromJson(t, "lut_samples.json"); },
        [](const LutSamples& s) { return lutSamplesToJson(s); });
#elif FUZZ_DOCUMENT == FUZZ_BOOKMARKS
    roundTrip(
        text, [](const std::string& t) { return ui::Bookmarks::fromJson(t, "bookmarks.json"); },
        [](const ui::Bookmarks& b) { return b.toJson(); });
#else
#error "FUZZ_DOCUMENT names no document"
#endif
    return 0;
}
