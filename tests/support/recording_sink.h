// A debug sink for core tests: asks for the given layers and keeps what the stages drew.
#pragma once

#include "visioncore/framework/data_wrapper.h"
#include "visioncore/basics/debug_drawing.h"

#include <map>
#include <set>
#include <string>

namespace fieldsight::test {

class RecordingSink : public DebugSink
{
public:
    std::set<std::string, std::less<>> requestedLayers() const override { return layers; }
    void publish(const DebugCanvas& canvas) override { published = canvas.drawings(); }
    std::set<std::string, std::less<>> layers;
    std::map<std::string, DebugDrawing, std::less<>> published;
};

} // namespace fieldsight::test
