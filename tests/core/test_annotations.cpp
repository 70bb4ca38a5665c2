// Ground-truth annotation files (SPEC §5.2): round trip, derived goalpost base, bad input.
#include "support/percept_kinds.h"
#include "support/test_suite.h"
#include "visioncore/framework/controller.h"
#include "visioncore/io/annotations.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/field_boundary.h"
#include "visioncore/percepts/field_line.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/percepts/obstacle.h"

#include "support/kill_during_save.h"

#include <QtTest>

#include <nlohmann/json.hpp>

#include <fstream>

using namespace fieldsight;

namespace {

const char* kSpecExample = R"({"format": "fieldsight-annotations/1",
 "frames": {"frame_000000.png": {"done": true,
   "balls": [{"x": 207.7, "y": 107.9, "radius": 6.2}],
   "goalposts": [{"left": 131, "right": 139, "top": 0, "bottom": 61}],
   "obstacles": [{"left": 70, "right": 99, "top": 26, "bottom": 80}],
   "field_boundary": [[0, 62], [319, 58]],
   "field_lines": [{"x1": 10, "y1": 200, "x2": 300, "y2": 181}]}}})";

/// The percept kinds the standard pipeline reads and writes.
} // namespace

class TestAnnotations : public QObject
{
    Q_OBJECT

private slots:
    void readsTheSpecExample()
    {
        auto parsed =
            Annotations::fromJson(kSpecExample, "annotations.json", test::standardKinds());
        QVERIFY2(parsed.ok(), parsed.ok() ? "" : parsed.error().message.c_str());
        const Annotations& a = parsed.value();
        QCOMPARE(a.frames.size(), std::size_t(1));
        const FrameAnnotation& f = a.frames.at("frame_000000.png");
        QVERIFY(f.done);
        QCOMPARE(f.truth.list<Ball>().size(), std::size_t(1));
        QCOMPARE(f.truth.list<Ball>()[0].x, 207.7);
        QCOMPARE(f.truth.list<Ball>()[0].y, 107.9);
        QCOMPARE(f.truth.list<Ball>()[0].radius, 6.2);
        QCOMPARE(f.truth.list<Goalpost>().size(), std::size_t(1));
        QCOMPARE(f.truth.list<Goalpost>()[0].left, 131);
        QCOMPARE(f.truth.list<Goalpost>()[0].right, 139);
        QCOMPARE(f.truth.list<Goalpost>()[0].top, 0);
        QCOMPARE(f.truth.list<Goalpost>()[0].bottom, 61);
        QCOMPARE(f.truth.list<Goalpost>()[0].base_x, 135.0); // (left + right) / 2
        QCOMPARE(f.truth.list<Goalpost>()[0].base_y, 61.0);  // bottom
        QCOMPARE(f.truth.list<Obstacle>().size(), std::size_t(1));
        QCOMPARE(f.truth.list<Obstacle>()[0].right, 99);
        QCOMPARE(f.truth.list<Obstacle>()[0].bottom, 80);
        QCOMPARE(boundaryOf(f.truth), (std::vector<PointF>{{0, 62}, {319, 58}}));
        QCOMPARE(f.truth.list<FieldLine>().size(), std::size_t(1));
        QCOMPARE(f.truth.list<FieldLine>()[0].y2, 181.0);
    }

    void saveThenLoadRoundTrips()
    {
        Annotations a;
        FrameAnnotation& f = a.frames["f001.png"];
        f.done = true;
        f.truth.output<Ball>().push_back({1.0 / 3.0, 2.5, 6.125});
        Goalpost post;
        post.left = 10;
        post.right = 13;
        post.top = 2;
        post.bottom = 90;
        f.truth.output<Goalpost>().push_back(post);
        f.truth.output<Obstacle>().push_back({5, 6, 7, 8});
        f.truth.output<FieldBoundary>() = {{{{0, 60.5}, {100, 58.25}, {319, 61}}}};
        f.truth.output<FieldLine>().push_back({1, 2, 3, 4});
        a.frames["f000.png"].done = false; // a frame with nothing yet

        QTemporaryDir dir;
        const std::string path = dir.filePath("annotations.json").toStdString();
        QVERIFY(a.save(path, test::standardKinds()).ok());
        auto loaded = Annotations::load(path, test::standardKinds());
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
        const Annotations& b = loaded.value();
        QCOMPARE(b.frames.size(), std::size_t(2));
        QVERIFY(!b.frames.at("f000.png").done);
        const FrameAnnotation& g = b.frames.at("f001.png");
        QVERIFY(g.done);
        QCOMPARE(g.truth.list<Ball>().size(), std::size_t(1));
        QCOMPARE(g.truth.list<Ball>()[0].x, 0.333); // written to 0.001 px
        QCOMPARE(g.truth.list<Ball>()[0].radius, 6.125);
        QCOMPARE(g.truth.list<Goalpost>()[0].left, 10);
        QCOMPARE(g.truth.list<Goalpost>()[0].bottom, 90);
        QCOMPARE(g.truth.list<Goalpost>()[0].base_x, 11.5);
        QCOMPARE(g.truth.list<Goalpost>()[0].base_y, 90.0);
        QCOMPARE(g.truth.list<Obstacle>()[0].left, 5);
        QCOMPARE(g.truth.list<Obstacle>()[0].bottom, 8);
        QCOMPARE(boundaryOf(g.truth), boundaryOf(f.truth));
        QCOMPARE(g.truth.list<FieldLine>()[0].x2, 3.0);
        // Saving what was loaded gives the same text.
        QCOMPARE(b.toJson(test::standardKinds()), a.toJson(test::standardKinds()));
        QVERIFY(a.toJson(test::standardKinds()).find("\"format\": \"fieldsight-annotations/1\"") !=
                std::string::npos);
    }

    void aWriterKilledMidSaveLeavesTheOldOrTheNewFile()
    {
        // A child saves two versions of a 1000-frame annotation file in turn through
        // Annotations::save and is killed at a random moment, 100 times (a quarter of that under
        // the sanitizer: test::kKillRounds). Every time the file reads back as one version or
        // the other, whole, and loads (issue 10).
        Annotations first, second;
        for (int i = 0; i < 1000; ++i) {
            const std::string name = "frame_" + std::to_string(100000 + i) + ".png";
            FrameAnnotation& a = first.frames[name];
            a.done = true;
            a.truth.output<Ball>().push_back({10.0 + i % 300, 20.5, 6.25});
            a.truth.output<FieldBoundary>() = {{{{0, 60.5}, {160, 58.25}, {319, 61}}}};
            FrameAnnotation& b = second.frames[name];
            b = a;
            b.truth.output<Ball>()[0].x += 0.5; // another version of the file
        }
        const QTemporaryDir dir(test::crashTestDirTemplate());
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath("annotations.json").toStdString();
        const std::string first_bytes = first.toJson(test::standardKinds()),
                          second_bytes = second.toJson(test::standardKinds());
        QVERIFY(first_bytes != second_bytes);
        QVERIFY(first.save(path, test::standardKinds()).ok());
        QCOMPARE(readWholeFile(path).value(), first_bytes); // a save writes toJson()

        const auto result = test::killDuringSaves(
            path, [&](bool two) { (void)(two ? second : first).save(path, test::standardKinds()); },
            first_bytes, second_bytes, test::kKillRounds, 60000);
        QCOMPARE(result.rounds, test::kKillRounds);
        QVERIFY2(result.mixes == 0 && result.unreadable == 0, result.first_problem.c_str());
        QVERIFY(result.saw_second > 0);
        auto loaded = Annotations::load(path, test::standardKinds());
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
        QCOMPARE(loaded.value().frames.size(), std::size_t(1000));
        QVERIFY(first.save(path, test::standardKinds()).ok());
        QCOMPARE(test::temporariesOf(path), 0); // the next save removes a stray temporary
        qInfo("%d kills of a %zu-byte save: the new file %d times, the old %d times, %lld "
              "temporaries left before the next save",
              result.rounds, first_bytes.size(), result.saw_second,
              result.rounds - result.saw_second, (long long)result.temporaries);
    }

    void rejectsWrongFormatString()
    {
        auto parsed = Annotations::fromJson(R"({"format": "fieldsight-results/1", "frames": {}})",
                                            "/x/annotations.json", test::standardKinds());
        QVERIFY(!parsed.ok());
        QCOMPARE(parsed.error().message,
                 std::string("/x/annotations.json: unsupported format \"fieldsight-results/1\" "
                             "(expected \"fieldsight-annotations/1\")"));
        auto missing = Annotations::fromJson(R"({"frames": {}})", "a.json", test::standardKinds());
        QVERIFY(!missing.ok());
        QCOMPARE(missing.error().message,
                 std::string("a.json: missing \"format\": \"fieldsight-annotations/1\""));
    }

    void rejectsWrongTypesNamingTheField()
    {
        const std::pair<const char*, const char*> cases[] = {
            {R"({"f.png": {"done": "yes"}})", "frames[\"f.png\"].done must be true or false"},
            {R"({"f.png": {"balls": [{"x": 1, "y": "2", "radius": 3}]}})",
             "frames[\"f.png\"].balls[0].y must be a number"},
            {R"({"f.png": {"goalposts": {"left": 1}}})",
             "frames[\"f.png\"].goalposts must be an array"},
            {R"({"f.png": {"obstacles": [{"left": 1, "right": 2, "top": 3}]}})",
             "frames[\"f.png\"].obstacles[0].bottom must be a number"},
            {R"({"f.png": {"field_boundary": [[0, 1], [2]]}})",
             "frames[\"f.png\"].field_boundary[1] must be [x, y]"},
            {R"({"f.png": {"field_lines": [5]}})",
             "frames[\"f.png\"].field_lines[0] must be an object"},
            {R"({"f.png": 3})", "frames[\"f.png\"] must be an object"},
            // Values out of range are refused where they are read (issue 10): none overflows
            // later in matching or drawing.
            {R"({"f.png": {"balls": [{"x": 2147483647, "y": 1, "radius": 3}]}})",
             "frames[\"f.png\"].balls[0].x must be within ±1000000 px (is 2147483647)"},
            {R"({"f.png": {"balls": [{"x": 1, "y": 1, "radius": -4}]}})",
             "frames[\"f.png\"].balls[0].radius must not be negative"},
            {R"({"f.png": {"balls": [{"x": 1, "y": 1, "radius": 1e300}]}})",
             "frames[\"f.png\"].balls[0].radius must be within ±1000000 px (is 1e+300)"},
            {R"({"f.png": {"goalposts": [{"left": -2147483648, "right": 2, "top": 0,
               "bottom": 9}]}})",
             "frames[\"f.png\"].goalposts[0].left must be within ±1000000 px (is -2147483648)"},
            {R"({"f.png": {"field_boundary": [[0, 1], [1e12, 2]]}})",
             "frames[\"f.png\"].field_boundary[1] must be within ±1000000 px"},
        };
        for (const auto& [frames, problem] : cases) {
            const std::string text =
                std::string(R"({"format": "fieldsight-annotations/1", "frames": )") + frames + "}";
            auto parsed = Annotations::fromJson(text, "ann.json", test::standardKinds());
            QVERIFY(!parsed.ok());
            QCOMPARE(parsed.error().message, std::string("ann.json: ") + problem);
        }
        auto not_json = Annotations::fromJson("{", "ann.json", test::standardKinds());
        QVERIFY(!not_json.ok());
        // Where the text stops being JSON, and why.
        QVERIFY2(
            not_json.error().message.starts_with("ann.json: not valid JSON at line 1, column 2 ("),
            not_json.error().message.c_str());
    }

    void flagsAndReviewedKindsRoundTripAndOldReadersSeeTheSameTruth()
    {
        // An object's flags are optional fields of the object, "reviewed" an optional list of
        // the frame: a file without them reads as before, one with them keeps them.
        const char* text = R"({"format": "fieldsight-annotations/1", "frames": {
            "f1.png": {"done": false, "reviewed": ["goalposts"],
                       "balls": [{"x": 10, "y": 20, "radius": 5, "concealed": true, "track": 7,
                                  "keyframe": true, "interpolate": false},
                                 {"x": 40, "y": 50, "radius": 3, "interpolated": true}],
                       "goalposts": []}}})";
        auto parsed = Annotations::fromJson(text, "a.json", test::standardKinds());
        QVERIFY2(parsed.ok(), parsed.ok() ? "" : parsed.error().message.c_str());
        const FrameAnnotation& f = parsed.value().frames.at("f1.png");
        QVERIFY(f.complete("goalposts"));
        QVERIFY(!f.complete("balls"));
        QCOMPARE(f.truth.list<Ball>().size(), std::size_t(2));
        const ObjectFlags first = f.flagsOf("balls", 0);
        QVERIFY(first.concealed && first.keyframe && !first.interpolate && !first.interpolated);
        QCOMPARE(first.track, 7);
        QVERIFY(f.flagsOf("balls", 1).interpolated);
        QVERIFY(f.flagsOf("balls", 5).isDefault());

        const std::string json = parsed.value().toJson(test::standardKinds());
        auto again = Annotations::fromJson(json, "b.json", test::standardKinds());
        QVERIFY(again.ok());
        QVERIFY(again.value().frames.at("f1.png") == f);
        QCOMPARE(again.value().toJson(test::standardKinds()), json);

        FrameAnnotation changed = f;
        changed.setFlags("balls", 1, {});
        QVERIFY(!(changed == f));
        changed.eraseFlags("balls", 0);
        QVERIFY(changed.flagsOf("balls", 0).isDefault());
    }

    void badFlagsAndNewerFormatsAreRefusedByName()
    {
        auto bad = Annotations::fromJson(
            R"({"format": "fieldsight-annotations/1", "frames": {"f.png": {"balls":
                [{"x": 1, "y": 2, "radius": 3, "concealed": "yes"}]}}})",
            "ann.json", test::standardKinds());
        QVERIFY(!bad.ok());
        QVERIFY2(bad.error().message.find("ann.json") != std::string::npos &&
                     bad.error().message.find("balls[0].concealed") != std::string::npos,
                 bad.error().message.c_str());
        auto newer =
            Annotations::fromJson(R"({"format": "fieldsight-annotations/2", "frames": {}})",
                                  "new.json", test::standardKinds());
        QVERIFY(!newer.ok());
        QVERIFY2(newer.error().message.find("new.json") != std::string::npos &&
                     newer.error().message.find("newer") != std::string::npos,
                 newer.error().message.c_str());
    }

    void unknownKeysAreKeptAndWrittenBackAfterTheKnownOnes()
    {
        // What a newer Fieldsight or another tool adds: a top-level key, a frame's key, a kind
        // this version does not know, a key on a goalpost and on a ball.
        const char* text = R"({"format": "fieldsight-annotations/1", "author": {"name": "kim"},
            "frames": {"f1.png": {"note": "blurry", "done": true,
                "robots_3d": [{"x": 1, "z": 2}],
                "goalposts": [{"left": 1, "right": 4, "top": 0, "bottom": 9, "side": "left",
                               "concealed": true}],
                "balls": [{"x": 10, "y": 20, "radius": 5, "colour": [255, 128, 0]}]}}})";
        auto parsed = Annotations::fromJson(text, "a.json", test::standardKinds());
        QVERIFY2(parsed.ok(), parsed.ok() ? "" : parsed.error().message.c_str());
        const std::string saved = parsed.value().toJson(test::standardKinds());
        const auto out = nlohmann::ordered_json::parse(saved);
        QCOMPARE(out.at("author"), nlohmann::ordered_json::parse(R"({"name": "kim"})"));
        const auto& frame = out.at("frames").at("f1.png");
        QCOMPARE(frame.at("note").get<std::string>(), std::string("blurry"));
        QCOMPARE(frame.at("robots_3d"), nlohmann::ordered_json::parse(R"([{"x": 1, "z": 2}])"));
        QCOMPARE(frame.at("goalposts").at(0).at("side").get<std::string>(), std::string("left"));
        QVERIFY(frame.at("goalposts").at(0).at("concealed").get<bool>());
        QCOMPARE(frame.at("balls").at(0).at("colour"),
                 nlohmann::ordered_json::parse("[255,128,0]"));
        // The known keys first, in the documented order (done, the lists in the pipeline's
        // order), then the ones kept; "format" and "frames" first at the top.
        std::vector<std::string> keys, top;
        for (const auto& item : frame.items())
            keys.push_back(item.key());
        for (const auto& item : out.items())
            top.push_back(item.key());
        QCOMPARE(keys,
                 (std::vector<std::string>{"done", "goalposts", "balls", "note", "robots_3d"}));
        QCOMPARE(top, (std::vector<std::string>{"format", "frames", "author"}));
        // Read again, the same file.
        auto again = Annotations::fromJson(saved, "b.json", test::standardKinds());
        QVERIFY(again.ok());
        QCOMPARE(again.value().toJson(test::standardKinds()), saved);

        // An edit of the object keeps its own unknown keys (they go with its flags); removing
        // the object removes them.
        Annotations edited = parsed.value();
        FrameAnnotation& f = edited.frames.at("f1.png");
        f.truth.output<Goalpost>()[0].left = 2;
        f.setFlags("goalposts", 0, [&] {
            ObjectFlags flags = f.flagsOf("goalposts", 0);
            flags.concealed = false;
            return flags;
        }());
        const auto moved = nlohmann::json::parse(edited.toJson(test::standardKinds()));
        const auto& post = moved.at("frames").at("f1.png").at("goalposts").at(0);
        QCOMPARE(post.at("left").get<int>(), 2);
        QCOMPARE(post.at("side").get<std::string>(), std::string("left"));
        QVERIFY(!post.contains("concealed"));
        f.truth.output<Goalpost>().clear();
        f.eraseFlags("goalposts", 0);
        QVERIFY(f.flagsOf("goalposts", 0).isDefault());
    }

    void aFrameHasOneNameThatIsAFileName()
    {
        const auto problem = [](const std::string& frames) {
            auto parsed = Annotations::fromJson(
                "{\"format\": \"fieldsight-annotations/1\", \"frames\": " + frames + "}", "a.json",
                test::standardKinds());
            return parsed.ok() ? std::string() : parsed.error().message;
        };
        // One frame under two names would be scored twice, and exported once.
        const std::string twice = problem(R"({"frame_000000.png": {"done": true},
                                              "frame_000000": {"done": true}})");
        QVERIFY2(twice.starts_with("a.json: ") &&
                     twice.find("\"frame_000000\"") != std::string::npos &&
                     twice.find("\"frame_000000.png\"") != std::string::npos &&
                     twice.find("same frame") != std::string::npos,
                 twice.c_str());
        const std::string outside = problem(R"({"../lab2/frame_000000.png": {"done": true}})");
        QVERIFY2(outside.starts_with("a.json: frames[\"../lab2/frame_000000.png\"]") &&
                     outside.find("path separator") != std::string::npos,
                 outside.c_str());
        QVERIFY(problem(R"({"..": {}})").find("'..'") != std::string::npos);
        QVERIFY(problem(R"({"sub\\f.png": {}})").find("path separator") != std::string::npos);
        // A NUL inside is named escaped, never printed raw.
        const std::string nul = problem(R"({"frame_000000.png\u0000x": {"done": true}})");
        QVERIFY2(nul.find("frame_000000.png\\0x") != std::string::npos &&
                     nul.find('\0') == std::string::npos && nul.find("NUL") != std::string::npos,
                 nul.c_str());
        QVERIFY(problem(R"({"a\nb.png": {}})").find("a\\nb.png") != std::string::npos);
        // A 10,000-character name is shortened, not echoed whole.
        const std::string long_name =
            problem("{\"" + std::string(5000, 'a') + "/" + std::string(4999, 'b') + "\": {}}");
        QVERIFY2(long_name.size() < 200 && long_name.find("…") != std::string::npos &&
                     long_name.find("path separator") != std::string::npos,
                 long_name.c_str());
        QVERIFY(problem(R"({"f.png": {}, "g.png": {}, "f.jpg.png": {}})").empty());
    }

    void aWrongTypeOfFormatIsNamedNotCalledMissing()
    {
        auto number = Annotations::fromJson(R"({"format": 1, "frames": {}})", "a.json",
                                            test::standardKinds());
        QVERIFY(!number.ok());
        QVERIFY2(number.error().message.starts_with("a.json: \"format\" must be the string "
                                                    "\"fieldsight-annotations/1\", not a number") &&
                     number.error().message.find("missing") == std::string::npos,
                 number.error().message.c_str());
    }

    void aLargeFileReadsFrameByFrameWithEveryFrame()
    {
        // (No raw strings with unbalanced braces here: moc would lose the class.)
        std::string text = "{\"format\": \"fieldsight-annotations/1\", \"frames\": {";
        constexpr int kCount = 20000;
        for (int i = 0; i < kCount; ++i)
            text += (i ? "," : "") + std::string("\"f") + std::to_string(i) +
                    ".png\": {\"done\": true, \"balls\": [{\"x\": 1, \"y\": 2, \"radius\": 3}]}";
        text += "}}";
        auto parsed = Annotations::fromJson(text, "a.json", test::standardKinds());
        QVERIFY(parsed.ok());
        QCOMPARE(parsed.value().frames.size(), std::size_t(kCount));
        QCOMPARE(parsed.value().frames.at("f19999.png").truth.list<Ball>().at(0).radius, 3.0);
    }

    void everyDrawnKindRoundTripsThroughItsEditShape()
    {
        for (const PerceptKind* kind : test::standardKinds()) {
            if (kind->form == ShapeForm::None)
                continue;
            EditShape shape;
            switch (kind->form) {
            case ShapeForm::Circle:
                shape = {{{12.5, 30}}, 6};
                break;
            case ShapeForm::Box:
                shape = {{{10, 20}, {30, 60}}, 0};
                break;
            case ShapeForm::Polyline:
                shape = {{{0, 50}, {100, 40}, {319, 55}}, 0};
                break;
            case ShapeForm::Segment:
                shape = {{{5, 6}, {70, 80}}, 0};
                break;
            case ShapeForm::None:
                break;
            }
            auto entry = kind->make();
            entry->setShapes({shape});
            QCOMPARE(entry->size(), std::size_t(1));
            QVERIFY2(entry->shapes().front() == shape, std::string(kind->key).c_str());
        }
        // A box drawn from its bottom-right corner is the same box.
        auto box = perceptKind<Obstacle>().make();
        box->setShapes({{{{30, 60}, {10, 20}}, 0}});
        QVERIFY((box->shapes().front() == EditShape{{{10, 20}, {30, 60}}, 0}));
    }

    void loadingAMissingFileNamesIt()
    {
        auto loaded = Annotations::load("/nonexistent/annotations.json", test::standardKinds());
        QVERIFY(!loaded.ok());
        QCOMPARE(
            loaded.error().message,
            std::string("cannot read /nonexistent/annotations.json: No such file or directory"));
    }
};

FIELDSIGHT_TEST_SUITE(TestAnnotations, None)

#include "test_annotations.moc"
