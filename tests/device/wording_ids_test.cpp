// Every message id and term id that motion/, imaging/, device/ and the screens can hand to
// a person is worded: none reaches a person as motion::msg::debugString. The ids are read
// from the sources themselves (string literals with an area's prefix), so an id
// added without its words fails here, in whatever file it was added.
#include "widgets/wording/wording.h"

#include "motion/plans/pattern.h"
#include "motion/plans/recipes/recipe_plan.h"
#include "motion/plans/scan/scan_plan.h"

#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QSet>

#include <gtest/gtest.h>

namespace {

/// Literals that look like ids but are field paths or prefixes an id is built from.
const QSet<QString> kNotIds = {
    QStringLiteral("compensation.x_error_poly_um"), QStringLiteral("compensation.y_error_poly_um"),
    QStringLiteral("capability.no_"),               QStringLiteral("capability.because."),
    QStringLiteral("tuning.rule."),                 QStringLiteral("recipe.step."),
    QStringLiteral("pattern.value_above"),  // an example in message.h's comment
    QStringLiteral("direction.circle"),     // a field path of the accuracy files
    QStringLiteral("scan.csv"),             // a file name
    // The scan plan's camera fields (paths in a plan file, not message ids).
    QStringLiteral("camera.field_mm"), QStringLiteral("camera.magnification"), QStringLiteral("camera.overlap"),
    QStringLiteral("camera.pixel_um"), QStringLiteral("camera.rotation_deg"), QStringLiteral("camera.sensor_pixel_um"),
    QStringLiteral("camera.sensor_px"), QStringLiteral("camera.profile"),
    QStringLiteral("link.state."),          // the prefix linkStateKey() strips
    // API method names the CLI's command table spells out (app/cli, docs/api.md).
    QStringLiteral("device.move"), QStringLiteral("recipe.run"), QStringLiteral("tuning.gains"),
    QStringLiteral("tuning.step_test"), QStringLiteral("tuning.tune"),
};

QStringList idLiterals()
{
    static const QRegularExpression id(QStringLiteral(
        "(?<!api\\()\"((?:pattern|plate|recipe|scan|profile|tuning|file|request|link|device|telemetry|path|json|segment|grbl|accuracy|"
        "compensation|direction|rotation|capability|instrument|log|gauge|imaging|camera)\\.[a-z0-9_.\\-]+)\""));
    QSet<QString> found;
    for (const char* dir : {"motion", "imaging", "device", "widgets", "app"}) {
        QDirIterator it(QStringLiteral(BP_SOURCE_DIR "/%1").arg(QLatin1String(dir)), {QStringLiteral("*.cpp"), QStringLiteral("*.h")},
                        QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            // The simulator is firmware (its words go on the wire); the wording tables hold
            // the ids themselves; the scripting API's literals are method names
            // ("device.home"), as are the CLI's api("…") specs (the lookbehind above).
            if (path.contains(QLatin1String("/device/sim/")) || path.contains(QLatin1String("/widgets/wording/"))
                || path.contains(QLatin1String("/app/api/")))
                continue;
            QFile f(path);
            if (!f.open(QIODevice::ReadOnly))
                continue;
            const QString text = QString::fromUtf8(f.readAll());
            for (auto m = id.globalMatch(text); m.hasNext();)
                found.insert(m.next().captured(1));
        }
    }
    QStringList out(found.begin(), found.end());
    out.sort();
    return out;
}

TEST(WordingIds, EveryIdInTheSourcesIsWorded)
{
    const QStringList ids = idLiterals();
    ASSERT_GT(ids.size(), 400) << "the scan found too few ids to be reading the sources";
    QStringList unworded;
    for (const QString& id : ids) {
        if (kNotIds.contains(id))
            continue;
        const std::string s = id.toStdString();
        const motion::msg::Message m = motion::msg::make(s);
        const bool sentence = ui::words::text(m) != QString::fromStdString(motion::msg::debugString(m));
        const bool term = ui::words::term(s) != id;
        if (!sentence && !term)
            unworded << id;
    }
    EXPECT_TRUE(unworded.isEmpty()) << "ids without words: " << unworded.join(QStringLiteral(", ")).toStdString();
}

TEST(WordingIds, APatternsProblemsAreSentencesWithTheirNumbers)
{
    motion::plans::Pattern p;
    p.shape = motion::plans::PatternShape::Spiral;
    p.feedMmS = 0;
    p.spiral.pitchMm = -1;
    p.spiral.turns = 2.3;
    QStringList lines;
    for (const auto& q : motion::plans::validate(p))
        lines << QString::fromStdString(q.path) + QStringLiteral(": ") + ui::words::englishText(q.message);
    const QStringList expected{QStringLiteral("feed_mm_s: must be from 0.001 mm/s to 1000.00 mm/s (got 0.00 mm/s)"),
                                  QStringLiteral("pitch_mm: must be above 0.000 mm (got -1.000 mm)"),
                                  QStringLiteral("turns: must be a whole or half number of turns (got 2.3)")};
    EXPECT_EQ(lines.join(QLatin1Char('\n')).toStdString(), expected.join(QLatin1Char('\n')).toStdString());
}

TEST(WordingIds, EveryProblemOfABadRecipeAndScanPlanIsWorded)
{
    // The validators' own output, not just their ids: arguments fill every placeholder.
    motion::plates::Recipe r;
    r.plates = {{"samples", "nowhere", "no-such-labware", -1, 5}};
    motion::plates::Step s;
    s.type = motion::plates::StepType::Dispense;
    s.volumeUl = -3;
    r.steps = {s};
    motion::plates::PlanContext c;
    const auto plan = motion::plates::planRecipe(r, c);
    ASSERT_FALSE(plan.problems.empty());
    for (const auto& problem : plan.problems) {
        const QString t = ui::words::englishText(problem.message);
        EXPECT_FALSE(t.contains(QLatin1Char('{')) || t.contains(QRegularExpression(QStringLiteral("%[0-9]")))) << t.toStdString();
        EXPECT_NE(t, QString::fromStdString(motion::msg::debugString(problem.message)));
    }
    motion::scan::ScanPlan bad;
    bad.overlapX = 2;
    bad.speedMmS = -1;
    bad.naming.filePattern = "{x}";
    for (const auto& problem : motion::scan::validate(bad)) {
        const QString t = ui::words::englishText(problem.message);
        EXPECT_NE(t, QString::fromStdString(motion::msg::debugString(problem.message))) << problem.path;
    }
}

} // namespace
