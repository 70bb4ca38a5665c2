// `fieldsight import`: a log folder made into a stream folder (docs/formats.md): the frames, a
// manifest with each frame's timestamp and kinematic horizon, the team's colour table converted,
// and the stream's own parameters from --set. Written into a new folder beside the output, which
// takes its name only once it is whole; nothing is written over and the log is only read.
#include "commands/commands.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/json_text.h"
#include "visioncore/io/bhuman_log.h"
#include "visioncore/io/lut_import.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <exception>
#include <filesystem>

namespace fieldsight::cli {
namespace {

double rounded3(double v)
{
    return std::round(v * 1000.0) / 1000.0;
}

/// Fills the new folder `dir` from `log`.
Status writeStream(const std::filesystem::path& dir, const BhumanLog& log, const ParamSet& params)
{
    namespace fs = std::filesystem;
    nlohmann::ordered_json manifest;
    manifest["format"] = "fieldsight-stream/1";
    manifest["pixel_format"] = "ycbcr";
    if (!log.colour_table.empty()) {
        auto table = importLut(log.colour_table);
        if (!table)
            return table.error();
        if (Status s = table.value().save((dir / "default.lut").string()); !s)
            return s;
        manifest["lut"] = "default.lut";
    }
    if (!params.empty()) {
        if (Status s = params.save((dir / "params.json").string()); !s)
            return s;
        manifest["params"] = "params.json";
    }
    nlohmann::ordered_json frames = nlohmann::ordered_json::array();
    for (const LoggedFrame& f : log.frames) {
        const fs::path name = fs::path(f.path).filename();
        std::error_code ec;
        fs::copy_file(f.path, dir / name, ec);
        if (ec)
            return Error{(dir / name).string() + ": cannot copy " + f.path +
                         " there: " + ec.message()};
        nlohmann::ordered_json entry{{"file", name.string()}, {"timestamp_ms", f.timestamp_ms}};
        if (f.horizon)
            entry["horizon"] = {rounded3(f.horizon->y_left), rounded3(f.horizon->y_right)};
        frames.push_back(std::move(entry));
    }
    manifest["frames"] = std::move(frames);
    return writeFileAtomically((dir / "stream.json").string(), jsonText(manifest, 1) + "\n");
}

} // namespace

int importCommand(const QStringList& args, const Context& ctx)
{
    namespace fs = std::filesystem;
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Makes a stream folder from a robot's log folder (a B-Human log as the reference data "
        "keeps it: frames_ycbcr/, frames.csv, coltable.c64): its frames, a manifest with every "
        "frame's timestamp and kinematic horizon, the colour table as default.lut, and the "
        "stream's own parameters from --params and --set (params.json).");
    parser.addPositionalArgument("LOG", "The log folder.");
    parser.addOption({"out", "The stream folder to make (new, or an empty folder).", "DIR"});
    parser.addOption(paramsOption());
    parser.addOption(setOption());
    if (auto done = parseCommand(parser, "import", args, 1, 1, ctx))
        return *done;
    if (!parser.isSet("out"))
        return badInput(ctx, "import: missing --out DIR");
    try {
        const std::string source = toLocalPath(parser.positionalArguments()[0]);
        const fs::path out = fs::absolute(toLocalPath(parser.value("out")));
        if (!isBhumanLogFolder(source))
            return badInput(ctx, source + ": not a log folder this version reads (it needs "
                                          "frames.csv and frames_ycbcr/, as a B-Human log); "
                                          "nothing was written");
        std::error_code ec;
        if (Status s = checkNotAnInput("import --out", out.string(),
                                       {source, toLocalPath(parser.value("params"))});
            !s)
            return badInput(ctx, s.error().message);
        if (fs::is_symlink(out, ec) || !checkNewOrEmptyFolder("import --out", out.string()))
            return badInput(ctx, out.string() + ": exists and is not an empty folder; nothing "
                                                "was written (choose a new folder)");
        auto loaded = paramsFrom(parser, ctx.pipeline);
        if (!loaded)
            return badInput(ctx, loaded.error().message + "; nothing was written");
        const ParamSet& params = loaded.value();
        auto log = readBhumanLog(source);
        if (!log)
            return badInput(ctx, log.error().message + "; nothing was written");

        // Made whole beside the output, then named: a stream folder is never half written.
        // A folder of that name already there is someone's: never removed, another name taken.
        fs::path partial = out.parent_path() / ("." + out.filename().string() + ".partial");
        for (int i = 2; fs::exists(fs::symlink_status(partial, ec)) && i < 1000; ++i)
            partial = out.parent_path() /
                      ("." + out.filename().string() + ".partial-" + std::to_string(i));
        if (!fs::create_directories(partial, ec) || ec) {
            printError(ctx.err, partial.string() + ": cannot make the folder: " +
                                    (ec ? ec.message() : std::string("it exists")));
            return kExitFailure;
        }
        Status s = writeStream(partial, log.value(), params);
        if (s) {
            fs::remove(out, ec); // an empty folder only (checked above)
            fs::rename(partial, out, ec);
            if (ec)
                s = Error{out.string() + ": cannot name the stream folder: " + ec.message()};
        }
        if (!s) {
            fs::remove_all(partial, ec);
            printError(ctx.err, s.error().message + "; nothing was written");
            return kExitFailure;
        }
        const BhumanLog& l = log.value();
        ctx.out << source << " -> " << out.string() << ": " << l.frames.size() << " frames ("
                << l.width << "x" << l.height << ", YCbCr), " << l.frames.size() - l.invalid
                << " with their kinematic horizon (" << l.invalid
                << " marked invalid in frames.csv have none)"
                << (l.colour_table.empty() ? "" : ", the colour table as default.lut")
                << (params.empty() ? "" : ", its parameters in params.json") << "\n";
        return kExitOk;
    } catch (const std::exception& e) {
        return failure(ctx, "import", e);
    }
}

} // namespace fieldsight::cli
