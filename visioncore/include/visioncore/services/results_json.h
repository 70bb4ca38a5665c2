// Results of a run as fieldsight-results/1 JSON (SPEC §5.1), written and read back.
#pragma once

#include "visioncore/framework/controller.h"
#include "visioncore/basics/result.h"
#include "visioncore/services/stream_runner.h"

#include <string>
#include <vector>

namespace fieldsight {

struct ResultsHeader
{
    std::string stream;
    std::string lut;
    int width = 0;  ///< px
    int height = 0; ///< px
    std::vector<std::string> skipped_stages;
    int orientation = 0; ///< deg the stored pictures were turned (written when not 0)
};

/// The header of a run over `input`.
ResultsHeader resultsHeader(const StreamInput& input);

/// The fieldsight-results/1 document; time_ms has a key per stage that ran,
/// and each percept list a stage produced (absent for a skipped stage). `stage_ids` orders the
/// summary's per-stage means.
std::string resultsJson(const ResultsHeader& header, const std::vector<FrameResult>& frames,
                        const std::vector<std::string>& stage_ids);

struct ResultsFile
{
    ResultsHeader header;
    std::vector<FrameResult> frames; ///< report.total_ms and the stage times as written
};

/// Reads a fieldsight-results/1 document; the percept lists of `pipeline`'s kinds are read, other
/// keys are ignored. Errors name `source` and the place.
Result<ResultsFile> readResults(const std::string& text, const std::string& source,
                                const Pipeline& pipeline = Pipeline::standard());

} // namespace fieldsight
