// Not a test: the LUT editor tried as a new user would, on real frames. It builds a colour table
// for the Dutch Nao Team's straight-walk pictures (reference_data/dnt_uva_2013_fieldpictures,
// yellow goals) in the real main window, from an empty LUT, with scripted clicks and wand fills
// (each one edit, as a user's mouse would make it), and leaves what is needed to score it:
//   lut_trial OUT_DIR
//   fieldsight eval OUT_DIR/stream --lut OUT_DIR/dnt.lut
// OUT_DIR/stream links the pictures and holds annotations.json made from the hand-labelled post
// feet (G labels): each foot becomes a post 7 px wide from the image top to the foot, so eval's
// rule accepts a detected base within max(4, 7) px across and 6 px (or 10 % of the height) of
// the foot. Every picture is "done" (a picture without G labels has no post foot to find).
// Then, as a user who finds the QVGA pictures' posts missed (a darker, olive yellow in their
// light), it opens that set with the table and clicks the posts on two of its pictures, 000009
// and 000048, and wand-fills the carpet there; the other 24 are not touched, so they score the
// table as a venue's new frames would. Screenshots of the editor go to OUT_DIR/*.png.
#include "ui/scans/edit_effect_scan.h"
#include "ui/actions/session_files.h"
#include "ui/main_window.h"
#include "ui/settings/window_settings.h"
#include "ui/panels/lut_panel.h"
#include "ui/panels/uv_plane_panel.h"

#include "tool_platform.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

#include <nlohmann/json.hpp>

#include <iostream>

using namespace fieldsight;

namespace {

struct Step
{
    int frame;        ///< 1-based, as the file names
    const char* tool; ///< a tool id
    Colour colour;
    Tolerance tolerance;
    QPoint at;
};

/// G labels of annotations_original.txt as SPEC §5.2 annotations.
bool writeAnnotations(const QString& labels, const QString& out)
{
    QFile in(labels);
    if (!in.open(QIODevice::ReadOnly))
        return false;
    nlohmann::ordered_json frames = nlohmann::ordered_json::object();
    const QRegularExpression line(QStringLiteral("^'(\\d{6}) .*\\[(.*)\\]'"));
    const QRegularExpression foot(QStringLiteral("G<(\\d+),(\\d+)>"));
    for (const QString& text : QString::fromUtf8(in.readAll()).split('\n')) {
        const auto m = line.match(text.trimmed());
        if (!m.hasMatch())
            continue;
        nlohmann::ordered_json posts = nlohmann::ordered_json::array();
        for (auto it = foot.globalMatch(m.captured(2)); it.hasNext();) {
            const auto g = it.next();
            const int x = g.captured(1).toInt(), y = g.captured(2).toInt();
            posts.push_back({{"left", x - 3}, {"right", x + 3}, {"top", 0}, {"bottom", y}});
        }
        frames[(m.captured(1) + ".png").toStdString()] = {{"done", true}, {"goalposts", posts}};
    }
    QFile o(out);
    if (!o.open(QIODevice::WriteOnly))
        return false;
    const std::string json =
        nlohmann::ordered_json{{"format", "fieldsight-annotations/1"}, {"frames", frames}}.dump(1);
    return o.write(json.data(), qint64(json.size())) == qint64(json.size());
}

} // namespace

int main(int argc, char** argv)
{
    tools::useOffscreenWithoutDisplay();
    QApplication app(argc, argv);
    QApplication::setOrganizationName("FieldsightTrial");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Builds a colour table for the Dutch Nao Team's straight-walk pictures in the main window, "
        "from an empty LUT, with scripted clicks and wand fills, and writes OUT_DIR/stream (the "
        "pictures, linked, with annotations.json), OUT_DIR/dnt.lut and screenshots of the editor "
        "(OUT_DIR/*.png). Score the table with\n"
        "  fieldsight eval OUT_DIR/stream --lut OUT_DIR/dnt.lut\n"
        "Needs ../shared/reference_data/dnt_uva_2013_fieldpictures. Runs offscreen when no display "
        "is set.");
    parser.addHelpOption();
    parser.addPositionalArgument("OUT_DIR", "the folder to write (its stream/ is replaced)");
    parser.process(app);
    if (parser.positionalArguments().size() != 1) {
        std::cerr << "usage: lut_trial OUT_DIR (lut_trial --help says more)\n";
        return 2;
    }
    const QString sets =
        QStringLiteral(FIELDSIGHT_SHARED_DIR "/reference_data/dnt_uva_2013_fieldpictures");
    const QString source = sets + "/straightwalk";
    if (!QFileInfo(source).isDir()) {
        std::cerr << "no reference data at " << source.toStdString() << "\n";
        return 2;
    }
    const QString out = parser.positionalArguments().front();
    const QString stream = out + "/stream";
    QDir(stream).removeRecursively();
    QDir().mkpath(stream);
    for (const QString& f : QDir(source).entryList({"*.png"}))
        QFile::link(source + "/" + f, stream + "/" + f);
    if (!writeAnnotations(source + "/annotations_original.txt", stream + "/annotations.json")) {
        std::cerr << "cannot write the annotations\n";
        return 1;
    }

    ui::MainWindow w;
    w.resize(1500, 950);
    w.show();
    QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
    w.files().openStream(stream); // no default.lut: an empty table
    if (!opened.wait(20000) || !opened.front().front().toBool())
        return 1;
    const auto waitFrame = [&] {
        for (int i = 0; i < 500 && w.session().stream().waiting(); ++i)
            QTest::qWait(10);
        QApplication::processEvents();
    };
    waitFrame();
    for (auto* dock : {"lut_dock", "uv_dock"})
        if (auto* d = w.findChild<QDockWidget*>(dock))
            d->raise();

    // What a user does: on a far, a middle and a near picture, a wand fill of the carpet, clicks
    // on the lines and on the posts (at the labelled feet, a little above them).
    const std::vector<Step> steps = {
        {8, "wand", Colour::Green, {14, 6, 6}, {60, 200}},
        {8, "click", Colour::White, {16, 5, 5}, {157, 142}},
        {8, "click", Colour::Yellow, {20, 8, 8}, {113, 60}},
        {8, "click", Colour::Yellow, {20, 8, 8}, {205, 60}},
        {20, "wand", Colour::Green, {14, 6, 6}, {160, 200}},
        {20, "click", Colour::Yellow, {20, 8, 8}, {60, 60}},
        {20, "click", Colour::Yellow, {20, 8, 8}, {268, 60}},
        {20, "click", Colour::White, {16, 5, 5}, {160, 145}},
        {2, "wand", Colour::Green, {14, 6, 6}, {160, 200}},
        {2, "click", Colour::Yellow, {20, 8, 8}, {138, 60}},
        // Then, seeing the side-by-side view: the lit middle of the carpet was left unclassified,
        // so more wand fills there, and on a picture of the other set.
        {8, "wand", Colour::Green, {18, 8, 8}, {160, 110}},
        {14, "wand", Colour::Green, {18, 8, 8}, {160, 120}},
        {20, "wand", Colour::Green, {18, 8, 8}, {100, 110}},
        {2, "wand", Colour::Green, {18, 8, 8}, {250, 130}},
    };
    int edits = 0;
    const auto perform = [&](const Step& s) {
        w.session().stream().setCurrentIndex(std::size_t(s.frame - 1));
        waitFrame();
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
        w.tools().activate(QString::fromLatin1(s.tool));
        w.tools().settings().setColour(s.colour);
        w.tools().settings().setTolerance(s.tolerance);
        const int before = w.session().lut().undoStack().count();
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, s.at);
        waitFrame();
        edits += w.session().lut().undoStack().count() - before;
    };
    const auto save = [&] {
        for (int i = 0; i < 2000 && w.session().effectScan().running(); ++i)
            QTest::qWait(10);
        if (Status s = w.session().lut().saveAs(out + "/dnt.lut"); !s) {
            std::cerr << s.error().message << "\n";
            return false;
        }
        return true;
    };
    for (const Step& s : steps)
        perform(s);
    if (!save())
        return 1;

    // The QVGA set with that table: its posts in a darker light, clicked on two pictures (1-based
    // in the set's file order: 5 is 000009, 20 is 000048), a far post and a near one.
    const QString qvga = out + "/qvga";
    QDir(qvga).removeRecursively();
    QDir().mkpath(qvga);
    for (const QString& f : QDir(sets + "/qvga_goal_subset").entryList({"*.png"}))
        QFile::link(sets + "/qvga_goal_subset/" + f, qvga + "/" + f);
    opened.clear();
    w.files().openStream(qvga, out + "/dnt.lut");
    if (!opened.wait(20000) || !opened.front().front().toBool())
        return 1;
    waitFrame();
    for (const Step& s : std::vector<Step>{
             {5, "click", Colour::Yellow, {20, 8, 8}, {305, 60}},
             {20, "click", Colour::Yellow, {20, 8, 8}, {290, 80}},
             {20, "click", Colour::Yellow, {20, 8, 8}, {110, 180}},
             // ...and, seeing the carpet speckled black in the side-by-side view, wand fills.
             {5, "wand", Colour::Green, {18, 8, 8}, {160, 200}},
             {20, "wand", Colour::Green, {18, 8, 8}, {220, 200}},
         })
        perform(s);
    std::cout << edits << " edits\n";
    if (!save())
        return 1;
    w.files().openStream(stream, out + "/dnt.lut");
    QTest::qWait(500);

    // The editor as the user sees it at the end, on a middle picture, zoomed.
    w.session().stream().setCurrentIndex(12);
    waitFrame();
    w.view().setMode(ui::ViewMode::SideBySide);
    w.view().fitToWindow();
    QTest::qWait(100);
    w.grab().save(out + "/editor_side.png");
    w.view().setMode(ui::ViewMode::Raw);
    w.view().setZoom(2);
    w.view().setImageOrigin({0, 0});
    w.tools().activate(QStringLiteral("click"));
    w.tools().settings().setColour(Colour::Yellow);
    QTest::mouseMove(&w.view(), QPoint(2 * 226 + 1, 2 * 70 + 1));
    QTest::qWait(100);
    w.grab().save(out + "/editor_preview.png");
    std::cout << "saved " << (out + "/dnt.lut").toStdString() << "\n";
    return 0;
}
