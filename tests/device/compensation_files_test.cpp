// Compensation as files: BenchPilot's own schema, the CSV and LinuxCNC exports
// (both of LinuxCNC's documented types) and the error-curve CSV a fit reads.
#include "accuracy_examples.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

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

CompensationModel tableExample()
{
    const CompensationRead r = compensationFromJson(read("stage-x-table.compensation.json"), "t");
    EXPECT_TRUE(r.compensation) << debugFormat(r.problems);
    return r.compensation ? r.compensation->model : CompensationModel{};
}

} // namespace

TEST(CompensationFiles, DerivedExamplesAreWhatTheWritersMake)
{
    accuracyexamples::checkDerivedExamples();
}

TEST(CompensationFiles, EveryCompensationExampleLoadsAndWritesBackTheSame)
{
    for (const char* name : {"stage-x-seed002.compensation.json", "stage-y-seed002.compensation.json", "stage-x-table.compensation.json",
                             "stage-x-fit.compensation.json"}) {
        const CompensationRead r = compensationFromJson(read(name), name);
        ASSERT_TRUE(r.compensation) << name << "\n" << debugFormat(r.problems);
        const std::string once = compensationToJson(*r.compensation);
        const CompensationRead again = compensationFromJson(once, "again");
        ASSERT_TRUE(again.compensation);
        EXPECT_EQ(compensationToJson(*again.compensation), once) << name;
    }
    const CompensationRead seed = compensationFromJson(read("stage-y-seed002.compensation.json"), "y");
    EXPECT_EQ(seed.compensation->model.polynomial.coefficientsUm, (std::vector<double>{1.021, 0.6397, 0.0168}));
    EXPECT_NEAR(seed.compensation->model.polynomial.errorUm(100), 232.991, 1e-9);
    const CompensationRead x = compensationFromJson(read("stage-x-seed002.compensation.json"), "x");
    EXPECT_TRUE(x.compensation->fit->chosenByOperator);
}

TEST(CompensationFiles, FitExampleCancelsTheInterferometersMeanError)
{
    // The example fitted to the stage's readings, with the backlash −B̄: applied to the
    // means it came from, it leaves the noise, the 0.5 µm pitch error the polynomial
    // cannot follow, and that is all.
    const CompensationRead r = compensationFromJson(read("stage-x-fit.compensation.json"), "f");
    ASSERT_TRUE(r.compensation);
    const CompensationModel& m = r.compensation->model;
    EXPECT_NEAR(m.backlashUm, 4, 0.3);
    const auto a = accuracyexamples::interferometerRun();
    for (const TargetStatistics& t : a.evaluation.targets)
        EXPECT_NEAR(m.polynomial.errorUm(t.targetMm), t.meanMm * 1e3, 1.0) << t.targetMm;
}

TEST(CompensationFiles, CompensationProblemsArePlaced)
{
    const std::string text = R"({
  "schema": "benchpilot.compensation",
  "version": 1,
  "axis": "X",
  "kind": "table",
  "table": {
    "per_direction": false,
    "points": [
      { "nominal_mm": 0, "correction_um": 1 },
      { "nominal_mm": 0, "correction_um": 2 }
    ]
  },
  "backlash_um": 2
})";
    const CompensationRead r = compensationFromJson(text, "c.json");
    EXPECT_FALSE(r.compensation);
    const auto p = find(r.problems, "compensation.nominals_not_increasing");
    ASSERT_TRUE(p) << debugFormat(r.problems);
    EXPECT_EQ(p->line, 10);
    EXPECT_EQ(p->path, "table.points[1].nominal_mm");
    std::string six = text;
    six.replace(six.find("\"correction_um\": 2"), 18, "\"correction_up_um\": 2");
    EXPECT_TRUE(find(compensationFromJson(six, "c").problems, "file.json_field")) << "an up column in a single-column table";
}

TEST(CompensationFiles, LinuxcncTypesCommandWhatBenchPilotWould)
{
    const CompensationModel m = tableExample();
    ASSERT_EQ(m.table.size(), 11u);
    for (auto type : {LinuxcncCompType::ActualPositions, LinuxcncCompType::Corrections}) {
        const std::string text = linuxcncCompensation(m, type);
        const LinuxcncRead back = linuxcncFromText(text, "x.comp", type);
        ASSERT_TRUE(back.model) << debugFormat(back.problems);
        for (std::size_t i = 0; i < m.table.size(); ++i) {
            EXPECT_NEAR(back.model->table[i].correctionUpUm, m.table[i].correctionUpUm, 0.0006) << "to LinuxCNC's nanometre";
            EXPECT_NEAR(back.model->table[i].correctionDownUm, m.table[i].correctionDownUm, 0.0006);
        }
    }
    // LinuxCNC's own reading (usrmotLoadComp): type 0 trim = nominal − actual, type 1 trim
    // as written; the motion controller adds the trim to the command.
    const std::string t0 = read("stage-x-table.linuxcnc-type0.comp"), t1 = read("stage-x-table.linuxcnc-type1.comp");
    double nom0, fwd0, rev0, nom1, fwd1, rev1;
    ASSERT_EQ(std::sscanf(t0.c_str(), "%lf %lf %lf", &nom0, &fwd0, &rev0), 3);
    ASSERT_EQ(std::sscanf(t1.c_str(), "%lf %lf %lf", &nom1, &fwd1, &rev1), 3);
    EXPECT_EQ(nom0, nom1);
    EXPECT_NEAR(nom0 - fwd0, fwd1, 1.5e-6);
    EXPECT_NEAR(nom0 - rev0, rev1, 1.5e-6);
    EXPECT_NEAR(fwd1 * 1e3, m.table[0].correctionUpUm, 0.0006);
    EXPECT_EQ(t0.find('#'), std::string::npos) << "no comment or header: LinuxCNC would stop reading there";
}

TEST(CompensationFiles, LinuxcncReaderIsStricterThanLinuxcnc)
{
    // A header line: LinuxCNC would read no table at all and say nothing.
    const LinuxcncRead header = linuxcncFromText("nominal forward reverse trims\n0 0.001 -0.001\n10 0.002 0\n", "h.comp", LinuxcncCompType::Corrections);
    const auto p = find(header.problems, "compensation.linuxcnc.not_a_triplet");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->line, 1);
    const LinuxcncRead order = linuxcncFromText("0 0 0\n\n10 0 0\n5 0 0\n", "o.comp", LinuxcncCompType::Corrections);
    const auto o = find(order.problems, "compensation.nominals_not_increasing");
    ASSERT_TRUE(o);
    EXPECT_EQ(o->line, 4);
    std::string many;
    for (int i = 0; i <= 256; ++i)
        many += std::to_string(i) + " 0 0\n";
    EXPECT_TRUE(find(linuxcncFromText(many, "m.comp", LinuxcncCompType::Corrections).problems, "compensation.too_many_table_points"));
    EXPECT_TRUE(find(linuxcncFromText("0 x 0\n1 0 0\n", "n.comp", LinuxcncCompType::Corrections).problems, "accuracy.csv.not_a_number"));
}

TEST(CompensationFiles, PolynomialIsSampledForExportsAndSingleColumnsCarryTheBacklash)
{
    const CompensationModel poly = polynomialModel("Y", motion::ErrorPolynomial{{1.021, 0.6397, 0.0168}}, 0, 100, 4);
    EXPECT_EQ(defaultNominals(poly).size(), 41u);
    EXPECT_EQ(defaultNominals(poly)[1], 2.5);
    const std::string csv = compensationCsv(poly, {0, 100});
    EXPECT_EQ(csv.substr(0, csv.find('\r')), "nominal_mm,correction_up_um,correction_down_um");
    const LinuxcncRead back = linuxcncFromText(linuxcncCompensation(poly, LinuxcncCompType::Corrections, {0, 50, 100}), "p", LinuxcncCompType::Corrections);
    ASSERT_TRUE(back.model);
    EXPECT_NEAR(back.model->table[2].correctionUpUm, poly.correctionUm(100, Direction::Up), 0.0006);
    EXPECT_NEAR(back.model->table[1].correctionUpUm - back.model->table[1].correctionDownUm, 4 / (1 + 2.3197e-3), 0.002);

    CompensationModel single;
    single.kind = CompensationModel::Kind::Table;
    single.table = {{0, 1, 1}, {10, 3, 3}};
    single.backlashUm = 2;
    const LinuxcncRead s = linuxcncFromText(linuxcncCompensation(single, LinuxcncCompType::Corrections), "s", LinuxcncCompType::Corrections);
    ASSERT_TRUE(s.model);
    EXPECT_NEAR(s.model->table[0].correctionUpUm, 2, 1e-9);
    EXPECT_NEAR(s.model->table[0].correctionDownUm, 0, 1e-9);
}

TEST(CompensationFiles, ErrorCurveCsvFeedsTheFit)
{
    const ErrorCurveRead r = errorCurveFromCsv(read("stage-x-interferometer.error-curve.csv"), "curve.csv");
    ASSERT_TRUE(r.ok()) << debugFormat(r.problems);
    const auto a = accuracyexamples::interferometerRun();
    const auto expected = fitPointsOf(a.evaluation);
    ASSERT_EQ(r.points.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(r.points[i].positionMm, expected[i].positionMm);
        EXPECT_NEAR(r.points[i].errorUm, expected[i].errorUm, 1e-9);
    }
    const ErrorCurveRead um = errorCurveFromCsv("position_um,error_nm,comment\n1000,1500,a\n2000,2500,b\n3000,2000,c\n", "u.csv");
    ASSERT_TRUE(um.ok());
    EXPECT_NEAR(um.points[1].positionMm, 2, 1e-12);
    EXPECT_NEAR(um.points[1].errorUm, 2.5, 1e-12);
    EXPECT_TRUE(find(errorCurveFromCsv("position_mm,error_parsec\n1,2\n", "p.csv").problems, "accuracy.csv.unknown_unit"));
    EXPECT_TRUE(find(errorCurveFromCsv("position_mm\n1\n", "p.csv").problems, "accuracy.csv.missing_column"));
}

TEST(CompensationFiles, SavedFilesReadBack)
{
    QTemporaryDir dir;
    motion::msg::Message error;
    const CompensationModel m = tableExample();
    const QString json = dir.filePath(QStringLiteral("x.compensation.json")), comp = dir.filePath(QStringLiteral("x.comp"));
    ASSERT_TRUE(saveCompensationFile(json, {m, std::nullopt, ""}, &error)) << motion::msg::debugString(error);
    ASSERT_TRUE(saveLinuxcncCompensation(comp, m, LinuxcncCompType::ActualPositions, &error));
    ASSERT_TRUE(saveCompensationCsv(dir.filePath(QStringLiteral("x.csv")), m, &error));
    const CompensationRead r = loadCompensationFile(json);
    ASSERT_TRUE(r.compensation) << debugFormat(r.problems);
    EXPECT_EQ(r.compensation->model.table.size(), 11u);
    EXPECT_FALSE(saveCompensationFile(dir.filePath(QStringLiteral("no/such/dir.json")), {m, std::nullopt, ""}, &error));
    EXPECT_EQ(error.id, "file.cannot_write");
    EXPECT_NE(error.text("file").find("no/such/dir.json"), std::string::npos);
}
