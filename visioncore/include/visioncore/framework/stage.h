// Stage: one processing module of the bottom layer, with its id, parameters and debug layers.
//
// A stage, complete (the transition filter, stages/transitions/, is the smallest real one):
//
//     class BallDetector : public Stage
//     {
//     public:
//         const StageInfo& info() const override
//         {
//             static const StageInfo info{"ball", "Ball", "Finds the ball.", true,
//                 {"transitions", "green_horizon"}, {}, {&perceptKind<Ball>()},
//                 {{"ball.edge_points", "Ball edge points", kCyan}}};
//             return info;
//         }
//         void run(Blackboard& bb) override
//         {
//             auto& balls = bb.percepts.output<Ball>(); // present (and empty) already
//             if (auto* d = bb.debug.layer("ball.edge_points")) ... // only when requested
//         }
//     private:
//         Param<double> m_min_radius{this, 2.5, {"min_radius", "px", 0, 100, 0.5,
//                                                "Smaller balls are ignored."}};
//     };
//
// and one line in stages/stage_list.cpp. A new kind of percept is its struct and PerceptTraits
// in percepts/ (see percept_set.h).
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/framework/param.h"
#include "visioncore/percepts/percept_set.h"
#include "visioncore/basics/result.h"

#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

class Blackboard;

struct LayerInfo
{
    std::string id;   ///< "<stage id>.<name>", e.g. "green_horizon.hull"
    std::string name; ///< for a layer list
    /// Its colour in the legend; drawings of the layer use it. Layers coloured by colour class
    /// (segments, transitions) set by_colour_class.
    Rgb colour;
    bool by_colour_class = false;
};

/// Blackboard slots a stage can read before any stage ran: the DataWrapper's inputs.
inline const std::vector<std::string>& blackboardInputs()
{
    static const std::vector<std::string> inputs{"image", "lut", "kinematic_horizon"};
    return inputs;
}

struct StageInfo
{
    std::string id;          ///< SPEC §5 stage id, e.g. "green_horizon"
    std::string name;        ///< human name, e.g. "Green horizon"
    std::string description; ///< one sentence for a user
    bool skippable = true;   ///< can a host switch it off per frame
    /// Blackboard slots it needs: inputs, or what an earlier stage writes or outputs (checked
    /// when a pipeline is put together).
    std::vector<std::string> reads;
    /// Working blackboard slots it fills for later stages (not percepts).
    std::vector<std::string> writes;
    /// The percept lists it produces: present (maybe empty) after it ran, absent when skipped.
    /// Their keys are blackboard slots later stages may read.
    std::vector<const PerceptKind*> percepts;
    std::vector<LayerInfo> layers;
};

class Stage
{
public:
    Stage() = default;
    Stage(const Stage&) = delete; // parameters point into the stage
    Stage& operator=(const Stage&) = delete;
    virtual ~Stage() = default;
    virtual const StageInfo& info() const = 0;
    /// Reads its inputs from and writes its results to `bb`. May throw; the controller turns an
    /// exception into a per-frame diagnostic.
    virtual void run(Blackboard& bb) = 0;

    /// Every parameter with its current value, in declaration order.
    std::vector<ParamInfo> params() const;
    Status setParam(std::string_view name, double value);
    void resetParams();

    /// The width of the frames about to be run: length parameters (unit "px") then read scaled
    /// by width / kParamReferenceWidth. The Controller sets it before every frame.
    void setFrameWidth(int width)
    {
        m_pixel_scale = width > 0 ? double(width) / kParamReferenceWidth : 1.0;
    }
    /// width / kParamReferenceWidth of the frame being run: for a length a stage fixes in code.
    double pixelScale() const { return m_pixel_scale; }

private:
    friend class ParamBase;
    std::vector<ParamBase*> m_params;
    double m_pixel_scale = 1.0;
};

/// What a host may know of a stage without holding it: its info and its parameters (values as
/// they were when the descriptor was made).
struct StageDescriptor
{
    StageInfo info;
    std::vector<ParamInfo> params;
};

} // namespace fieldsight
