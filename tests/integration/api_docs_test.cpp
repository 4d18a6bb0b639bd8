// docs/api.md's method list is generated from the command table: every method with
// its parameters and an example request and response. This test runs every example on
// the simulators (their clocks sped up where no jog is timed on the host) and checks
// the page: the same methods, parameters and requests, and responses of the same shape
// (values such as measured positions differ from run to run).
//
// After changing a command:  BP_UPDATE_DOCS=1 build/tests/test_integration --gtest_filter='ApiDocs.*'
#include "api_support.h"
#include "cli_in_process.h"

#include "app/api/command_methods.h"
#include "app/api/openrpc.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>

using itest::ApiFixture;
using itest::ApiTestClient;

namespace {

const QString kBegin = QStringLiteral("<!-- methods:begin -->");
const QString kEnd = QStringLiteral("<!-- methods:end -->");

QString docPath() { return QStringLiteral(BP_SOURCE_DIR "/docs/api.md"); }

/// Arrays cut to three elements, at every depth: a page, not a data dump.
QJsonValue shortened(const QJsonValue& v)
{
    if (v.isArray()) {
        QJsonArray out;
        const QJsonArray a = v.toArray();
        for (int i = 0; i < a.size() && i < 3; ++i)
            out.append(shortened(a[i]));
        return out;
    }
    if (v.isObject()) {
        QJsonObject out;
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it)
            out.insert(it.key(), shortened(it.value()));
        return out;
    }
    return v;
}

/// The shape of a value: its keys and the JSON types of its leaves, arrays by their first element.
QString shape(const QJsonValue& v)
{
    switch (v.type()) {
    case QJsonValue::Object: {
        QStringList parts;
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it)
            parts << it.key() + QLatin1Char(':') + shape(it.value());
        return QLatin1Char('{') + parts.join(QLatin1Char(',')) + QLatin1Char('}');
    }
    case QJsonValue::Array: return QLatin1Char('[') + (v.toArray().isEmpty() ? QString() : shape(v.toArray().first())) + QLatin1Char(']');
    case QJsonValue::Double: return QStringLiteral("n");
    case QJsonValue::String: return QStringLiteral("s");
    case QJsonValue::Bool: return QStringLiteral("b");
    default: return QStringLiteral("null");
    }
}

QString typeText(app::cli::ParamType t)
{
    using T = app::cli::ParamType;
    switch (t) {
    case T::Text: return QStringLiteral("string");
    case T::Number: return QStringLiteral("number");
    case T::Integer: return QStringLiteral("integer");
    case T::Boolean: return QStringLiteral("boolean");
    case T::Numbers: return QStringLiteral("numbers");
    case T::Axis: return QStringLiteral("axis letter");
    case T::Axes: return QStringLiteral("axis letters");
    case T::AxisValues: return QStringLiteral("axis → number(s)");
    case T::AxisRanges: return QStringLiteral("axis → [min, max]");
    case T::File: return QStringLiteral("path");
    }
    return QStringLiteral("string");
}

QString cell(QString text) { return text.replace(QLatin1Char('|'), QStringLiteral("\\|")).replace(QLatin1Char('\n'), QLatin1Char(' ')); }

struct Section {
    QString method;
    QString head;      ///< everything but the response line
    QString response;  ///< the response line's JSON
};

/// The generated section, one block per method, running each example.
QVector<Section> generate()
{
    ApiFixture f(true, 0);
    QTemporaryDir work;
    QFile::link(QStringLiteral(BP_SOURCE_DIR "/resources"), work.filePath(QStringLiteral("resources")));
    // scan.run's example runs the plan scan.plan's example makes.
    const itest::CliResult plan = itest::runCliInProcess(itest::splitWords("scan plan --roi 40,40,42.5,41 --fov 1.33,1.33 --overlap 0.1"));
    QFile planFile(work.filePath(QStringLiteral("slide.scan.json")));
    EXPECT_TRUE(planFile.open(QIODevice::WriteOnly));
    planFile.write(plan.out.toUtf8());
    planFile.close();

    ApiTestClient c(f.path);
    c.call(QStringLiteral("client.hello"), QJsonObject{{QStringLiteral("name"), QStringLiteral("docs")}, {QStringLiteral("cwd"), work.path()}});
    QString lease = ApiTestClient::result(c.call(QStringLiteral("control.acquire"))).value(QStringLiteral("lease")).toString();
    QTimer beat;
    QObject::connect(&beat, &QTimer::timeout, [&] { c.send(QStringLiteral("control.heartbeat"), QJsonObject{{QStringLiteral("lease"), lease}}); });
    beat.start(100);

    QVector<Section> out;
    for (const app::api::CommandMethod& m : app::api::commandMethods()) {
        const app::cli::ApiSpec& spec = m.command->api;
        Section s;
        s.method = m.method;
        QString h = QStringLiteral("### `%1`\n\n%2 — `benchpilot-cli %3` · %4\n\n")
                        .arg(m.method, m.command->summary, m.path, app::api::accessName(spec.access, spec.readsWithoutArguments));
        if (!m.command->description.isEmpty())
            h += app::api::apiWording(m, m.command->description) + QStringLiteral("\n\n");
        h += QStringLiteral("| param | type | | description |\n|---|---|---|---|\n");
        for (const app::api::MethodParam& p : app::api::methodParams(m)) {
            QString type = typeText(p.type);
            if (!p.choices.isEmpty())
                type = p.choices.join(QStringLiteral(" \\| "));
            QString note = p.required ? QStringLiteral("required") : QString();
            if (!p.defaultValue.isEmpty())
                note = QStringLiteral("default %1").arg(p.defaultValue);
            h += QStringLiteral("| `%1` | %2 | %3 | %4 |\n").arg(p.name, type, note, cell(app::api::apiWording(m, p.description)));
        }
        QJsonObject params = spec.example;
        if (spec.access == app::cli::Access::Control)
            params.insert(QStringLiteral("lease"), QStringLiteral("…"));
        h += QStringLiteral("\n```\n→ %1\n")
                 .arg(QString::fromUtf8(QJsonDocument(QJsonObject{{QStringLiteral("jsonrpc"), QStringLiteral("2.0")}, {QStringLiteral("id"), 1},
                                                                  {QStringLiteral("method"), m.method}, {QStringLiteral("params"), params}})
                                             .toJson(QJsonDocument::Compact)));
        s.head = h;
        f.stage.link.host().setTimeScale(20);
        f.analyzer->link.host().setTimeScale(20);
        if (spec.access == app::cli::Access::Control) {
            // The test's heartbeats share the server's thread: a long computation in an
            // earlier example (a model plant's tuning) can starve them. Take the lease anew.
            lease = ApiTestClient::result(c.call(QStringLiteral("control.acquire"))).value(QStringLiteral("lease")).toString();
            params.insert(QStringLiteral("lease"), lease);
        }
        const bool onStage = m.method.startsWith(QLatin1String("accuracy.")) || m.method.startsWith(QLatin1String("compensation."));
        if (m.method == QLatin1String("pattern.run") || m.method == QLatin1String("scan.run") || (onStage && spec.access != app::cli::Access::Compute)) {
            // Their examples run on a homed stage (the page says so): home it first, quietly.
            c.call(QStringLiteral("device.home"), QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}, {QStringLiteral("lease"), lease}},
                   120000);
        }
        // Run it: the host's jog renewals are timed in real time, and the circular test samples
        // the stage's status at its real rate; everything else runs 20× faster.
        const double scale = m.method == QLatin1String("device.jog") || m.method == QLatin1String("accuracy.circle") ? 1 : 20;
        f.stage.link.host().setTimeScale(scale);
        f.analyzer->link.host().setTimeScale(scale);
        QJsonObject answer = c.call(m.method, params, 120000);
        answer.insert(QStringLiteral("id"), 1);  // as the request shown
        if (answer.contains(QStringLiteral("result")))
            answer.insert(QStringLiteral("result"), shortened(answer.value(QStringLiteral("result"))));
        s.response = QString::fromUtf8(QJsonDocument(answer).toJson(QJsonDocument::Compact));
        s.response.replace(work.path() + QLatin1Char('/'), QString());  // paths as the client gave them
        out.push_back(s);
    }
    f.stage.link.host().setTimeScale(1);
    f.analyzer->link.host().setTimeScale(1);
    return out;
}

QString render(const QVector<Section>& sections)
{
    QString text;
    for (const Section& s : sections)
        text += s.head + QStringLiteral("← ") + s.response + QStringLiteral("\n```\n\n");
    return text;
}

/// The page's blocks, parsed back: method → (head, response).
QVector<Section> parse(const QString& text)
{
    QVector<Section> out;
    const QStringList blocks = text.split(QStringLiteral("### `"), Qt::SkipEmptyParts);
    for (const QString& b : blocks) {
        if (!b.contains(QStringLiteral("← ")))
            continue;
        Section s;
        s.method = b.section(QLatin1Char('`'), 0, 0);
        const int arrow = b.indexOf(QStringLiteral("← "));
        s.head = QStringLiteral("### `") + b.left(arrow);
        s.response = b.mid(arrow + 2).section(QLatin1Char('\n'), 0, 0);
        out.push_back(s);
    }
    return out;
}

TEST(ApiDocs, EveryMethodIsOnThePageWithItsParamsAnExampleAndAResponseOfTheRightShape)
{
    const QVector<Section> fresh = generate();
    QFile page(docPath());
    ASSERT_TRUE(page.open(QIODevice::ReadOnly));
    QString text = QString::fromUtf8(page.readAll());
    page.close();
    const int begin = text.indexOf(kBegin), end = text.indexOf(kEnd);
    ASSERT_GE(begin, 0);
    ASSERT_GT(end, begin);
    if (qEnvironmentVariableIsSet("BP_UPDATE_DOCS")) {
        text = text.left(begin + kBegin.size()) + QStringLiteral("\n\n") + render(fresh) + text.mid(end);
        QFile write(docPath());
        ASSERT_TRUE(write.open(QIODevice::WriteOnly | QIODevice::Truncate));
        write.write(text.toUtf8());
        return;
    }
    const QVector<Section> onPage = parse(text.mid(begin + kBegin.size(), end - begin - kBegin.size()));
    QStringList methodsOnPage, methodsNow;
    for (const auto& s : onPage)
        methodsOnPage << s.method;
    for (const auto& s : fresh)
        methodsNow << s.method;
    ASSERT_EQ(methodsOnPage, methodsNow) << "docs/api.md lists other methods: regenerate it (BP_UPDATE_DOCS=1, see the top of this file)";
    for (int i = 0; i < fresh.size(); ++i) {
        EXPECT_EQ(onPage[i].head.trimmed(), fresh[i].head.trimmed()) << fresh[i].method.toStdString() << ": regenerate docs/api.md";
        const QJsonValue shown = QJsonDocument::fromJson(onPage[i].response.toUtf8()).object();
        const QJsonValue now = QJsonDocument::fromJson(fresh[i].response.toUtf8()).object();
        EXPECT_EQ(shape(shown), shape(now)) << fresh[i].method.toStdString() << ": the example's answer changed shape\n  page: "
                                            << onPage[i].response.toStdString() << "\n  now:  " << fresh[i].response.toStdString();
        EXPECT_TRUE(now.toObject().contains(QStringLiteral("result")))
            << fresh[i].method.toStdString() << ": the example should succeed: " << fresh[i].response.toStdString();
    }
}

TEST(ApiDocs, DiscoverCarriesTheSameExamplesAsThePage)
{
    const QJsonObject doc = app::api::openRpcDocument(app::api::commandMethods());
    int withExample = 0;
    for (const QJsonValue& m : doc.value(QStringLiteral("methods")).toArray())
        withExample += m.toObject().contains(QStringLiteral("examples"));
    EXPECT_EQ(withExample, app::api::commandMethods().size()) << "every command method has an example in its ApiSpec";
}

} // namespace
