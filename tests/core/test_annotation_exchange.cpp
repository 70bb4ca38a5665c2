// Annotations to and from other tools: `fieldsight annotations export --coco` read back by this
// test's own reading of both files (nlohmann::json on the raw annotations and the COCO output,
// image sizes from the PNGs), and the Dutch Nao Team's hand labels turned into goalpost truth,
// on a made-up label file with known boxes and on the real files in ../shared.
#include "support/test_suite.h"
#include "support/child_process.h"
#include "support/synthetic_frames.h"
#include "support/test_images.h"
#include "visioncore/io/annotations.h"
#include "visioncore/io/dnt_labels.h"
#include "visioncore/framework/controller.h"
#include "visioncore/percepts/goalpost.h"

#include <nlohmann/json.hpp>

#include <QtTest>

#include <QTemporaryDir>

#include <algorithm>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>

using namespace fieldsight;
using fieldsight::test::Outcome;
using Json = nlohmann::json;

namespace {

std::string lab1()
{
    return test::sampleStreamsDir() + "/lab1";
}

/// What the COCO file must hold for one true object: its category name and bbox.
struct Expected
{
    std::string category;
    std::vector<double> bbox;
    std::vector<double> polyline; ///< for lines and the boundary
    bool concealed = false;       ///< COCO's "occluded"
};

/// The objects of one frame of a raw fieldsight-annotations/1 frame object, as COCO should
/// give them (worked out here from SPEC §5.2 and docs/formats.md, not with the writer's code).
/// COCO's [x, y, w, h] of the span [x0, x1] x [y0, y1] clipped to a W x H image, w and h at
/// least 1 px inside it.
std::vector<double> clippedBox(double x0, double y0, double x1, double y1, int w, int h)
{
    const auto axis = [](double lo, double hi, double size) {
        lo = std::clamp(lo, 0.0, size), hi = std::clamp(hi, 0.0, size);
        if (hi - lo < 1)
            hi = std::min(size, lo + 1), lo = hi - 1;
        return std::pair{lo, hi - lo};
    };
    const auto [x, bw] = axis(x0, x1, w);
    const auto [y, bh] = axis(y0, y1, h);
    return {x, y, bw, bh};
}

std::vector<Expected> expectedObjects(const Json& frame, int w, int h)
{
    std::vector<Expected> out;
    for (const Json& b : frame.value("balls", Json::array())) {
        const double x = b.at("x"), y = b.at("y"), r = b.at("radius");
        out.push_back({"balls",
                       clippedBox(x - r, y - r, x + r, y + r, w, h),
                       {},
                       b.value("concealed", false)});
    }
    for (const char* key : {"goalposts", "obstacles"})
        for (const Json& o : frame.value(key, Json::array())) {
            const double l = o.at("left"), t = o.at("top"), r = o.at("right"), b = o.at("bottom");
            out.push_back(
                {key, clippedBox(l, t, r + 1, b + 1, w, h), {}, o.value("concealed", false)});
        }
    if (frame.contains("field_boundary")) {
        Expected e{"field_boundary", {}, {}};
        double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
        for (const Json& p : frame.at("field_boundary")) {
            const double x = p.at(0), y = p.at(1);
            e.polyline.insert(e.polyline.end(), {x, y});
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
        e.bbox = clippedBox(x0, y0, x1, y1, w, h);
        out.push_back(e);
    }
    for (const Json& l : frame.value("field_lines", Json::array())) {
        const double x1 = l.at("x1"), y1 = l.at("y1"), x2 = l.at("x2"), y2 = l.at("y2");
        out.push_back({"field_lines",
                       clippedBox(std::min(x1, x2), std::min(y1, y2), std::max(x1, x2),
                                  std::max(y1, y2), w, h),
                       {x1, y1, x2, y2},
                       l.value("concealed", false)});
    }
    return out;
}

bool near(const std::vector<double>& a, const Json& b)
{
    if (!b.is_array() || a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::abs(a[i] - b.at(i).get<double>()) > 1e-6)
            return false;
    return true;
}

/// A folder of `count` black PNG frames named by `name(i)`.
void makeFrames(const std::string& folder, int count, int width, int height,
                const std::function<std::string(int)>& name)
{
    std::filesystem::create_directories(folder);
    for (int i = 0; i < count; ++i)
        QVERIFY(fieldsight::test::imwrite(folder + "/" + name(i),
                                          cv::Mat(height, width, CV_8UC3, cv::Scalar(0, 90, 0))));
}

std::string numbered(int i)
{
    char name[32];
    std::snprintf(name, sizeof name, "%06d.png", i + 1);
    return name;
}

Goalpost box(int left, int right, int top, int bottom)
{
    return {left, right, top, bottom, 0, 0, GoalpostSide::Unknown};
}

bool sameBox(const Goalpost& a, const Goalpost& b)
{
    return a.left == b.left && a.right == b.right && a.top == b.top && a.bottom == b.bottom;
}

} // namespace

class TestAnnotationExchange : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    std::string path(const std::string& name) const
    {
        return m_dir.filePath(QString::fromStdString(name)).toStdString();
    }
    Outcome fieldsight(const std::vector<std::string>& args)
    {
        return test::runChild(FIELDSIGHT_EXE, args, m_dir.path().toStdString(), RLIM_INFINITY,
                              false, 120);
    }

private slots:
    void cocoExportReadsBackAsTheAnnotations()
    {
        const std::string coco_path = path("lab1_coco.json");
        const Outcome o = fieldsight({"annotations", "export", lab1(), "--coco", coco_path});
        QVERIFY2(o.status == 0, o.err.c_str());
        const Json coco = Json::parse(test::readAll(coco_path), nullptr, false);
        const Json truth = Json::parse(test::readAll(lab1() + "/annotations.json"), nullptr, false);
        QVERIFY(coco.is_object() && truth.is_object());

        std::map<int, std::string> category_names;
        for (const Json& c : coco.at("categories"))
            QVERIFY(category_names.emplace(c.at("id").get<int>(), c.at("name")).second);
        std::set<std::string> names;
        for (const auto& [id, name] : category_names)
            names.insert(name);
        QCOMPARE(names, (std::set<std::string>{"balls", "goalposts", "obstacles", "field_boundary",
                                               "field_lines"}));

        std::map<int, std::string> image_files;
        int width = 0, height = 0;
        for (const Json& image : coco.at("images")) {
            const std::string file = image.at("file_name");
            QVERIFY(image_files.emplace(image.at("id").get<int>(), file).second);
            const cv::Mat pixels = fieldsight::test::imread(lab1() + "/" + file);
            QVERIFY2(!pixels.empty(), file.c_str());
            QCOMPARE(image.at("width").get<int>(), pixels.cols);
            QCOMPARE(image.at("height").get<int>(), pixels.rows);
            width = pixels.cols, height = pixels.rows;
        }
        QCOMPARE(image_files.size(), truth.at("frames").size());

        // Every annotation once, on an image and a category that exist, with the frame's bboxes.
        std::set<int> ids;
        std::map<std::string, std::vector<const Json*>> by_image;
        for (const Json& a : coco.at("annotations")) {
            QVERIFY(ids.insert(a.at("id").get<int>()).second);
            QVERIFY(image_files.count(a.at("image_id").get<int>()));
            QVERIFY(category_names.count(a.at("category_id").get<int>()));
            QCOMPARE(a.at("iscrowd").get<int>(), 0);
            by_image[image_files.at(a.at("image_id").get<int>())].push_back(&a);
        }
        std::size_t expected_count = 0;
        for (const auto& [name, frame] : truth.at("frames").items()) {
            const std::vector<Expected> expected = expectedObjects(frame, width, height);
            expected_count += expected.size();
            std::vector<const Json*> found = by_image[name];
            QCOMPARE(found.size(), expected.size());
            for (const Expected& e : expected) {
                const auto it = std::find_if(found.begin(), found.end(), [&](const Json* a) {
                    return category_names.at(a->at("category_id").get<int>()) == e.category &&
                           near(e.bbox, a->at("bbox")) &&
                           (e.polyline.empty() || near(e.polyline, a->at("polyline"))) &&
                           a->at("attributes").at("occluded").get<bool>() == e.concealed;
                });
                QVERIFY2(it != found.end(), (name + ": no " + e.category + " at the bbox").c_str());
                const Json& bbox = (*it)->at("bbox");
                if (e.category == "goalposts" || e.category == "obstacles")
                    QCOMPARE((*it)->at("area").get<double>(),
                             bbox.at(2).get<double>() * bbox.at(3).get<double>());
                found.erase(it);
            }
        }
        QCOMPARE(ids.size(), expected_count);
        QVERIFY(expected_count > 200);
    }

    void cocoExportKeepsFlagsAndRefusesToWriteOverAnInput()
    {
        const std::string stream = path("flagged");
        makeFrames(stream, 2, 64, 48,
                   [](int i) { return "frame_00000" + std::to_string(i) + ".png"; });
        test::writeBytes(stream + "/annotations.json", R"({"format": "fieldsight-annotations/1",
            "frames": {"frame_000001.png": {"done": false, "reviewed": ["goalposts"],
              "balls": [{"x": 10, "y": 12, "radius": 3, "concealed": true, "track": 4,
                         "keyframe": true}]}}})");
        const Outcome o = fieldsight({"annotations", "export", stream, "--coco", "-"});
        QVERIFY2(o.status == 0, o.err.c_str());
        const Json coco = Json::parse(o.out, nullptr, false);
        QCOMPARE(coco.at("images").size(), std::size_t(1));
        const Json& image = coco.at("images").at(0);
        QCOMPARE(image.at("id").get<int>(), 2); // the stream index + 1
        QCOMPARE(image.at("fieldsight").at("done").get<bool>(), false);
        QCOMPARE(image.at("fieldsight").at("reviewed"), Json::array({"goalposts"}));
        const Json& ball = coco.at("annotations").at(0);
        QCOMPARE(ball.at("attributes").at("concealed").get<bool>(), true);
        QCOMPARE(ball.at("attributes").at("occluded").get<bool>(), true);
        QCOMPARE(ball.at("attributes").at("track_id").get<int>(), 4);
        QCOMPARE(ball.at("attributes").at("keyframe").get<bool>(), true);
        QVERIFY(near({7, 9, 6, 6}, ball.at("bbox")));
        QVERIFY(near({10, 12, 3}, ball.at("circle")));

        const std::string before = test::readAll(stream + "/annotations.json");
        const Outcome over =
            fieldsight({"annotations", "export", stream, "--coco", stream + "/annotations.json"});
        QCOMPARE(over.status, 2);
        QVERIFY2(over.err.find("nothing was written") != std::string::npos, over.err.c_str());
        QCOMPARE(test::readAll(stream + "/annotations.json"), before);

        // A frame the stream lacks is named.
        test::writeBytes(path("stray.json"), R"({"format": "fieldsight-annotations/1",
            "frames": {"frame_000007.png": {"done": true}}})");
        const Outcome stray = fieldsight(
            {"annotations", "export", stream, "--annotations", path("stray.json"), "--coco", "-"});
        QCOMPARE(stray.status, 2);
        QVERIFY2(stray.err.find("frame_000007.png") != std::string::npos, stray.err.c_str());
    }

    void cocoBoxesLieInsideTheImageAndAreNeverEmpty()
    {
        // 64 x 48 frames: a ball cut by the bottom edge, a post cut by the left edge and running
        // below the picture, a field line from x = -5 lying flat, a boundary wholly inside.
        const std::string stream = path("cut");
        makeFrames(stream, 1, 64, 48, [](int) { return std::string("frame_000000.png"); });
        test::writeBytes(stream + "/annotations.json", R"({"format": "fieldsight-annotations/1",
            "frames": {"frame_000000.png": {"done": true,
              "balls": [{"x": 20, "y": 45, "radius": 6}],
              "goalposts": [{"left": -3, "right": 2, "top": 10, "bottom": 60}],
              "field_lines": [{"x1": -5, "y1": 30, "x2": 40, "y2": 30}],
              "field_boundary": [[0, 12], [63, 12]]}}})");
        const Outcome o = fieldsight({"annotations", "export", stream, "--coco", "-"});
        QVERIFY2(o.status == 0, o.err.c_str());
        const Json coco = Json::parse(o.out, nullptr, false);
        QVERIFY(coco.is_object());
        std::map<std::string, const Json*> by_name;
        std::map<int, std::string> category;
        for (const Json& c : coco.at("categories"))
            category[c.at("id").get<int>()] = c.at("name");
        for (const Json& a : coco.at("annotations")) {
            by_name[category.at(a.at("category_id").get<int>())] = &a;
            const Json& b = a.at("bbox");
            QVERIFY2(b.at(0).get<double>() >= 0 && b.at(1).get<double>() >= 0 &&
                         b.at(2).get<double>() >= 1 && b.at(3).get<double>() >= 1 &&
                         b.at(0).get<double>() + b.at(2).get<double>() <= 64 &&
                         b.at(1).get<double>() + b.at(3).get<double>() <= 48,
                     b.dump().c_str());
        }
        QCOMPARE(by_name.size(), std::size_t(4));
        const Json& ball = *by_name.at("balls");
        QVERIFY2(near({14, 39, 12, 9}, ball.at("bbox")), ball.dump().c_str());
        QVERIFY(near({20, 45, 6}, ball.at("circle"))); // the annotation as it is
        // The part of the disc inside the picture: less than π r², more than half of it.
        const double area = ball.at("area").get<double>();
        QVERIFY2(area > 0.5 * std::numbers::pi * 36 && area < 0.9 * std::numbers::pi * 36,
                 ball.dump().c_str());
        const Json& post = *by_name.at("goalposts");
        QVERIFY2(near({0, 10, 3, 38}, post.at("bbox")), post.dump().c_str());
        QCOMPARE(post.at("area").get<double>(), 3.0 * 38);
        const Json& line = *by_name.at("field_lines");
        QVERIFY2(near({0, 30, 40, 1}, line.at("bbox")), line.dump().c_str());
        QVERIFY(near({-5, 30, 40, 30}, line.at("polyline")));
        QVERIFY(near({0, 12, 63, 1}, by_name.at("field_boundary")->at("bbox")));
    }

    void oneFrameUnderTwoNamesIsRefusedNotExportedOnce()
    {
        const std::string stream = path("two_names");
        makeFrames(stream, 1, 64, 48, [](int) { return std::string("frame_000000.png"); });
        test::writeBytes(stream + "/annotations.json", R"({"format": "fieldsight-annotations/1",
            "frames": {"frame_000000.png": {"done": true, "balls": [{"x": 5, "y": 5, "radius": 2}]},
                       "frame_000000": {"done": true, "balls": [{"x": 30, "y": 9, "radius": 3}]}}})");
        const Outcome o = fieldsight({"annotations", "export", stream, "--coco", "-"});
        QCOMPARE(o.status, 2);
        QVERIFY(o.out.empty());
        QVERIFY2(o.err.find("annotations.json") != std::string::npos &&
                     o.err.find("\"frame_000000\"") != std::string::npos &&
                     o.err.find("same frame") != std::string::npos,
                 o.err.c_str());
    }

    void dntLabelsParseAndRefuseWhatIsNotALabel()
    {
        auto ok = parseDntLabels("'000001 -280 0 0 4VGA.png [X<153,122>;G<125,68>;U<120,30>;]'\r\n"
                                 "\r\n'000002 a.png []'\r\n",
                                 "labels.txt");
        QVERIFY2(ok.ok(), ok ? "" : ok.error().message.c_str());
        QCOMPARE(ok.value().size(), std::size_t(2));
        QCOMPARE(ok.value()[0].name, std::string("000001 -280 0 0 4VGA.png"));
        QCOMPARE(ok.value()[0].number(), std::string("000001"));
        QCOMPARE(ok.value()[0].points.size(), std::size_t(3));
        QCOMPARE(ok.value()[0].points[1].label, 'G');
        QCOMPARE(ok.value()[0].points[1].x, 125);
        QCOMPARE(ok.value()[0].points[1].y, 68);
        QCOMPARE(ok.value()[1].line, std::size_t(3));
        QVERIFY(ok.value()[1].points.empty());

        auto bad = parseDntLabels("'000001 a.png []'\n'000002 b.png [G<1,2>;G<x,3>;]'\n", "l.txt");
        QVERIFY(!bad.ok());
        QVERIFY2(bad.error().message.find("l.txt: line 2: 'G<x,3>'") != std::string::npos,
                 bad.error().message.c_str());
        auto unquoted = parseDntLabels("000001 a.png [G<1,2>]\n", "l.txt");
        QVERIFY(!unquoted.ok());
        QVERIFY(unquoted.error().message.find("line 1") != std::string::npos);
    }

    void dntLabelsNameWhatTheyRefuseAndTakeABom()
    {
        // A byte order mark before the first line is no part of it.
        auto bom = parseDntLabels("\xEF\xBB\xBF'000001 a.png [G<1,2>;U<1,0>]'\n", "l.txt");
        QVERIFY2(bom.ok(), bom ? "" : bom.error().message.c_str());
        QCOMPARE(bom.value().at(0).name, std::string("000001 a.png"));
        // An item of another letter is refused naming the line, not dropped.
        auto unknown =
            parseDntLabels("'000001 a.png []'\n'000002 b.png [G<1,2>;Q<3,4>]'\n", "l.txt");
        QVERIFY(!unknown.ok());
        QVERIFY2(unknown.error().message.starts_with("l.txt: line 2: 'Q<3,4>': unknown label 'Q'"),
                 unknown.error().message.c_str());
        // A NUL inside an item is written escaped.
        auto nul = parseDntLabels(std::string("'000001 a.png [G<1,\0>]'\n", 24), "l.txt");
        QVERIFY(!nul.ok());
        QVERIFY2(nul.error().message.find("G<1,\\0>") != std::string::npos &&
                     nul.error().message.find('\0') == std::string::npos,
                 nul.error().message.c_str());
        // Many post labels on one line: refused by a bound, not paired each with each (which
        // grew with their square: 10,000 took 8 s and 842 MB); other items any number.
        std::string posts = "'000001 a.png [";
        for (int i = 0; i < 65; ++i)
            posts += "G<" + std::to_string(i) + ",100>;";
        auto crowded = parseDntLabels(posts + "]'\n", "l.txt");
        QVERIFY(!crowded.ok());
        QVERIFY2(crowded.error().message.starts_with("l.txt: line 1: more than 64 post labels"),
                 crowded.error().message.c_str());
        std::string crossings = "'000001 a.png [";
        for (int i = 0; i < 200000; ++i)
            crossings += "L<" + std::to_string(i % 320) + ",5>;";
        QVERIFY(crossings.size() < (std::size_t(4) << 20));
        auto many = parseDntLabels(crossings + "]'\n", "l.txt");
        QVERIFY(many.ok());
        QCOMPARE(many.value().at(0).points.size(), std::size_t(200000));
    }

    void dntLabelsOfOneFrameTwiceAreRefused()
    {
        const std::string stream = path("dnt_twice");
        makeFrames(stream, 1, 320, 240, numbered);
        const std::string labels = path("twice_labels.txt");
        test::writeBytes(labels, "'000001 0 0 0 QVGA.png [G<100,100>;]'\n"
                                 "'000001.png [G<200,100>;]'\n");
        const Outcome o = fieldsight(
            {"annotations", "import-dnt", labels, "--stream", stream, "--out", path("t.json")});
        QCOMPARE(o.status, 2);
        QVERIFY2(o.err.find("line 2") != std::string::npos &&
                     o.err.find("line 1 labels already") != std::string::npos,
                 o.err.c_str());
        QVERIFY(!std::filesystem::exists(path("t.json")));
    }

    void dntLabelsBecomeGoalpostBoxes()
    {
        const std::string stream = path("dnt_made_up");
        makeFrames(stream, 3, 320, 240, numbered);
        const std::string labels = path("made_up_labels.txt");
        test::writeBytes(labels,
                         "'000001 0 0 0 QVGA.png [X<162,156>;G<100,100>;U<98,30>;G<230,101>;]'\r\n"
                         "'000002 0 0 45 QVGA.png []'\r\n"
                         "'000003 0 0 90 QVGA.png [G<5,245>;U<300,20>;]'\r\n"
                         "'000009 0 0 90 QVGA.png [G<5,100>;]'\r\n");
        const std::string out = path("made_up_annotations.json");
        const Outcome o =
            fieldsight({"annotations", "import-dnt", labels, "--stream", stream, "--out", out});
        QVERIFY2(o.status == 0, o.err.c_str());
        QVERIFY2(o.out.find("4 goalposts on 3 frames") != std::string::npos, o.out.c_str());
        QVERIFY2(o.out.find("1 labelled pictures are not in the stream") != std::string::npos,
                 o.out.c_str());

        auto read = Annotations::load(out, Pipeline::standard().perceptKinds());
        QVERIFY2(read.ok(), read ? "" : read.error().message.c_str());
        const auto& frames = read.value().frames;
        QCOMPARE(frames.size(), std::size_t(3));
        for (const auto& [name, frame] : frames) {
            QVERIFY(!frame.done);
            QCOMPARE(frame.reviewed, (std::set<std::string, std::less<>>{"goalposts"}));
            QVERIFY(frame.complete("goalposts") && !frame.complete("balls"));
        }
        // Foot and top: 71 px tall, so 10 px wide around the foot; the other foot is sized by
        // the feet's distance (130 / 13 = 10) and made 7 widths tall.
        const auto& first = frames.at("000001.png").truth.list<Goalpost>();
        QCOMPARE(first.size(), std::size_t(2));
        QVERIFY(sameBox(first[0], box(96, 105, 30, 100)));
        QVERIFY(sameBox(first[1], box(226, 235, 32, 101)));
        QVERIFY(frames.at("000002.png").truth.find<Goalpost>() != nullptr); // reviewed: none
        QVERIFY(frames.at("000002.png").truth.list<Goalpost>().empty());
        // A lone foot below the picture is clamped to its bottom row; a lone top reaches below
        // the picture; both the default 10 px wide.
        const auto& third = frames.at("000003.png").truth.list<Goalpost>();
        QCOMPARE(third.size(), std::size_t(2));
        QVERIFY(sameBox(third[0], box(1, 10, 170, 239)));
        QVERIFY(sameBox(third[1], box(296, 305, 20, 239)));

        // The default output is beside the stream, once: never over a file of it.
        QCOMPARE(fieldsight({"annotations", "import-dnt", labels, "--stream", stream}).status, 0);
        const std::string written = test::readAll(stream + "/annotations.json");
        QCOMPARE(written, test::readAll(out));
        const Outcome again = fieldsight(
            {"annotations", "import-dnt", labels, "--stream", stream, "--post-width", "4"});
        QCOMPARE(again.status, 2);
        QVERIFY2(again.err.find("nothing was written") != std::string::npos, again.err.c_str());
        QCOMPARE(test::readAll(stream + "/annotations.json"), written);
    }

    void realDntLabelsLandOnTheYellowPosts()
    {
        const std::string reference = test::referenceDataDir();
        if (reference.empty() ||
            !std::filesystem::exists(reference + "/dnt_uva_2013_fieldpictures"))
            QSKIP("../shared/reference_data/dnt_uva_2013_fieldpictures is absent");
        const std::string base = reference + "/dnt_uva_2013_fieldpictures/";
        struct Set
        {
            const char* folder;
            std::size_t pictures, not_in_stream, posts;
        };
        // straightwalk: 23 pictures with both feet, one with one, six with none. qvga: 26 of
        // the 64 pictures copied, 39 feet and every top above one of them.
        for (const Set& set :
             {Set{"straightwalk", 30, 0, 47}, Set{"qvga_goal_subset", 26, 38, 39}}) {
            const std::string stream = base + set.folder;
            const std::string out = path(std::string(set.folder) + "_truth.json");
            const Outcome o =
                fieldsight({"annotations", "import-dnt", stream + "/annotations_original.txt",
                            "--stream", stream, "--out", out});
            QVERIFY2(o.status == 0, o.err.c_str());
            if (set.not_in_stream > 0)
                QVERIFY2(o.out.find(std::to_string(set.not_in_stream) +
                                    " labelled pictures are not in the stream") !=
                             std::string::npos,
                         o.out.c_str());
            auto read = Annotations::load(out, Pipeline::standard().perceptKinds());
            QVERIFY(read.ok());
            QCOMPARE(read.value().frames.size(), set.pictures);
            std::size_t posts = 0, on_yellow = 0;
            for (const auto& [name, frame] : read.value().frames) {
                QCOMPARE(frame.reviewed.count("goalposts"), std::size_t(1));
                const cv::Mat bgr = fieldsight::test::imread(stream + "/" + name);
                QVERIFY(!bgr.empty());
                for (const Goalpost& p : frame.truth.list<Goalpost>()) {
                    ++posts;
                    QVERIFY(p.left <= p.right && p.top <= p.bottom && p.bottom < bgr.rows);
                    // The box's middle column a little above its bottom is on the post.
                    const cv::Vec3b px =
                        bgr.at<cv::Vec3b>(std::max(0, p.bottom - 6), (p.left + p.right) / 2);
                    on_yellow += px[2] > 120 && px[1] > 120 && px[0] < 0.6 * std::min(px[1], px[2]);
                }
            }
            QCOMPARE(posts, set.posts);
            QVERIFY2(on_yellow * 10 >= posts * 9,
                     qPrintable(QString("%1 of %2 on yellow").arg(on_yellow).arg(posts)));
            if (std::string(set.folder) == "qvga_goal_subset") {
                // G<96,88> under U<91,11>: 78 px tall, so 11 px wide around the foot.
                const auto& first = read.value().frames.at("000001.png").truth.list<Goalpost>();
                QCOMPARE(first.size(), std::size_t(2));
                QVERIFY(sameBox(first[0], box(91, 101, 11, 88)));
            }
        }
    }
};

FIELDSIGHT_TEST_SUITE(TestAnnotationExchange, None)

#include "test_annotation_exchange.moc"
