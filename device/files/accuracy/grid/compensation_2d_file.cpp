#include "device/files/accuracy/grid/compensation_2d_file.h"

#include "device/files/accuracy/load_text.h"
#include "device/files/text_file.h"

#include <cmath>
#include <cstdio>

namespace dev::files::accuracy {

using dev::files::json::ObjectReader;
using dev::files::json::Value;
using motion::metrology::CompensationTable2D;

namespace {
constexpr double kTable2dAny = 1e12;
constexpr double kTable2dOnGridMm = 1e-3;
} // namespace

std::string compensation2DToJson(const Compensation2DFile& f)
{
    const CompensationTable2D& t = f.table;
    Value root = dev::files::json::schemaObject(kCompensation2DSchema, kCompensation2DVersion);
    Value g = Value::object();
    g.set("origin_x_mm", t.originXMm);
    g.set("origin_y_mm", t.originYMm);
    g.set("pitch_x_mm", t.pitchXMm);
    g.set("pitch_y_mm", t.pitchYMm);
    g.set("columns", t.columns);
    g.set("rows", t.rows);
    root.set("grid", g);
    Value nodes = Value::array();
    for (int j = 0; j < t.rows; ++j)
        for (int i = 0; i < t.columns; ++i) {
            const auto k = static_cast<std::size_t>(j * t.columns + i);
            Value v = Value::object();
            v.set("x_mm", t.originXMm + t.pitchXMm * i);
            v.set("y_mm", t.originYMm + t.pitchYMm * j);
            v.set("correction_x_um", t.correctionXUm[k]);
            v.set("correction_y_um", t.correctionYUm[k]);
            nodes.push(v);
        }
    root.set("nodes", nodes);
    if (!f.source.empty())
        root.set("source", f.source);
    return dev::files::json::write(root);
}

Compensation2DRead compensation2DFromJson(std::string_view text, std::string_view fileName)
{
    motion::msg::Problems problems;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        problems.push_back(fromParseError(parsed.error, fileName));
        return Compensation2DRead::refused(std::move(problems));
    }
    const Value& root = *parsed.value;
    dev::files::json::Problems p;
    if (!dev::files::json::checkSchema(root, kCompensation2DSchema, kCompensation2DVersion, p)) {
        addJsonProblems(p, fileName, problems);
        return Compensation2DRead::refused(std::move(problems));
    }
    Compensation2DFile f;
    CompensationTable2D& t = f.table;
    ObjectReader o(root, "", p);
    bool gridRead = false;
    if (const Value* g = o.get("grid", Value::Type::Object, true)) {
        ObjectReader go(*g, "grid", p);
        const auto ox = go.number("origin_x_mm", true, -kTable2dAny, kTable2dAny);
        const auto oy = go.number("origin_y_mm", true, -kTable2dAny, kTable2dAny);
        const auto px = go.number("pitch_x_mm", true, -kTable2dAny, kTable2dAny);
        const auto py = go.number("pitch_y_mm", true, -kTable2dAny, kTable2dAny);
        const auto nx = go.integer("columns", true, 0, 1000000);
        const auto ny = go.integer("rows", true, 0, 1000000);
        go.refuseUnknown({"origin_x_mm", "origin_y_mm", "pitch_x_mm", "pitch_y_mm", "columns", "rows"});
        if (ox && oy && px && py && nx && ny) {
            t.originXMm = *ox;
            t.originYMm = *oy;
            t.pitchXMm = *px;
            t.pitchYMm = *py;
            t.columns = static_cast<int>(*nx);
            t.rows = static_cast<int>(*ny);
            gridRead = true;
        }
    }
    if (const Value* list = o.get("nodes", Value::Type::Array, true))
        for (std::size_t k = 0; k < list->items().size(); ++k) {
            ObjectReader no(list->items()[k], dev::files::json::childPath("nodes", k), p);
            const auto x = no.number("x_mm", true, -kTable2dAny, kTable2dAny);
            const auto y = no.number("y_mm", true, -kTable2dAny, kTable2dAny);
            const auto cx = no.number("correction_x_um", true, -kTable2dAny, kTable2dAny);
            const auto cy = no.number("correction_y_um", true, -kTable2dAny, kTable2dAny);
            no.refuseUnknown({"x_mm", "y_mm", "correction_x_um", "correction_y_um"});
            if (!(x && y && cx && cy))
                continue;
            t.correctionXUm.push_back(*cx);
            t.correctionYUm.push_back(*cy);
            // A node's position is for people reading the file; it must be where the
            // grid puts it, or the file says two different things.
            if (gridRead && t.columns > 0) {
                const double gx = t.originXMm + t.pitchXMm * static_cast<double>(k % static_cast<std::size_t>(t.columns));
                const double gy = t.originYMm + t.pitchYMm * static_cast<double>(k / static_cast<std::size_t>(t.columns));
                if (std::abs(*x - gx) > kTable2dOnGridMm || std::abs(*y - gy) > kTable2dOnGridMm)
                    p.add(list->items()[k], dev::files::json::childPath("nodes", k),
                          motion::msg::make("grid.node_off_grid", {motion::msg::real("x", *x, motion::msg::Unit::Mm), motion::msg::real("y", *y, motion::msg::Unit::Mm),
                                                           motion::msg::real("expected_x", gx, motion::msg::Unit::Mm),
                                                           motion::msg::real("expected_y", gy, motion::msg::Unit::Mm)}));
            }
        }
    if (auto s = o.string("source", false))
        f.source = *s;
    o.refuseUnknown({"schema", "version", "grid", "nodes", "source"});
    addJsonProblems(p, fileName, problems);
    if (hasErrors(problems))
        return Compensation2DRead::refused(std::move(problems));
    addModelProblems(motion::metrology::validate(t), root, fileName, problems);
    return Compensation2DRead::from(f, std::move(problems));
}

Compensation2DRead loadCompensation2DFile(const QString& path)
{
    motion::msg::Problems problems;
    std::string name;
    const auto text = loadText(path, name, problems);
    return text ? compensation2DFromJson(*text, name) : Compensation2DRead::refused(std::move(problems));
}

bool saveCompensation2DFile(const QString& path, const Compensation2DFile& f, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, compensation2DToJson(f), error);
}

std::string compensation2DToCsv(const CompensationTable2D& t)
{
    std::string out = "x_mm,y_mm,correction_x_um,correction_y_um\n";
    char line[128];
    for (int j = 0; j < t.rows; ++j)
        for (int i = 0; i < t.columns; ++i) {
            const auto k = static_cast<std::size_t>(j * t.columns + i);
            std::snprintf(line, sizeof line, "%.6f,%.6f,%.4f,%.4f\n", t.originXMm + t.pitchXMm * i,
                          t.originYMm + t.pitchYMm * j, t.correctionXUm[k], t.correctionYUm[k]);
            out += line;
        }
    return out;
}

} // namespace dev::files::accuracy
