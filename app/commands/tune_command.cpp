// `fieldsight tune`: the stages' parameters fitted to a stream's annotations (tuneParams),
// written as fieldsight-params/1 with what each change bought, fit and held-out scores side by
// side so a user sees overfitting.
#include "commands/commands.h"

#include "visioncore/basics/json_text.h"
#include "visioncore/services/param_tuning.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>

namespace fieldsight::cli {
namespace {

inline const OutputFileKind kTuneFile{"fieldsight-tune/1", {}, false, true};

std::atomic<bool> g_interrupted{false};

/// Ctrl+C stops the search and keeps the best so far; a second one ends the program.
extern "C" void onInterrupt(int)
{
    g_interrupted.store(true);
    std::signal(SIGINT, SIG_DFL);
}

/// Ctrl+C stops the search while the command runs (from before the frames are read).
class InterruptGuard
{
public:
    InterruptGuard() : m_previous(std::signal(SIGINT, onInterrupt)) { g_interrupted.store(false); }
    ~InterruptGuard() { std::signal(SIGINT, m_previous == SIG_ERR ? SIG_DFL : m_previous); }
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
    void (*m_previous)(int);
};

std::string scoreCell(const TuneScore& s, const std::string& term)
{
    char cell[64];
    if (term == kBoundaryTerm) {
        if (s.boundary_median < 0)
            return "-";
        std::snprintf(cell, sizeof cell, "%.2f px", s.boundary_median);
        return cell;
    }
    const auto c = s.classes.find(term);
    if (c == s.classes.end() || c->second.tp + c->second.fp + c->second.fn == 0)
        return "-";
    std::snprintf(cell, sizeof cell, "%.2f/%.2f", c->second.precision(), c->second.recall());
    return cell;
}

/// `kinds`: the pipeline's scored kinds, a row each.
std::string tuneTable(const std::string& stream, const TuneResult& r, const TuneOptions& o,
                      const std::vector<const PerceptKind*>& kinds)
{
    std::string text;
    char line[320];
    if (r.folds > 0)
        std::snprintf(line, sizeof line,
                      "fieldsight tune: %s, %zu scored frames, %d-fold cross-validation: each "
                      "fold held out from a search on the others (seed %llu)\n",
                      stream.c_str(), r.fit_frames.size(), r.folds, (unsigned long long)o.seed);
    else
        std::snprintf(line, sizeof line,
                      "fieldsight tune: %s, %zu scored frames: %zu fitted, %zu held out (seed "
                      "%llu)\n",
                      stream.c_str(), r.fit_frames.size() + r.holdout_frames.size(),
                      r.fit_frames.size(), r.holdout_frames.size(), (unsigned long long)o.seed);

    text += line;
    std::snprintf(line, sizeof line, "%d parameters searched, %d evaluations in %.1f s%s\n",
                  r.parameters, r.evaluations, r.seconds,
                  r.cancelled ? " (interrupted: the best so far)" : "");
    text += line;
    const bool aside = !r.validation_frames.empty();
    if (aside) {
        std::snprintf(line, sizeof line, "%zu frames of the validation streams, never fitted\n",
                      r.validation_frames.size());
        text += line;
    }
    std::snprintf(line, sizeof line, "%-11s %-23s %-23s%s\n", "", "fit frames",
                  r.folds > 0 ? "held out, by fold" : "held-out frames",
                  aside ? " validation streams" : "");
    text += line;
    std::snprintf(line, sizeof line, "%-11s %-11s %-11s %-11s %-11s%s\n", "class", "start", "tuned",
                  "start", "tuned", aside ? " start       tuned" : "");
    text += line;
    const auto validationCells = [&](const std::string& start, const std::string& tuned) {
        if (!aside)
            return std::string();
        char cells[64];
        std::snprintf(cells, sizeof cells, " %-11s %s", start.c_str(), tuned.c_str());
        return std::string(cells);
    };
    std::vector<std::string> terms;
    for (const PerceptKind* kind : kinds)
        terms.push_back(scoredClassName(*kind));
    terms.push_back(kBoundaryTerm);
    for (const std::string& term : terms) {
        std::snprintf(line, sizeof line, "%-11s %-11s %-11s %-11s %-11s%s\n", term.c_str(),
                      scoreCell(r.start_fit, term).c_str(), scoreCell(r.tuned_fit, term).c_str(),
                      scoreCell(r.start_holdout, term).c_str(),
                      scoreCell(r.tuned_holdout, term).c_str(),
                      validationCells(scoreCell(r.start_validation, term),
                                      scoreCell(r.tuned_validation, term))
                          .c_str());
        text += line;
    }
    const bool held = !r.holdout_frames.empty();
    const auto total = [](bool scored, const TuneScore& s) {
        return scored ? std::to_string(s.total).substr(0, 5) : std::string("-");
    };
    std::snprintf(
        line, sizeof line, "%-11s %-11.3f %-11.3f %-11s %-11s%s\n", "score", r.start_fit.total,
        r.tuned_fit.total, total(held, r.start_holdout).c_str(),
        total(held, r.tuned_holdout).c_str(),
        validationCells(total(aside, r.start_validation), total(aside, r.tuned_validation))
            .c_str());
    text += line;
    if (r.start_fit.ms_per_frame >= 0 && r.tuned_fit.ms_per_frame >= 0) {
        std::snprintf(line, sizeof line, "%-11s %-11s %-11s\n", "core time",
                      (std::to_string(r.start_fit.ms_per_frame).substr(0, 5) + " ms").c_str(),
                      (std::to_string(r.tuned_fit.ms_per_frame).substr(0, 5) + " ms").c_str());
        text += line;
    }
    text += "(precision/recall per class; boundary: median error; core time: a frame, wall "
            "clock; score: docs/formats.md)\n";
    if (r.changes.empty()) {
        text += "no change beats the start on the fit frames\n";
        return text;
    }
    text += "changed (what each buys on the fit frames: the score without it is lower by):\n";
    for (const TuneChange& c : r.changes) {
        std::string terms_text;
        for (const auto& [term, gain] : c.term_gain)
            if (std::abs(gain) >= 0.0005) {
                char t[64];
                std::snprintf(t, sizeof t, "%s%s %+.3f", terms_text.empty() ? "" : ", ",
                              term.c_str(), gain);
                terms_text += t;
            }
        std::snprintf(line, sizeof line, "  %-36s %10g -> %-10g %+.4f%s%s%s\n",
                      (c.stage + "." + c.name).c_str(), c.before, c.after, c.gain,
                      terms_text.empty() ? "" : " (", terms_text.c_str(),
                      terms_text.empty() ? "" : ")");
        text += line;
    }
    return text;
}

std::string tuneJson(const std::vector<std::string>& streams,
                     const std::vector<std::string>& validation_streams, const std::string& out,
                     const TuneResult& r, const TuneOptions& o)
{
    using Json = nlohmann::ordered_json;
    auto score = [](const TuneScore& s) {
        Json j;
        j["score"] = rounded(s.total, 6);
        j["frames"] = s.frames;
        Json classes = Json::object();
        for (const auto& [name, c] : s.classes)
            classes[name] = {{"tp", c.tp}, {"fp", c.fp}, {"fn", c.fn}};
        j["classes"] = std::move(classes);
        j["boundary_median_px"] =
            s.boundary_median < 0 ? Json() : Json(rounded(s.boundary_median, 4));
        j["boundary_mean_px"] = s.boundary_mean < 0 ? Json() : Json(rounded(s.boundary_mean, 4));
        j["ms_per_frame"] = s.ms_per_frame < 0 ? Json() : Json(rounded(s.ms_per_frame, 4));
        return j;
    };
    Json j;
    j["format"] = "fieldsight-tune/1";
    j["stream"] = streams.front();
    if (streams.size() > 1)
        j["streams"] = streams; // every stream fitted, the first as "stream"
    j["params"] = out;
    j["seed"] = o.seed;
    j["budget"] = o.budget;
    j["evaluations"] = r.evaluations;
    j["seconds"] = rounded(r.seconds, 3);
    j["cancelled"] = r.cancelled;
    j["folds"] = r.folds;
    j["agree"] = o.agree;
    j["fit_frames"] = r.fit_frames;
    j["holdout_frames"] = r.holdout_frames;
    j["start"] = {{"fit", score(r.start_fit)}, {"holdout", score(r.start_holdout)}};
    j["tuned"] = {{"fit", score(r.tuned_fit)}, {"holdout", score(r.tuned_holdout)}};
    if (!validation_streams.empty()) { // only then: older readers see the same keys as before
        j["validation_streams"] = validation_streams;
        j["validation_frames"] = r.validation_frames;
        j["start"]["validation"] = score(r.start_validation);
        j["tuned"]["validation"] = score(r.tuned_validation);
    }
    Json changes = Json::array();
    for (const TuneChange& c : r.changes)
        changes.push_back({{"stage", c.stage},
                           {"param", c.name},
                           {"before", c.before},
                           {"after", c.after},
                           {"gain", rounded(c.gain, 6)}});
    j["changes"] = std::move(changes);
    Json history = Json::array();
    for (const auto& [evaluations, best] : r.history)
        history.push_back({evaluations, rounded(best, 6)});
    j["history"] = std::move(history);
    return jsonText(j, 2) + "\n";
}

} // namespace

int tuneCommand(const QStringList& args, const Context& ctx)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Fits the stages' parameters to the stream's annotations: searches their registered "
        "ranges to maximise the score on some annotated frames, scores the others (held out) "
        "too, and writes the parameters that differ from the defaults. Ctrl+C stops the search "
        "and keeps the best so far.");
    parser.addPositionalArgument(
        "STREAM",
        "Image folder or .strm file; several streams of one venue are fitted together "
        "(each with its own annotations.json and table, the same share of each held "
        "out).",
        "STREAM...");
    parser.addOption({"out", "The fitted parameters (fieldsight-params/1).", "PARAMS"});
    parser.addOption({"annotations",
                      "Annotations to fit (default: annotations.json in the stream folder).",
                      "FILE"});
    parser.addOption(
        {"stages", "Only these stages' parameters (default: every stage).", "STAGE,..."});
    parser.addOption({"budget", "Evaluations of a parameter set, at most (default 1500).", "N"});
    parser.addOption({"seed", "Seed of the search and of the held-out frames (default 1).", "S"});
    parser.addOption({"validate",
                      "An annotated stream of the venue kept aside: scored with the start and "
                      "the result, never fitted (repeatable; its own annotations.json and "
                      "table).",
                      "STREAM"});
    parser.addOption({"holdout",
                      "Share of the annotated frames held out, in contiguous blocks (default "
                      "0.33; 0 fits them all).",
                      "SHARE"});
    parser.addOption({"folds",
                      "K-fold cross-validation instead of --holdout: K contiguous blocks, each "
                      "scored with what a search on the others found; the result is fitted on "
                      "every frame (K + 1 searches).",
                      "K"});
    parser.addOption({"allow-costly",
                      "Let the parameters that set a frame's cost (RANSAC samples, scan-line "
                      "spacing) go beyond twice their default's cost."});
    parser.addOption({"agree",
                      "A move is kept only when none of this many contiguous blocks of the fit "
                      "frames scores lower (default 3; 1: the total alone).",
                      "N"});
    parser.addOption({"weight",
                      "Weight of a score term, e.g. obstacle=2 or boundary=0 (repeatable; "
                      "terms: ball, goalpost, obstacle, field_line, boundary; default 1).",
                      "TERM=W"});
    parser.addOption({"json", "Also write the report as fieldsight-tune/1 JSON.", "FILE"});
    parser.addOption(lutOption());
    parser.addOption(setOption());
    parser.addOption(paramsOption());
    parser.addOption(orientationOption());
    parser.addOption(threadsOption("0"));
    if (auto done = parseCommand(parser, "tune", args, 1, 64, ctx))
        return *done;

    const InterruptGuard interrupt;
    try {
        std::vector<std::string> streams;
        for (const QString& s : parser.positionalArguments())
            streams.push_back(toLocalPath(s));
        const std::string& stream = streams.front();
        if (streams.size() > 1 && parser.isSet("annotations"))
            return badInput(ctx, "tune: --annotations names one stream's file; with several "
                                 "streams each is fitted to its own annotations.json");
        if (!parser.isSet("out"))
            return badInput(ctx, "tune: --out PARAMS is required");
        const std::string out = toLocalPath(parser.value("out"));
        const std::string json = toLocalPath(parser.value("json"));
        const std::string truth_path = parser.isSet("annotations")
                                           ? toLocalPath(parser.value("annotations"))
                                           : defaultTruthPath(stream);
        std::vector<std::string> inputs{truth_path, toLocalPath(parser.value("lut")),
                                        toLocalPath(parser.value("params"))};
        std::vector<std::string> validation_streams;
        for (const QString& s : parser.values("validate"))
            validation_streams.push_back(toLocalPath(s));
        for (const std::string& s : streams) {
            inputs.push_back(s);
            inputs.push_back(defaultTruthPath(s));
        }
        for (const std::string& s : validation_streams) {
            if (std::find(streams.begin(), streams.end(), s) != streams.end())
                return badInput(ctx, "tune: " + s +
                                         " is both fitted and a --validate stream; a stream "
                                         "kept aside must be another one");
            inputs.push_back(s);
            inputs.push_back(defaultTruthPath(s));
        }
        if (Status s = checkOutputFile("tune --out", out, inputs, kParamsFile); !s)
            return badInput(ctx, s.error().message);
        if (Status s = checkOutputFile("tune --json", json, inputs, kTuneFile); !s)
            return badInput(ctx, s.error().message);
        if (!json.empty() && json == out)
            return badInput(ctx, "tune: --json and --out name the same file");

        TuneOptions options;
        QString error;
        const auto budget = intOption(parser, "budget", options.budget, 1, error);
        const auto seed =
            intOption(parser, "seed", 1, 0, error, std::numeric_limits<long long>::max());
        const auto threads = intOption(parser, "threads", 0, 0, error);
        const auto folds = intOption(parser, "folds", 0, 0, error, 20);
        const auto agree = intOption(parser, "agree", options.agree, 1, error, 20);
        if (!budget || !seed || !threads || !folds || !agree)
            return badInput(ctx, "tune: " + error);
        options.budget = int(*budget);
        options.seed = std::uint64_t(*seed);
        options.threads = int(*threads);
        options.folds = int(*folds);
        options.agree = int(*agree);
        options.allow_costly = parser.isSet("allow-costly");
        if (options.folds == 1)
            return badInput(ctx, "tune: --folds must be 2 or more (or 0: --holdout)");
        if (parser.isSet("holdout")) {
            bool ok = false;
            options.holdout = parser.value("holdout").toDouble(&ok);
            if (!ok || options.holdout < 0 || options.holdout > 0.9)
                return badInput(ctx, "tune: --holdout must be a share from 0 to 0.9, not '" +
                                         parser.value("holdout") + "'");
        }
        for (const QString& w : parser.values("weight")) {
            const auto parts = w.split('=');
            bool ok = parts.size() == 2;
            const double value = ok ? parts[1].toDouble(&ok) : 0;
            if (!ok)
                return badInput(ctx, "tune: --weight takes TERM=W, not '" + w + "'");
            options.weights[parts[0].toStdString()] = value;
        }
        if (Status s = checkTuneWeights(options.weights, scoredKinds(ctx.pipeline.perceptKinds()));
            !s)
            return badInput(ctx, "tune --weight: " + s.error().message);
        for (const QString& id : parser.value("stages").split(',', Qt::SkipEmptyParts))
            options.stages.push_back(id.trimmed().toStdString());

        auto input = openInput(parser, stream, ctx);
        if (!input)
            return badInput(ctx, input.error().message);
        auto truth = Annotations::load(truth_path, ctx.pipeline.perceptKinds(),
                                       input.value().info().frame_count);
        if (!truth)
            return badInput(ctx, truth.error().message);
        // The other streams, each with its own annotations (and table, unless --lut names one).
        // The other streams (fitted, then kept aside), each with its own annotations (and table,
        // unless --lut names one).
        std::vector<StreamInput> more_inputs;
        std::vector<Annotations> more_truth;
        more_inputs.reserve(streams.size() + validation_streams.size());
        more_truth.reserve(streams.size() + validation_streams.size());
        std::vector<TuneStream> more;
        std::vector<std::pair<std::string, bool>> others;
        for (std::size_t k = 1; k < streams.size(); ++k)
            others.emplace_back(streams[k], false);
        for (const std::string& s : validation_streams)
            others.emplace_back(s, true);
        for (const auto& [path, aside] : others) {
            auto other = openInput(parser, path, ctx);
            if (!other)
                return badInput(ctx, other.error().message);
            const std::string other_truth = defaultTruthPath(path);
            auto annotations = Annotations::load(other_truth, ctx.pipeline.perceptKinds(),
                                                 other.value().info().frame_count);
            if (!annotations)
                return badInput(ctx, annotations.error().message);
            more_inputs.push_back(std::move(other).value());
            more_truth.push_back(std::move(annotations).value());
            more.push_back({&more_inputs.back(), &more_truth.back(), other_truth, aside});
        }

        const bool terminal = &ctx.err == &std::cerr && isatty(STDERR_FILENO);
        options.progress = [&](const TuneProgress& p) {
            if (terminal)
                ctx.err << "\rtune: " << p.evaluations << " of " << p.budget
                        << " evaluations, best fit score " << rounded(p.best_fit, 4) << std::flush;
        };
        options.cancel = &g_interrupted;
        auto result = tuneStreams(input.value(), truth.value(), truth_path, options, more);
        if (terminal)
            ctx.err << "\r\033[K" << std::flush;
        if (!result)
            return badInput(ctx, result.error().message);
        if (Status s = result.value().params.save(out); !s) {
            printError(ctx.err, s.error().message);
            return kExitFailure;
        }
        std::string names;
        for (const std::string& s : streams)
            names += (names.empty() ? "" : ", ") + s;
        std::string table =
            tuneTable(names, result.value(), options, scoredKinds(ctx.pipeline.perceptKinds()));
        table += "wrote " + out + "\n";
        return finishReport(ctx, table, json,
                            tuneJson(streams, validation_streams, out, result.value(), options));
    } catch (const std::exception& e) {
        return failure(ctx, "tune", e);
    }
}

} // namespace fieldsight::cli
