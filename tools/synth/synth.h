// Deterministic scene generator: renders a kid-size field as a robot's head camera sees it and
// writes the frames with exact ground truth (SPEC §5.2), the kinematic horizon and an ideal LUT.
#pragma once

#include "visioncore/basics/result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fieldsight::synth {

/// The paper's five streams, modelled, and a crowded scene made to test on (not one of the
/// paper's): five robots around the ball, some close enough to the camera to fill the frame.
enum class Scenario { Lab1, Lab2, Difficult, RC2012, RC2013, Crowded };

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
    /// The light's colour temperature and level drift by this much (0..0.5) from the first frame
    /// to the last (ScenarioScript::setLightDrift); the truth is the same, and default.lut stays
    /// the ideal table of the first frame's light.
    double drift = 0;
    /// With a drift, default.lut is the ideal table of the light at this point of it instead
    /// (0: the first frame's, 1: the last frame's): the table made for a later frame's light.
    double table_light = 0;
    /// m, the camera's height above the carpet (the NAO's head, 0.45, by default; 0.3..0.7).
    double camera_height = 0.45;
};

/// "lab1", "lab2", "difficult", "rc2012", "rc2013", "crowded"
std::vector<std::string> scenarioNames();
Result<Scenario> scenarioFromName(const std::string& name);
std::string scenarioName(Scenario scenario);
/// Frame counts of the paper's streams: 5090 / 470 / 175 / 2640 / 625 (crowded: 300).
int paperFrameCount(Scenario scenario);

/// Renders the stream beside options.out_dir, then moves it in: into a new or empty folder, or
/// over synth's own earlier output where nothing it wrote was changed since and no file of the
/// user's would be replaced (synth/output_folder.h; files of the user's stay). Errors name the
/// path; `refused` (when given) is set when the folder's content was the reason (nothing in it
/// was touched), rather than the system.
Status generateStream(const SynthOptions& options, bool* refused = nullptr);

} // namespace fieldsight::synth
