// An automatic first colour table from a stream's frames alone (issue 33): the carpet as the
// dominant chroma cluster low in the frames, white as bright low-chroma pixels in thin runs on the
// carpet, then the saturated clusters told apart by hue and by what their pixels form (a round
// blob on the carpet is the ball, bars standing on the field's edge a goal). Contested cells stay
// unclassified. Shared by `fieldsight lut auto` and the window's Calibrate menu.
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/basics/colour_lut.h"
#include "visioncore/basics/result.h"
#include "visioncore/framework/controller.h"
#include "visioncore/io/annotations.h"
#include "visioncore/io/stream_reader.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fieldsight {

struct AutoLutOptions
{
    /// Frames sampled, spread evenly over the stream (0: every frame). 160: on B-Human's log (160
    /// frames) 40 found 0.80 of the field lines, every frame 0.90 (the team's table 0.883); on
    /// generated 160-frame streams the two are level (docs/formats.md).
    std::size_t frames = 160;
    /// The stream's annotations, when it has them and they are to be used: their done frames'
    /// regions vote as `lut build --annotations` votes, over the automatic clusters.
    const Annotations* annotations = nullptr;
};

/// What one class took.
struct AutoLutClass
{
    Colour colour = Colour::Unclassified;
    std::size_t cells = 0;  ///< cells of the table
    double pixel_share = 0; ///< share of the sampled pixels the table gives this class
};

struct AutoLut
{
    ColourLut lut;
    /// The classes given cells, in colour id order.
    std::vector<AutoLutClass> classes;
    /// The goal colour the stream shows (yellow or blue), when a goal was found.
    std::optional<Colour> goal_colour;
    std::size_t frames = 0; ///< frames sampled
    bool cancelled = false; ///< the table is from the frames read before the cancel
    /// What the run found or could not find, one line each ("no ball-coloured blob found").
    std::vector<std::string> notes;
};

/// Called after every frame read (done of total); returning false cancels.
using AutoLutProgress = std::function<bool(std::size_t done, std::size_t total)>;

/// The automatic table of `reader`'s frames. Deterministic: the same frames and options give the
/// same table. Errors name the stream and the problem (a frame that cannot be read).
Result<AutoLut> buildAutoLut(StreamReader& reader, const AutoLutOptions& options = {},
                             const AutoLutProgress& progress = {});

/// The pipeline's goal-colour parameter: a choice parameter named "goal_colour" of whichever stage
/// declares one (the transition filter's today), found through the registry so neither the
/// command nor the window names a stage. Nothing when no stage declares one.
struct GoalColourParam
{
    std::string stage;
    std::string name;
    double default_value = 0;
};
std::optional<GoalColourParam> goalColourParam(const Pipeline& pipeline);

} // namespace fieldsight
