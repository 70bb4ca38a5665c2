// The parameter search (visioncore/services/param_tuning.h): from a wrong start it finds what
// the held-out frames confirm, the same seed gives the same result on any number of cores, a
// cancel keeps the start, the held-out frames are whole contiguous blocks, a seed is never
// fitted, and bad options are errors naming them.
#include "support/test_suite.h"
#include "support/sanitizer.h"
#include "support/synthetic_frames.h"
#include "visioncore/framework/controller.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/param_tuning.h"
#include "visioncore/services/stream_runner.h"

#include <QtTest>

#include <set>

using namespace fieldsight;

namespace {

struct Fixture
{
    StreamInput input;
    Annotations truth;
    std::string truth_path;
};

Fixture open(const char* name, const ParamSet& start = {})
{
    const std::string stream = test::sampleStreamsDir() + "/" + name;
    auto input = openStreamInput(stream, "");
    if (!input.ok())
        qFatal("%s", input.error().message.c_str());
    input.value().params.merge(start);
    Fixture f{std::move(input).value(), {}, defaultTruthPath(stream)};
    auto truth = Annotations::load(f.truth_path, Pipeline::standard().perceptKinds());
    if (!truth.ok())
        qFatal("%s", truth.error().message.c_str());
    f.truth = std::move(truth).value();
    return f;
}

TuneResult tune(Fixture& f, const TuneOptions& options)
{
    auto result = tuneParams(f.input, f.truth, f.truth_path, options);
    if (!result.ok())
        qFatal("%s", result.error().message.c_str());
    return std::move(result).value();
}

double valueIn(const ParamSet& set, const std::string& stage, const std::string& name,
               double fallback)
{
    const auto s = set.values.find(stage);
    if (s == set.values.end())
        return fallback;
    const auto v = s->second.find(name);
    return v == s->second.end() ? fallback : v->second;
}

ParamSet wrongGoal()
{
    ParamSet start;
    start.set("transitions", "goal_colour", double(int(Colour::Blue))); // lab2's goals are yellow
    return start;
}

} // namespace

class TestParamTuning : public QObject
{
    Q_OBJECT

private slots:
    void fromAWrongGoalColourTheHeldOutPostsAreFound()
    {
        Fixture f = open("lab2", wrongGoal());
        TuneOptions options;
        options.stages = {"transitions"};
        options.budget = 40;
        const TuneResult r = tune(f, options);
        QCOMPARE(r.fit_frames.size() + r.holdout_frames.size(), std::size_t(30));
        QCOMPARE(r.holdout_frames.size(), std::size_t(10));
        const ClassScore start = r.start_holdout.classes.at("goalpost");
        const ClassScore tuned = r.tuned_holdout.classes.at("goalpost");
        QVERIFY2(start.recall() < 0.1, qPrintable(QString::number(start.recall())));
        QVERIFY2(tuned.recall() >= 0.85, qPrintable(QString::number(tuned.recall())));
        QVERIFY(r.tuned_fit.total > r.start_fit.total);
        // Yellow is the default, but the start said blue: the file must say yellow to win.
        QCOMPARE(valueIn(r.params, "transitions", "goal_colour", -1), double(int(Colour::Yellow)));
        bool priced = false;
        for (const TuneChange& c : r.changes)
            if (c.name == "goal_colour") {
                priced = true;
                QCOMPARE(c.before, double(int(Colour::Blue)));
                QVERIFY(c.gain > 0.1);
                QVERIFY(c.term_gain.at("goalpost") > 0.5);
            }
        QVERIFY(priced);
        // Only the stage asked for moves.
        for (const TuneChange& c : r.changes)
            QCOMPARE(c.stage, std::string("transitions"));
        QVERIFY(r.evaluations <= 40);
        QVERIFY(!r.history.empty());
        QCOMPARE(r.history.back().second, r.history.back().second); // not NaN
        for (std::size_t i = 1; i < r.history.size(); ++i)
            QVERIFY(r.history[i].second > r.history[i - 1].second);
    }

    void crossValidationHoldsOutEveryFrameOnce()
    {
        Fixture f = open("lab2", wrongGoal());
        TuneOptions options;
        options.stages = {"transitions"};
        options.budget = 30;
        options.folds = 3;
        const TuneResult r = tune(f, options);
        QCOMPARE(r.folds, 3);
        QCOMPARE(r.fit_frames.size(), std::size_t(30));
        QCOMPARE(r.holdout_frames.size(), std::size_t(30));
        QCOMPARE(r.tuned_holdout.frames, std::size_t(30));
        QCOMPARE(std::set<std::string>(r.holdout_frames.begin(), r.holdout_frames.end()).size(),
                 std::size_t(30));
        // Every fold's search found the goal colour without seeing the fold.
        QVERIFY(r.start_holdout.classes.at("goalpost").recall() < 0.1);
        QVERIFY(r.tuned_holdout.classes.at("goalpost").recall() >= 0.85);
        QVERIFY(r.evaluations > 30 && r.evaluations <= 4 * 30);
        QCOMPARE(valueIn(r.params, "transitions", "goal_colour", -1), double(int(Colour::Yellow)));
        options.folds = 1;
        QVERIFY(!tuneParams(f.input, f.truth, f.truth_path, options).ok());
    }

    void theSameSeedGivesTheSameResultOnAnyNumberOfCores()
    {
        Fixture f = open("lab1");
        TuneOptions options;
        options.stages = {"ball", "field_lines"};
        options.budget = 60;
        options.seed = 7;
        options.threads = 1;
        const TuneResult one = tune(f, options);
        options.threads = 2;
        const TuneResult two = tune(f, options);
        QCOMPARE(one.params.toJson(), two.params.toJson());
        QCOMPARE(one.history, two.history);
        QCOMPARE(one.fit_frames, two.fit_frames);
        options.seed = 8;
        const TuneResult other = tune(f, options);
        QVERIFY(other.holdout_frames != one.holdout_frames || other.history != one.history);
    }

    void reusingTheFirstStagesChangesNothing()
    {
        // Every stage's parameters move, so the search resumes frames at every split. It starts
        // where balls and posts are lost, so that it surely moves.
        ParamSet start;
        start.set("ball", "min_radius", 30);
        start.set("goalposts", "min_width", 30);
        // Under the sanitizer a quarter of the budget (the search first moves a colour of the
        // first stage, at evaluation 24 of 300, then the posts at 210; the normal build sees both).
        Fixture f = open("lab1", start);
        TuneOptions options;
        options.budget = test::repeats(300);
        const TuneResult reused = tune(f, options);
        options.reuse_stages = false;
        const TuneResult fresh = tune(f, options);
        QCOMPARE(reused.history, fresh.history);
        QCOMPARE(reused.params.toJson(), fresh.params.toJson());
        QCOMPARE(reused.tuned_holdout.total, fresh.tuned_holdout.total);
        QVERIFY(reused.history.size() > (test::kUnderSanitizer ? 1u : 2u)); // the search moved
    }

    void severalStreamsAreScoredEachWithItsOwnTable()
    {
        // lab1 and lab2 have tables of their own (lab2's field lines score 87/2/63 with its own,
        // 85/3/65 with lab1's): fitted together, the counts are each stream's own, added.
        Fixture a = open("lab1");
        Fixture b = open("lab2");
        TuneOptions options;
        options.budget = 1;
        options.holdout = 0;
        const TuneResult alone_a = tune(a, options);
        const TuneResult alone_b = tune(b, options);
        auto both = tuneStreams(a.input, a.truth, a.truth_path, options,
                                {{&b.input, &b.truth, b.truth_path}});
        QVERIFY2(both.ok(), both.ok() ? "" : both.error().message.c_str());
        const TuneResult& r = both.value();
        QCOMPARE(r.fit_frames.size(), alone_a.fit_frames.size() + alone_b.fit_frames.size());
        QCOMPARE(r.fit_frames.front(), alone_a.fit_frames.front());
        QCOMPARE(r.fit_frames.back(), b.input.stream + "/" + alone_b.fit_frames.back());
        for (const auto& [name, score] : r.start_fit.classes) {
            const ClassScore& x = alone_a.start_fit.classes.at(name);
            const ClassScore& y = alone_b.start_fit.classes.at(name);
            QCOMPARE(score.tp, x.tp + y.tp);
            QCOMPARE(score.fp, x.fp + y.fp);
            QCOMPARE(score.fn, x.fn + y.fn);
        }

        // The same share of each stream held out.
        options.holdout = 1.0 / 3.0;
        auto held = tuneStreams(a.input, a.truth, a.truth_path, options,
                                {{&b.input, &b.truth, b.truth_path}});
        QVERIFY(held.ok());
        const auto& out = held.value().holdout_frames;
        const auto of_b = std::count_if(out.begin(), out.end(), [&](const std::string& name) {
            return name.rfind(b.input.stream + "/", 0) == 0;
        });
        QCOMPARE(of_b, 10);
        QCOMPARE(out.size(), std::size_t(20));

        // One set is fitted to both, so they must start alike.
        Fixture wrong = open("lab2", wrongGoal());
        auto refused = tuneStreams(a.input, a.truth, a.truth_path, options,
                                   {{&wrong.input, &wrong.truth, wrong.truth_path}});
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.find("must start alike") != std::string::npos,
                 refused.error().message.c_str());
    }

    void aValidationStreamIsScoredButNeverFitted()
    {
        // lab2 kept aside from a search on lab1: the search and its result are exactly those
        // without it (were its frames fitted, or did it move a seed, they would differ), and
        // lab2 is only scored, with the start and the result.
        Fixture a = open("lab1");
        Fixture b = open("lab2");
        TuneOptions options;
        options.stages = {"field_lines", "transitions"};
        options.budget = 40;
        const TuneResult alone = tune(a, options);
        auto with = tuneStreams(a.input, a.truth, a.truth_path, options,
                                {{&b.input, &b.truth, b.truth_path, true}});
        QVERIFY2(with.ok(), with.ok() ? "" : with.error().message.c_str());
        const TuneResult& r = with.value();
        QCOMPARE(r.fit_frames, alone.fit_frames);
        QCOMPARE(r.holdout_frames, alone.holdout_frames);
        QCOMPARE(r.params.toJson(), alone.params.toJson());
        QCOMPARE(r.tuned_fit.total, alone.tuned_fit.total);
        QCOMPARE(r.tuned_holdout.total, alone.tuned_holdout.total);
        const TuneResult only_b = tune(b, [] {
            TuneOptions o;
            o.budget = 1;
            o.holdout = 0;
            return o;
        }());
        QCOMPARE(r.validation_frames.size(), only_b.fit_frames.size());
        QCOMPARE(r.validation_frames.front(), b.input.stream + "/" + only_b.fit_frames.front());
        // Scored with the start: the counts lab2 has alone.
        for (const auto& [name, score] : only_b.start_fit.classes) {
            const ClassScore& v = r.start_validation.classes.at(name);
            QCOMPARE(v.tp, score.tp);
            QCOMPARE(v.fp, score.fp);
            QCOMPARE(v.fn, score.fn);
        }
        QVERIFY(r.tuned_validation.frames == r.start_validation.frames);
        QCOMPARE(r.start_validation.frames, only_b.start_fit.frames);

        // With folds too, the validation frames stay out of every fold.
        options.folds = 3;
        auto folded = tuneStreams(a.input, a.truth, a.truth_path, options,
                                  {{&b.input, &b.truth, b.truth_path, true}});
        QVERIFY(folded.ok());
        QCOMPARE(folded.value().holdout_frames.size(),
                 alone.fit_frames.size() + alone.holdout_frames.size());
        QCOMPARE(folded.value().validation_frames, r.validation_frames);
    }

    void aSeedIsNeverFitted()
    {
        Fixture f = open("lab1");
        TuneOptions options;
        options.stages = {"field_lines"};
        options.budget = 80;
        const TuneResult r = tune(f, options);
        for (const TuneChange& c : r.changes)
            QVERIFY2(c.name != "seed", "a RANSAC seed was fitted");
        int fitted = 0;
        for (const ParamInfo& p : Pipeline::standard().find("field_lines")->params)
            fitted += p.fitted;
        QCOMPARE(r.parameters, fitted);
        QVERIFY(fitted < int(Pipeline::standard().find("field_lines")->params.size()));
    }

    void aCancelKeepsTheStart()
    {
        Fixture f = open("lab2", wrongGoal());
        std::atomic<bool> cancel{true};
        TuneOptions options;
        options.stages = {"transitions"};
        options.cancel = &cancel;
        const TuneResult r = tune(f, options);
        QVERIFY(r.cancelled);
        QCOMPARE(r.evaluations, 1);
        QVERIFY(r.changes.empty());
        QCOMPARE(valueIn(r.params, "transitions", "goal_colour", -1), double(int(Colour::Blue)));
        QCOMPARE(r.tuned_holdout.total, r.start_holdout.total);
    }

    void theHeldOutFramesAreWholeBlocks()
    {
        const std::vector<bool> mask = tuning_holdout(30, 1.0 / 3.0, 1);
        QCOMPARE(std::count(mask.begin(), mask.end(), true), 10);
        // Two blocks of five: at most two runs of held-out frames, each a multiple of 5 long.
        int runs = 0;
        for (std::size_t i = 0; i < mask.size(); ++i)
            if (mask[i] && (i == 0 || !mask[i - 1])) {
                ++runs;
                QCOMPARE(i % 5, std::size_t(0));
            }
        QVERIFY(runs >= 1 && runs <= 2);
        QCOMPARE(tuning_holdout(30, 0, 1), std::vector<bool>(30, false));
        QCOMPARE(tuning_holdout(1, 0.5, 1), std::vector<bool>(1, false));
        bool differs = false;
        for (std::uint64_t seed = 2; seed < 6; ++seed)
            differs = differs || tuning_holdout(30, 1.0 / 3.0, seed) != mask;
        QVERIFY(differs);
        const std::vector<bool> half = tuning_holdout(12, 0.5, 3);
        QCOMPARE(std::count(half.begin(), half.end(), true), 6);
    }

    void scoresAreF1AndTheBoundaryTerm()
    {
        QCOMPARE(f1Score({}), 1.0);
        ClassScore s;
        s.tp = 3;
        s.fp = 1;
        s.fn = 2;
        QCOMPARE(f1Score(s), 6.0 / 9.0);
        Fixture f = open("lab2");
        TuneOptions options;
        options.budget = 1;
        options.holdout = 0;
        options.weights = {{"boundary", 0}, {"obstacle", 0}};
        const TuneResult r = tune(f, options);
        QVERIFY(r.holdout_frames.empty());
        QCOMPARE(r.tuned_fit.terms.count("boundary"), std::size_t(0));
        QVERIFY(r.tuned_fit.boundary_median >= 0);
        double sum = 0;
        for (const auto& [term, value] : r.tuned_fit.terms)
            sum += value;
        QVERIFY(qAbs(r.tuned_fit.total - sum / double(r.tuned_fit.terms.size())) < 1e-12);
    }

    void badOptionsAreErrorsNamingThem()
    {
        Fixture f = open("lab2");
        TuneOptions options;
        options.stages = {"no_such_stage"};
        auto r = tuneParams(f.input, f.truth, f.truth_path, options);
        QVERIFY(!r.ok());
        QVERIFY(r.error().message.find("no_such_stage") != std::string::npos);
        options.stages = {};
        options.weights = {{"balls", 1}};
        r = tuneParams(f.input, f.truth, f.truth_path, options);
        QVERIFY(!r.ok());
        QVERIFY(r.error().message.find("balls") != std::string::npos);
        options.weights = {{"ball", -1}};
        QVERIFY(!tuneParams(f.input, f.truth, f.truth_path, options).ok());
        options.weights = {};
        Annotations none;
        r = tuneParams(f.input, none, "none.json", options);
        QVERIFY(!r.ok());
        QVERIFY(r.error().message.find("none.json") != std::string::npos);
    }

private:
    static std::vector<bool> tuning_holdout(std::size_t frames, double share, std::uint64_t seed)
    {
        return holdoutFrames(frames, share, seed);
    }
};

FIELDSIGHT_TEST_SUITE(TestParamTuning, Core)

#include "test_param_tuning.moc"
