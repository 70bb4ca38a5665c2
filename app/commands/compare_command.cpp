// `fieldsight compare`: the pipeline over a stream's annotated frames with two tables or two
// parameter sets (A and B); per class each side's scores and the frames B fixed and broke,
// printed as a table or written as fieldsight-compare/1 JSON (docs/formats.md).
#include "commands/commands.h"

#include "visioncore/basics/json_text.h"
#include "visioncore/services/ab_compare.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <exception>

namespace fieldsight::cli {
namespace {

/// Frames listed per class and kind of change in the table (the JSON has them all).
constexpr std::size_t kListed = 12;

struct Sides
{
    std::string stream;
    std::string truth;
    std::string a_lut;
    std::string a_params;
    AbSide b;
};

std::string scoreText(const ClassScore& s)
{
    char text[96];
    std::snprintf(text, sizeof text, "%5d %5d %5d %6.3f %6.3f", s.tp, s.fp, s.fn, s.precision(),
                  s.recall());
    return text;
}

/// "frame_000003.png (FN 1->0)": what changed in the frame.
std::string frameText(const AbFrame& f)
{
    std::string text = f.name + " (";
    const auto part = [&](const char* what, int a, int b) {
        if (a == b)
            return;
        if (text.back() != '(')
            text += ", ";
        text += std::string(what) + " " + std::to_string(a) + "->" + std::to_string(b);
    };
    part("FP", f.a.fp, f.b.fp);
    part("FN", f.a.fn, f.b.fn);
    return text + ")";
}

std::string compareTable(const AbComparison& c, const Sides& s)
{
    std::string text = "fieldsight compare: " + s.stream + " against " + s.truth + "\n";
    text += "A: " + s.a_lut + (s.a_params.empty() ? "" : ", parameters " + s.a_params) + "\n";
    text += "B: " + (s.b.lut_path.empty() ? s.a_lut : s.b.lut_path) +
            (s.b.params_path.empty() ? "" : ", parameters " + s.b.params_path) + "\n";
    text += std::to_string(c.frames) + " annotated frames scored (each class where its truth is "
                                       "complete; concealed objects apart, as in eval)\n";
    char line[256];
    std::snprintf(line, sizeof line,
                  "%-10s %6s | %5s %5s %5s %6s %6s | %5s %5s %5s %6s %6s | %5s %6s\n", "class",
                  "frames", "A TP", "FP", "FN", "prec", "recall", "B TP", "FP", "FN", "prec",
                  "recall", "fixed", "broken");
    text += line;
    for (const AbClass& k : c.classes) {
        std::snprintf(line, sizeof line, "%-10s %6zu | %s | %s | %5zu %6zu\n", k.name.c_str(),
                      k.frames, scoreText(k.a).c_str(), scoreText(k.b).c_str(), k.fixed.size(),
                      k.broken.size());
        text += line;
    }
    const auto boundary = [](double e, std::size_t n) {
        char out[64];
        if (n == 0)
            return std::string("none");
        std::snprintf(out, sizeof out, "%.2f px over %zu frames", e, n);
        return std::string(out);
    };
    text += "field boundary: A " + boundary(c.boundary_a, c.boundary_frames_a) + ", B " +
            boundary(c.boundary_b, c.boundary_frames_b) + "\n";
    for (const AbClass& k : c.classes) {
        for (const auto& [what, list] :
             {std::pair{"fixed", &k.fixed}, std::pair{"broken", &k.broken}}) {
            if (list->empty())
                continue;
            text += std::string(what) + " " + k.name + ":";
            for (std::size_t i = 0; i < list->size() && i < kListed; ++i)
                text += (i ? ", " : " ") + frameText((*list)[i]);
            if (list->size() > kListed)
                text += ", and " + std::to_string(list->size() - kListed) + " more (--json)";
            text += "\n";
        }
    }
    text += "(per class, frames with fewer misses and false detections with B than with A are "
            "fixed, with more broken)\n";
    return text;
}

std::string compareJson(const AbComparison& c, const Sides& s)
{
    using Json = nlohmann::ordered_json;
    const auto score = [](const ClassScore& k) {
        return Json{{"tp", k.tp},
                    {"fp", k.fp},
                    {"fn", k.fn},
                    {"precision", rounded(k.precision(), 6)},
                    {"recall", rounded(k.recall(), 6)},
                    {"concealed_found", k.concealed_found},
                    {"concealed_missed", k.concealed_missed}};
    };
    const auto frames = [](const std::vector<AbFrame>& list) {
        Json out = Json::array();
        for (const AbFrame& f : list)
            out.push_back(Json{{"index", f.index},
                               {"name", f.name},
                               {"a", {{"tp", f.a.tp}, {"fp", f.a.fp}, {"fn", f.a.fn}}},
                               {"b", {{"tp", f.b.tp}, {"fp", f.b.fp}, {"fn", f.b.fn}}}});
        return out;
    };
    const auto boundary = [](double e, std::size_t n) {
        return Json{{"mean_error_px", n ? Json(rounded(e, 4)) : Json(nullptr)}, {"frames", n}};
    };
    Json j;
    j["format"] = "fieldsight-compare/1";
    j["stream"] = s.stream;
    j["truth"] = s.truth;
    j["a"] = {{"lut", s.a_lut}, {"params", s.a_params.empty() ? Json(nullptr) : Json(s.a_params)}};
    j["b"] = {{"lut", s.b.lut_path.empty() ? s.a_lut : s.b.lut_path},
              {"params", s.b.params_path.empty() ? Json(nullptr) : Json(s.b.params_path)}};
    j["frames"] = c.frames;
    Json classes = Json::object();
    for (const AbClass& k : c.classes)
        classes[k.name] = {{"key", std::string(k.kind->truth_key)},
                           {"frames", k.frames},
                           {"a", score(k.a)},
                           {"b", score(k.b)},
                           {"fixed", frames(k.fixed)},
                           {"broken", frames(k.broken)},
                           {"wrong_both", k.wrong_both}};
    j["classes"] = std::move(classes);
    j["field_boundary"] = {{"a", boundary(c.boundary_a, c.boundary_frames_a)},
                           {"b", boundary(c.boundary_b, c.boundary_frames_b)}};
    j["note"] = "fixed: fewer misses and false detections with B than with A; broken: more; "
                "precision = 1 when TP+FP = 0; recall = 1 when TP+FN = 0";
    return jsonText(j, 2) + "\n";
}

/// Side B from --lut-b and --params-b (over the stream's own parameters, with every --set applied
/// to both sides).
Result<AbSide> sideB(const QCommandLineParser& parser, const Context& ctx, const StreamInput& a)
{
    AbSide b;
    if (parser.isSet("lut-b")) {
        b.lut_path = toLocalPath(parser.value("lut-b"));
        auto lut = ColourLut::load(b.lut_path);
        if (!lut)
            return Error{"--lut-b " + lut.error().message};
        b.lut = std::make_shared<const ColourLut>(std::move(lut).value());
    }
    if (!parser.isSet("params-b")) {
        b.params = a.params;
        b.params_path = toLocalPath(parser.value("params"));
        return b;
    }
    b.params_path = toLocalPath(parser.value("params-b"));
    auto loaded = ParamSet::load(b.params_path);
    if (!loaded)
        return Error{"--params-b " + loaded.error().message};
    if (Status s = loaded.value().check(ctx.pipeline); !s)
        return Error{"--params-b " + b.params_path + ": " + s.error().message};
    // Over the stream's own parameters (A's --params is replaced, not added to).
    auto own = streamParams(a.info(), ctx.pipeline);
    if (!own)
        return own.error();
    b.params = std::move(own).value();
    b.params.merge(loaded.value());
    for (const QString& setting : parser.values("set"))
        if (Status s = b.params.parseSetting(setting.toStdString()); !s)
            return Error{"--set " + s.error().message};
    if (Status s = b.params.check(ctx.pipeline); !s)
        return Error{"--set: " + s.error().message};
    return b;
}

} // namespace

int compareCommand(const QStringList& args, const Context& ctx)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Runs the pipeline twice over the annotated frames of a stream, with table A and B or "
        "parameters A and B, scores both (SPEC 5.3, each class where its truth is complete) and "
        "lists per class the frames B fixed (a miss or false detection with A, none with B) and "
        "broke.");
    parser.addPositionalArgument("STREAM", "Image folder or .strm file.");
    parser.addOption(lutOption());
    parser.addOption({"lut-b", "Side B's table (default: side A's).", "FILE"});
    parser.addOption(paramsOption());
    parser.addOption({"params-b", "Side B's parameters (default: side A's).", "FILE"});
    parser.addOption(setOption());
    parser.addOption(orientationOption());
    parser.addOption(adaptOption());
    parser.addOption(
        {"truth", "Annotations (default: annotations.json in the stream folder).", "FILE"});
    parser.addOption({"json",
                      "Write the comparison as fieldsight-compare/1 JSON to FILE (\"-\": to "
                      "standard output, instead of the table).",
                      "FILE"});
    parser.addOption(threadsOption("0"));
    if (auto done = parseCommand(parser, "compare", args, 1, 1, ctx))
        return *done;
    if (!parser.isSet("lut-b") && !parser.isSet("params-b"))
        return badInput(ctx, "compare: give side B with --lut-b FILE, --params-b FILE or both");

    try {
        Sides sides;
        sides.stream = toLocalPath(parser.positionalArguments().first());
        QString error;
        const auto threads = intOption(parser, "threads", 0, 0, error);
        if (!threads)
            return badInput(ctx, ("compare: " + error).toStdString());
        auto input = openInput(parser, sides.stream, ctx);
        if (!input)
            return badInput(ctx, input.error().message);
        sides.truth = parser.isSet("truth") ? toLocalPath(parser.value("truth"))
                                            : defaultTruthPath(sides.stream);
        const std::string json_path = toLocalPath(parser.value("json"));
        if (Status s = checkOutputFile("compare --json", json_path,
                                       {sides.stream, sides.truth, toLocalPath(parser.value("lut")),
                                        toLocalPath(parser.value("lut-b")),
                                        toLocalPath(parser.value("params")),
                                        toLocalPath(parser.value("params-b"))},
                                       kCompareFile);
            !s)
            return badInput(ctx, s.error().message);
        auto b = sideB(parser, ctx, input.value());
        if (!b)
            return badInput(ctx, b.error().message);
        sides.b = std::move(b).value();
        sides.a_lut = input.value().lut_path;
        sides.a_params = toLocalPath(parser.value("params"));
        auto truth = Annotations::load(sides.truth, ctx.pipeline.perceptKinds(),
                                       input.value().info().frame_count);
        if (!truth)
            return badInput(ctx, truth.error().message);
        auto compared =
            compareAb(input.value(), sides.b, truth.value(), sides.truth, int(*threads));
        if (!compared)
            return badInput(ctx, compared.error().message);
        if (compared.value().frames == 0)
            return badInput(ctx, sides.truth +
                                     ": nothing to compare (no frame is done or has a reviewed "
                                     "class)");
        if (json_path == "-")
            return finishReport(ctx, {}, json_path, compareJson(compared.value(), sides));
        return finishReport(ctx, compareTable(compared.value(), sides), json_path,
                            compareJson(compared.value(), sides));
    } catch (const std::exception& e) {
        return failure(ctx, "compare", e);
    }
}

} // namespace fieldsight::cli
