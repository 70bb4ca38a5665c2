// Deterministic scene generator: renders a kid-size field as a robot's head camera sees it and
// writes the frames with exact ground truth (SPEC §5.2), the kinematic horizon and an ideal LUT.
#pragma once

#include "visioncore/basics/result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fieldsight::synth {

/// The paper's five streams, modelled.
enum class Scenario { Lab1, Lab2, Difficult, RC2012, RC2013 };

struct SynthOptions
{
    Scenario scenario = Scenario::Lab2;
    int frames = 30;        ///< number of frames to render
    std::uint64_t seed = 1; ///< same seed, same bytes
    /// Stream folder to create (frames, stream.json, default.lut, annotations.json).
    std::string out_dir;
    int width = 320;         ///< px
    int height = 240;        ///< px
    bool write_strm = false; ///< also write <out_dir>/image.strm with the same frames (YCbCr)
    bool write_png = true;   ///< write the PNG frames and stream.json (annotations are keyed
                             ///< by the PNG names either way)
};

std::vector<std::string> scenarioNames(); ///< "lab1", "lab2", "difficult", "rc2012", "rc2013"
Result<Scenario> scenarioFromName(const std::string& name);
std::string scenarioName(Scenario scenario);
/// Frame counts of the paper's streams: 5090 / 470 / 175 / 2640 / 625.
int paperFrameCount(Scenario scenario);

/// Renders the stream into options.out_dir (created if needed, or empty, or an earlier synth
/// output, which is replaced whole; any other folder is refused). Errors name the path.
Status generateStream(const SynthOptions& options);
/// Makes `folder` ready for a new stream: nothing to do when it is missing or empty; an earlier
/// synth output loses its files; anything else is an Error naming it (nothing is removed).
Status clearEarlierOutput(const std::string& folder);

} // namespace fieldsight::synth
