// The accuracy bench's files: test definitions, readings CSV and result JSON.
// Real examples load; what is written reads back the same; a bad file is refused
// with the file, line, column and field of every problem, and a message id.
#include "accuracy_examples.h"
#include "device/files/accuracy/accuracy_test_file.h"
#include "device/files/accuracy/csv_table.h"
#include "device/files/accuracy/interferometer_csv.h"
#include "motion/metrology/linear/run_sequence.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

using namespace dev::files::accuracy;
using namespace motion::metrology;
using accuracyexamples::read;

namespace {

std::optional<motion::msg::Problem> find(const motion::msg::Problems& ps, const std::string& id)
{
    for (const motion::msg::Problem& p : ps)
        if (p.message.id == id)
            return p;
    return std::nullopt;
}

} // namespace

TEST(AccuracyFiles, EveryTestDefinitionExampleLoadsAndWritesBackTheSame)
{
    const QStringList names = QDir(QStringLiteral(BP_SOURCE_DIR "/resources/examples")).entryList({QStringLiteral("*.accuracy-test.json")});
    ASSERT_GE(names.size(), 4) << "an axis, a seed 000 axis, an XY line and a circle";
    for (const QString& name : names) {
        const std::string text = read(name.toStdString());
        const AccuracyTestRead r = accuracyTestFromJson(text, name.toStdString());
        ASSERT_TRUE(r.test) << debugFormat(r.problems);
        const std::string once = accuracyTestToJson(*r.test);
        const AccuracyTestRead again = accuracyTestFromJson(once, "again");
        ASSERT_TRUE(again.test) << debugFormat(again.problems);
        EXPECT_EQ(accuracyTestToJson(*again.test), once) << name.toStdString();
    }
    const AccuracyTestRead seed = accuracyTestFromJson(read("analyzer-x-seed000.accuracy-test.json"), "seed");
    const auto& axis = std::get<AxisTest>(*seed.test);
    EXPECT_FALSE(axis.bidirectional);
    EXPECT_EQ(targetsOf(axis), (std::vector<double>{30, 60, 90, 120, 150}));
    EXPECT_EQ(*axis.tolerances.aMm, 0.4);
    const auto stage = std::get<AxisTest>(*accuracyTestFromJson(read("stage-x-iso230-2.accuracy-test.json"), "s").test);
    EXPECT_EQ(targetsOf(stage)[1], 10.59) << "the irregular grid: 10 + (frac(φ) − ½)·10/2";
    EXPECT_EQ(readingCount(stage), 110u);
    const auto xy = std::get<XyLineTest>(*accuracyTestFromJson(read("analyzer-xy-seed000.accuracy-test.json"), "xy").test);
    EXPECT_EQ(pointsOf(xy)[4].yMm, 200);
    const auto circle = std::get<CircularTest>(*accuracyTestFromJson(read("stage-circle-r20.accuracy-test.json"), "c").test);
    EXPECT_TRUE(circle.clockwise && circle.counterClockwise);
    EXPECT_EQ(*circle.maxHMm, 0.005);
}

TEST(AccuracyFiles, TestDefinitionProblemsNameLineColumnAndField)
{
    const std::string text = R"({
  "schema": "benchpilot.accuracy-test",
  "version": 1,
  "kind": "axis",
  "axis": "X",
  "targets_mm": [10, 20, 15],
  "cycles": 1,
  "feed_mm_s": 0
})";
    const AccuracyTestRead r = accuracyTestFromJson(text, "x.accuracy-test.json");
    EXPECT_FALSE(r.test);
    const auto cycles = find(r.problems, "accuracy.too_few_cycles");
    ASSERT_TRUE(cycles) << debugFormat(r.problems);
    EXPECT_EQ(cycles->file, "x.accuracy-test.json");
    EXPECT_EQ(cycles->line, 7);
    EXPECT_EQ(cycles->column, 13);
    EXPECT_EQ(cycles->path, "cycles");
    const auto order = find(r.problems, "accuracy.targets_not_increasing");
    ASSERT_TRUE(order);
    EXPECT_EQ(order->line, 6);
    EXPECT_EQ(order->column, 26) << "at the 15, not at the list";
    EXPECT_TRUE(find(r.problems, "accuracy.value_not_positive"));

    // Warnings (fewer than ISO's 5 cycles) do not refuse the file.
    std::string three = text;
    three.replace(three.find("[10, 20, 15]"), 12, "[10, 20, 30, 40, 50]");
    three.replace(three.find("\"cycles\": 1"), 11, "\"cycles\": 3");
    three.replace(three.find("\"feed_mm_s\": 0"), 14, "\"feed_mm_s\": 2");
    const AccuracyTestRead w = accuracyTestFromJson(three, "w");
    ASSERT_TRUE(w.test) << debugFormat(w.problems);
    ASSERT_EQ(w.problems.size(), 1u);
    EXPECT_TRUE(w.problems[0].isWarning());
    EXPECT_EQ(w.problems[0].message.id, "accuracy.fewer_cycles_than_iso");

    const AccuracyTestRead bad = accuracyTestFromJson("{\"schema\": \"benchpilot.accuracy-test\", \"version\": 1,\n \"kind\": \"spiral\"}", "k");
    ASSERT_EQ(bad.problems.size(), 1u);
    EXPECT_EQ(bad.problems[0].message.id, "file.json_field");
    EXPECT_EQ(bad.problems[0].line, 2);
    const AccuracyTestRead syntax = accuracyTestFromJson("{\n  \"schema\": ,", "s");
    ASSERT_EQ(syntax.problems.size(), 1u);
    EXPECT_EQ(syntax.problems[0].message.id, "file.json_syntax");
    EXPECT_EQ(syntax.problems[0].line, 2);
}

TEST(AccuracyFiles, SeedReadingsExampleGivesTheSeedsRepeatability)
{
    const auto a = analyzeReadingsCsv(read("analyzer-x-seed000.readings.csv"), "analyzer-x-seed000.readings.csv");
    ASSERT_TRUE(a.ok()) << debugFormat(a.problems);
    EXPECT_FALSE(a.evaluation.bidirectional);
    EXPECT_EQ(a.read.readings.size(), 25u);
    EXPECT_NEAR(a.evaluation.figures.rUpMm, 0.15073, 0.00001) << "Table 3's 0.151; the note column is ignored";
}

TEST(AccuracyFiles, InterferometerExampleShowsTheStagesErrorAndBacklash)
{
    const auto a = accuracyexamples::interferometerRun();
    ASSERT_TRUE(a.ok()) << debugFormat(a.problems);
    EXPECT_TRUE(a.evaluation.bidirectional);
    EXPECT_EQ(a.evaluation.targets.size(), 11u);
    EXPECT_EQ(a.evaluation.cycles, 5);
    // Seed 002's X curve rises 89 µm over the travel; 4 µm of backlash; 0.3 µm noise.
    EXPECT_NEAR(*a.evaluation.figures.bMeanMm, -0.004, 0.0003);
    EXPECT_NEAR(*a.evaluation.figures.eMm, 0.093, 0.002);
    // 4s of 0.3 µm noise is 1.2 µm; the largest of 11 targets' is about 2 µm.
    EXPECT_LT(a.evaluation.figures.rUpMm, 0.003);
}

TEST(AccuracyFiles, ReadingsInOtherUnitsOrderAndWithQuotesReadTheSame)
{
    const std::string text = "\xEF\xBB\xBF" "cycle,Measured_um,\"note, free\",direction,target_mm\r\n"
                             "1,10001.5,\"a \"\"quoted\"\" note\",up,10\r\n"
                             "\r\n"
                             "1,  20003 ,,UP,20\r\n"
                             "2,10002.5,,up,10\n"
                             "2,20002,,up,+20\n";
    const ReadingsRead r = readingsFromCsv(text, "r.csv");
    ASSERT_TRUE(r.ok()) << debugFormat(r.problems);
    ASSERT_EQ(r.readings.size(), 4u);
    EXPECT_NEAR(r.readings[0].measuredMm, 10.0015, 1e-12);
    EXPECT_EQ(r.readings[1].direction, Direction::Up);
    EXPECT_EQ(r.lines, (std::vector<int>{2, 4, 5, 6}));
    EXPECT_EQ(r.readings[3].targetMm, 20);
    // And back: the writer's file reads to the same readings.
    const ReadingsRead again = readingsFromCsv(readingsToCsv(r.readings), "again.csv");
    ASSERT_TRUE(again.ok());
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_EQ(again.readings[i].measuredMm, r.readings[i].measuredMm);
}

TEST(AccuracyFiles, ReadingsProblemsNameLineAndColumn)
{
    motion::msg::Problems ps = readingsFromCsv("target_mm,direction,cycle,measured_furlong\n10,up,1,10\n", "u.csv").problems;
    auto unit = find(ps, "accuracy.csv.unknown_unit");
    ASSERT_TRUE(unit);
    EXPECT_EQ(unit->line, 1);
    EXPECT_EQ(unit->column, 27);
    EXPECT_EQ(unit->message.text("column"), "measured_furlong");

    ps = readingsFromCsv("target_mm,direction,measured_mm\n10,up,10\n", "m.csv").problems;
    ASSERT_TRUE(find(ps, "accuracy.csv.missing_column"));
    EXPECT_EQ(find(ps, "accuracy.csv.missing_column")->message.text("column"), "cycle");

    ps = readingsFromCsv("target_mm,direction,cycle,measured_mm\n"
                         "10,up,1,10.001\n"
                         "10,up,1\n"
                         "20,sideways,1.5,NaN\n"
                         "abc,down,2,20\n",
                         "bad.csv")
             .problems;
    const auto cells = find(ps, "accuracy.csv.wrong_cell_count");
    ASSERT_TRUE(cells);
    EXPECT_EQ(cells->line, 3);
    EXPECT_EQ(cells->message.integer("count"), 3);
    const auto nan = find(ps, "accuracy.value_not_finite");
    ASSERT_TRUE(nan);
    EXPECT_EQ(nan->line, 4);
    EXPECT_EQ(nan->column, 17);
    EXPECT_EQ(nan->path, "measured_mm");
    EXPECT_EQ(find(ps, "accuracy.csv.unknown_direction")->column, 4);
    EXPECT_EQ(find(ps, "accuracy.csv.not_a_cycle")->message.text("text"), "1.5");
    EXPECT_EQ(find(ps, "accuracy.csv.not_a_number")->line, 5);
    EXPECT_EQ(ps.size(), 5u) << debugFormat(ps);

    EXPECT_TRUE(find(readingsFromCsv("target_mm;direction;cycle;measured_mm\n10;up;1;10,001\n", "s.csv").problems, "file.csv.semicolons"));
    EXPECT_TRUE(find(readingsFromCsv("", "e.csv").problems, "accuracy.csv.no_readings"));
    EXPECT_TRUE(find(readingsFromCsv("target_mm,direction,cycle,measured_mm\n10,up,1,\"10\n", "q.csv").problems, "file.csv.unterminated_quote"));
}

TEST(AccuracyFiles, EvaluationProblemsArePlacedOnTheReadingsLine)
{
    // Two readings per target (enough cycles), but 20 mm's second reading repeats cycle 1.
    const auto a = analyzeReadingsCsv("target_mm,direction,cycle,measured_mm\n"
                                      "10,up,1,10.001\n"
                                      "10,up,2,10.002\n"
                                      "20,up,1,20.001\n"
                                      "20,up,1,20.003\n",
                                      "d.csv");
    EXPECT_FALSE(a.ok());
    const auto dup = find(a.problems, "accuracy.duplicate_reading");
    ASSERT_TRUE(dup);
    EXPECT_EQ(dup->line, 5);
    EXPECT_EQ(dup->file, "d.csv");
    const auto one = analyzeReadingsCsv("target_mm,direction,cycle,measured_mm\n10,up,1,10.001\n20,up,1,20.001\n", "o.csv");
    const auto cycles = find(one.problems, "accuracy.too_few_cycles");
    ASSERT_TRUE(cycles);
    EXPECT_EQ(cycles->line, 2);
}

TEST(AccuracyFiles, ResultExampleIsWhatTheWriterMakesAndReadsBack)
{
    accuracyexamples::checkDerivedExamples();
    const std::string text = read("stage-x-interferometer.accuracy-result.json");
    const AccuracyResultRead r = accuracyResultFromJson(text, "result.json");
    ASSERT_TRUE(r.result) << debugFormat(r.problems);
    EXPECT_EQ(accuracyResultToJson(*r.result), text);
    const auto a = accuracyexamples::interferometerRun();
    EXPECT_EQ(*r.result->evaluation.figures.aMm, *a.evaluation.figures.aMm);
    // The keys scripts rely on, in mm under "figures".
    const dev::files::json::Value doc = *dev::files::json::parse(text).value;
    for (const char* key : {"A", "A_up", "A_down", "E", "E_up", "E_down", "M", "R", "R_up", "R_down", "B", "B_mean"})
        EXPECT_TRUE(doc.find("figures")->find(key)->isNumber()) << key;
    EXPECT_EQ(doc.find("targets")->items().size(), 11u);
    EXPECT_EQ(doc.find("pass")->asBool(), true) << "R within its 10 µm";
}

TEST(AccuracyFiles, ResultWithAFigureThatDisagreesWithItsTableIsRefused)
{
    std::string text = read("stage-x-interferometer.accuracy-result.json");
    const auto at = text.find("\"A\": ");
    ASSERT_NE(at, std::string::npos);
    text.replace(at + 5, 1, "9");  // the first digit of A
    const AccuracyResultRead r = accuracyResultFromJson(text, "r.json");
    EXPECT_FALSE(r.result);
    const auto p = find(r.problems, "accuracy.result.figure_disagrees");
    ASSERT_TRUE(p) << debugFormat(r.problems);
    EXPECT_EQ(p->message.text("figure"), "A");
    EXPECT_EQ(p->path, "figures.A");
    EXPECT_GT(p->line, 5);
}

TEST(AccuracyFiles, UnidirectionalResultWritesNullForWhatItDoesNotHave)
{
    const auto a = analyzeReadingsCsv(read("analyzer-x-seed000.readings.csv"), "seed.csv");
    AccuracyResult res;
    res.evaluation = a.evaluation;
    res.tolerances = analyzerTolerances('X');
    const std::string text = accuracyResultToJson(res);
    const dev::files::json::Value doc = *dev::files::json::parse(text).value;
    EXPECT_TRUE(doc.find("figures")->find("A")->isNull());
    EXPECT_TRUE(doc.find("figures")->find("B_mean")->isNull());
    EXPECT_TRUE(doc.find("figures")->find("R_up")->isNumber());
    EXPECT_EQ(doc.find("verdicts")->items()[0].find("figure")->asString(), "A_up");
    const AccuracyResultRead back = accuracyResultFromJson(text, "u.json");
    ASSERT_TRUE(back.result) << debugFormat(back.problems);
    EXPECT_EQ(accuracyResultToJson(*back.result), text);
}

TEST(AccuracyFiles, WritersLeaveNothingHalfWritten)
{
    QTemporaryDir dir;
    const QString good = dir.filePath(QStringLiteral("r.csv"));
    motion::msg::Message error;
    const auto a = analyzeReadingsCsv(read("analyzer-x-seed000.readings.csv"), "seed.csv");
    ASSERT_TRUE(saveReadingsCsv(good, a.read.readings, &error)) << motion::msg::debugString(error);
    const ReadingsRead back = loadReadingsCsv(good);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back.readings.size(), 25u);
    EXPECT_EQ(back.problems.size(), 0u);
    // A directory that is not there: refused, and nothing appears.
    const QString nowhere = dir.filePath(QStringLiteral("missing/r.csv"));
    EXPECT_FALSE(saveReadingsCsv(nowhere, a.read.readings, &error));
    EXPECT_EQ(error.id, "file.cannot_write");
    EXPECT_EQ(error.text("file"), nowhere.toStdString());
    EXPECT_FALSE(QFile::exists(nowhere));
    const ReadingsRead none = loadReadingsCsv(nowhere);
    ASSERT_EQ(none.problems.size(), 1u);
    EXPECT_EQ(none.problems[0].message.id, "file.cannot_open");
    EXPECT_EQ(none.problems[0].message.text("file"), nowhere.toStdString());
    EXPECT_EQ(none.problems[0].file, "r.csv");
}

TEST(AccuracyFiles, ATargetSequenceWithABadTimeIsRefusedAtItsCell)
{
    // A time that is not a number used to be dropped without a word, so a sequence the
    // operator edited by hand read back without its times.
    const std::string head = "index,target_mm,direction,cycle,time_s\r\n";
    const auto words = targetSequenceFromCsv(head + "1,10,up,1,1.5\r\n2,20,up,1,soon\r\n", "seq.csv");
    EXPECT_FALSE(words.ok());
    const auto p = find(words.problems, "accuracy.csv.not_a_number");
    ASSERT_TRUE(p) << debugFormat(words.problems);
    EXPECT_EQ(p->line, 3);
    EXPECT_EQ(p->column, 11);
    EXPECT_EQ(p->path, "time_s");
    // Seconds since the run began: negative or beyond 1e9 s is a typo, refused likewise.
    const auto huge = targetSequenceFromCsv(head + "1,10,up,1,-2\r\n", "seq.csv");
    EXPECT_FALSE(huge.ok());
    ASSERT_EQ(huge.problems.size(), 1u) << debugFormat(huge.problems);
    EXPECT_EQ(huge.problems[0].path, "time_s");
    EXPECT_EQ(targetSequenceFromCsv(head + "1,10,up,1,2.5\r\n", "seq.csv").stops.at(0).timeS, 2.5);
}
