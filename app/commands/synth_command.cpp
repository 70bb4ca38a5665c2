// `fieldsight synth`: a synthetic stream with exact ground truth, from the scene generator.
#include "commands/commands.h"

#include "synth/synth.h"

namespace fieldsight::cli {

int synthCommand(const QStringList& args, const Context& ctx)
{
    namespace synth = fieldsight::synth;
    QCommandLineParser parser;
    parser.setApplicationDescription("Renders a synthetic stream with exact ground truth.");
    QString names;
    for (const std::string& name : synth::scenarioNames())
        names += (names.isEmpty() ? "" : ", ") + QString::fromStdString(name);
    parser.addOption({"scenario",
                      "One of " + names +
                          " (default lab2). crowded is no stream of the paper's but a scene to "
                          "test on: five robots around the ball, two of them between the camera "
                          "and the ball and as close as 0.2 m (filling the frame); the camera "
                          "scans often, so the ball and posts are cut by the frame's sides.",
                      "NAME"});
    parser.addOption({"frames",
                      "Number of frames (default 30), or 'paper' for the paper's length of the "
                      "scenario (5090, 470, 175, 2640, 625; crowded 300).",
                      "N"});
    parser.addOption({"seed", "Random seed (default 1).", "S"});
    parser.addOption({"out", "Stream folder to create.", "DIR"});
    parser.addOption({"width", "Image width in px (default 320).", "PX"});
    parser.addOption({"height", "Image height in px (default 240).", "PX"});
    parser.addOption({"camera-height",
                      "The camera's height above the carpet in m, 0.3 to 0.7 (default 0.45, "
                      "the NAO's head); stream.json's camera.height_m says it.",
                      "M"});
    parser.addOption({"strm", "Also write image.strm."});
    parser.addOption({"no-png", "Do not write PNG frames (needs --strm)."});
    parser.addOption({"drift",
                      "Light drift over the stream, 0 to 0.5 (default 0): the colour temperature "
                      "and level move by this share from the first frame to the last; "
                      "default.lut stays the first frame's table.",
                      "F"});
    parser.addOption({"table-light",
                      "With --drift: default.lut is the table of the light this far along the "
                      "drift instead, 0 (the first frame's, default) to 1 (the last frame's).",
                      "P"});
    if (auto done = parseCommand(parser, "synth", args, 0, 0, ctx))
        return *done;

    synth::SynthOptions options;
    if (!parser.isSet("out"))
        return badInput(ctx, "synth: --out DIR is required");
    options.out_dir = toLocalPath(parser.value("out"));
    if (parser.isSet("scenario")) {
        auto scenario = synth::scenarioFromName(parser.value("scenario").toStdString());
        if (!scenario)
            return badInput(ctx, "synth: --scenario: " +
                                     QString::fromStdString(scenario.error().message));
        options.scenario = scenario.value();
    }
    QString error;
    if (parser.value("frames") == "paper")
        options.frames = synth::paperFrameCount(options.scenario);
    const auto frames = parser.value("frames") == "paper"
                            ? std::optional<long long>(options.frames)
                            : intOption(parser, "frames", options.frames, 1, error);
    const auto width = intOption(parser, "width", options.width, 16, error, 8192);
    const auto height = intOption(parser, "height", options.height, 16, error, 8192);
    if (!frames || !width || !height)
        return badInput(ctx, "synth: " + error);
    options.frames = int(*frames);
    options.width = int(*width);
    options.height = int(*height);
    if (parser.isSet("seed")) {
        bool ok = false;
        options.seed = parser.value("seed").toULongLong(&ok);
        if (!ok)
            return badInput(ctx, "synth: --seed: expected a whole number >= 0, got '" +
                                     parser.value("seed") + "'");
    }
    if (parser.isSet("drift")) {
        bool ok = false;
        options.drift = parser.value("drift").toDouble(&ok);
        if (!ok || !(options.drift >= 0 && options.drift <= 0.5))
            return badInput(ctx, "synth: --drift: expected a number from 0 to 0.5, got '" +
                                     parser.value("drift") + "'");
    }
    if (parser.isSet("table-light")) {
        bool ok = false;
        options.table_light = parser.value("table-light").toDouble(&ok);
        if (!ok || !(options.table_light >= 0 && options.table_light <= 1))
            return badInput(ctx, "synth: --table-light: expected a number from 0 to 1, got '" +
                                     parser.value("table-light") + "'");
    }
    if (parser.isSet("camera-height")) {
        bool ok = false;
        options.camera_height = parser.value("camera-height").toDouble(&ok);
        if (!ok || !(options.camera_height >= 0.3 && options.camera_height <= 0.7))
            return badInput(ctx, "synth: --camera-height: expected a number from 0.3 to 0.7, "
                                 "got '" +
                                     parser.value("camera-height") + "'");
    }
    options.write_strm = parser.isSet("strm");
    options.write_png = !parser.isSet("no-png");
    if (!options.write_png && !options.write_strm)
        return badInput(ctx, "synth: --no-png without --strm would write no frames");

    // A folder that is someone's stream, or that holds edits since synth wrote it, is refused
    // before anything in it is touched (bad input).
    bool refused = false;
    if (fieldsight::Status s = synth::generateStream(options, &refused); !s) {
        printError(ctx.err, s.error().message);
        return refused ? kExitBadInput : kExitFailure;
    }
    ctx.out << "wrote " << options.frames << " frames of " << synth::scenarioName(options.scenario)
            << " to " << options.out_dir << '\n';
    return kExitOk;
}

} // namespace fieldsight::cli
