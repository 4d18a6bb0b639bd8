#include "device/files/accuracy/grid/grid_map_result_file.h"

#include "device/files/accuracy/load_text.h"
#include "device/files/text_file.h"

#include <cmath>

namespace dev::files::accuracy {

using dev::files::json::ObjectReader;
using dev::files::json::Value;
using motion::metrology::GridMapNode;

namespace {

constexpr double kGridAny = 1e12;
constexpr double kGridOnGridMm = 1e-3;  ///< a node within 1 µm of its grid place is on it

Value gridOrNull(const std::optional<double>& v) { return v ? Value(*v) : Value(nullptr); }

std::optional<double> gridNumberOrNull(ObjectReader& o, std::string_view key)
{
    const Value* v = o.value().find(key);
    if (!v || v->isNull())
        return std::nullopt;
    return o.number(key, false, -kGridAny, kGridAny);
}

} // namespace

std::string gridMapResultToJson(const GridMapResultFile& f)
{
    const auto& r = f.result;
    Value root = dev::files::json::schemaObject(kGridMapResultSchema, kGridMapResultVersion);
    root.set("standard", "ISO 230-1 least-squares reference lines");
    Value pl = Value::object();
    pl.set("offset_x_um", r.placement.offsetXUm);
    pl.set("offset_y_um", r.placement.offsetYUm);
    pl.set("rotation_urad", r.placement.rotationUrad);
    root.set("placement", pl);
    Value fig = Value::object();
    fig.set("scale_x_ppm", r.figures.scaleXPpm);
    fig.set("scale_y_ppm", r.figures.scaleYPpm);
    fig.set("squareness_urad", r.figures.squarenessUrad);
    fig.set("straightness_x_um", r.figures.straightnessXUm);
    fig.set("straightness_y_um", r.figures.straightnessYUm);
    fig.set("rms_error_um", r.figures.rmsErrorUm);
    fig.set("max_error_um", r.figures.maxErrorUm);
    fig.set("rms_residual_um", r.figures.rmsResidualUm);
    fig.set("max_reversal_um", gridOrNull(r.figures.maxReversalUm));
    fig.set("mean_reversal_x_um", gridOrNull(r.figures.meanReversalXUm));
    fig.set("mean_reversal_y_um", gridOrNull(r.figures.meanReversalYUm));
    root.set("figures", fig);
    Value nodes = Value::array();
    for (const GridMapNode& n : r.nodes) {
        Value v = Value::object();
        v.set("x_mm", n.xMm);
        v.set("y_mm", n.yMm);
        v.set("ex_um", n.exUm);
        v.set("ey_um", n.eyUm);
        v.set("residual_x_um", n.residualXUm);
        v.set("residual_y_um", n.residualYUm);
        v.set("reversal_x_um", gridOrNull(n.reversalXUm));
        v.set("reversal_y_um", gridOrNull(n.reversalYUm));
        // Each direction's own error, only in a bidirectional map (ex, ey are their mean).
        if (n.bidirectional() && n.forwardExUm && n.forwardEyUm && n.reverseExUm && n.reverseEyUm) {
            v.set("reversal_um", n.reversalUm());
            v.set("forward_ex_um", *n.forwardExUm);
            v.set("forward_ey_um", *n.forwardEyUm);
            v.set("reverse_ex_um", *n.reverseExUm);
            v.set("reverse_ey_um", *n.reverseEyUm);
        }
        nodes.push(v);
    }
    root.set("nodes", nodes);
    if (!f.source.empty())
        root.set("source", f.source);
    return dev::files::json::write(root);
}

GridMapResultRead gridMapResultFromJson(std::string_view text, std::string_view fileName)
{
    motion::msg::Problems problems;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        problems.push_back(fromParseError(parsed.error, fileName));
        return GridMapResultRead::refused(std::move(problems));
    }
    const Value& root = *parsed.value;
    dev::files::json::Problems p;
    if (!dev::files::json::checkSchema(root, kGridMapResultSchema, kGridMapResultVersion, p)) {
        addJsonProblems(p, fileName, problems);
        return GridMapResultRead::refused(std::move(problems));
    }
    GridMapResultFile f;
    auto& r = f.result;
    ObjectReader o(root, "", p);
    (void)o.string("standard", false);
    if (const Value* v = o.get("placement", Value::Type::Object, false)) {
        ObjectReader po(*v, "placement", p);
        r.placement.offsetXUm = po.number("offset_x_um", true, -kGridAny, kGridAny).value_or(0);
        r.placement.offsetYUm = po.number("offset_y_um", true, -kGridAny, kGridAny).value_or(0);
        r.placement.rotationUrad = po.number("rotation_urad", true, -kGridAny, kGridAny).value_or(0);
        po.refuseUnknown({"offset_x_um", "offset_y_um", "rotation_urad"});
    }
    if (const Value* v = o.get("figures", Value::Type::Object, true)) {
        ObjectReader fo(*v, "figures", p);
        auto& g = r.figures;
        g.scaleXPpm = fo.number("scale_x_ppm", true, -kGridAny, kGridAny).value_or(0);
        g.scaleYPpm = fo.number("scale_y_ppm", true, -kGridAny, kGridAny).value_or(0);
        g.squarenessUrad = fo.number("squareness_urad", true, -kGridAny, kGridAny).value_or(0);
        g.straightnessXUm = fo.number("straightness_x_um", true, 0, kGridAny).value_or(0);
        g.straightnessYUm = fo.number("straightness_y_um", true, 0, kGridAny).value_or(0);
        g.rmsErrorUm = fo.number("rms_error_um", true, 0, kGridAny).value_or(0);
        g.maxErrorUm = fo.number("max_error_um", true, 0, kGridAny).value_or(0);
        g.rmsResidualUm = fo.number("rms_residual_um", true, 0, kGridAny).value_or(0);
        g.maxReversalUm = gridNumberOrNull(fo, "max_reversal_um");
        g.meanReversalXUm = gridNumberOrNull(fo, "mean_reversal_x_um");
        g.meanReversalYUm = gridNumberOrNull(fo, "mean_reversal_y_um");
        fo.refuseUnknown({"scale_x_ppm", "scale_y_ppm", "squareness_urad", "straightness_x_um", "straightness_y_um",
                          "rms_error_um", "max_error_um", "rms_residual_um", "max_reversal_um", "mean_reversal_x_um",
                          "mean_reversal_y_um"});
    }
    std::vector<const Value*> nodeValues;
    if (const Value* list = o.get("nodes", Value::Type::Array, true))
        for (std::size_t i = 0; i < list->items().size(); ++i) {
            ObjectReader no(list->items()[i], dev::files::json::childPath("nodes", i), p);
            GridMapNode n;
            const auto x = no.number("x_mm", true, -kGridAny, kGridAny);
            const auto y = no.number("y_mm", true, -kGridAny, kGridAny);
            const auto ex = no.number("ex_um", true, -kGridAny, kGridAny);
            const auto ey = no.number("ey_um", true, -kGridAny, kGridAny);
            n.residualXUm = no.number("residual_x_um", false, -kGridAny, kGridAny).value_or(0);
            n.residualYUm = no.number("residual_y_um", false, -kGridAny, kGridAny).value_or(0);
            n.reversalXUm = gridNumberOrNull(no, "reversal_x_um");
            n.reversalYUm = gridNumberOrNull(no, "reversal_y_um");
            n.forwardExUm = gridNumberOrNull(no, "forward_ex_um");
            n.forwardEyUm = gridNumberOrNull(no, "forward_ey_um");
            n.reverseExUm = gridNumberOrNull(no, "reverse_ex_um");
            n.reverseEyUm = gridNumberOrNull(no, "reverse_ey_um");
            (void)gridNumberOrNull(no, "reversal_um");  // the reversal's length, for a reader without a calculator
            no.refuseUnknown({"x_mm", "y_mm", "ex_um", "ey_um", "residual_x_um", "residual_y_um", "reversal_x_um", "reversal_y_um",
                              "reversal_um", "forward_ex_um", "forward_ey_um", "reverse_ex_um", "reverse_ey_um"});
            if (x && y && ex && ey) {
                n.xMm = *x;
                n.yMm = *y;
                n.exUm = *ex;
                n.eyUm = *ey;
                r.nodes.push_back(n);
                nodeValues.push_back(&list->items()[i]);
            }
        }
    if (auto s = o.string("source", false))
        f.source = *s;
    o.refuseUnknown({"schema", "version", "standard", "placement", "figures", "nodes", "source"});
    addJsonProblems(p, fileName, problems);
    if (hasErrors(problems))
        return GridMapResultRead::refused(std::move(problems));
    // The nodes: one regular grid, row by row, as a map is visited and a 2D table kept.
    std::size_t nx = 0;
    while (nx < r.nodes.size() && r.nodes[nx].yMm == r.nodes.front().yMm)
        ++nx;
    const std::size_t n = r.nodes.size();
    if (nx < 2 || n / nx < 2) {
        problems.emplace_back(std::string(fileName), root.position().line, root.position().column, "nodes",
                                  motion::msg::make("grid.too_few_nodes", {motion::msg::integer("columns", static_cast<long long>(nx)),
                                                                   motion::msg::integer("rows", static_cast<long long>(nx ? n / nx : 0)),
                                                                   motion::msg::integer("min", 2)}));
        return GridMapResultRead::refused(std::move(problems));
    }
    if (n % nx != 0) {
        const auto pos = nodeValues.back()->position();
        problems.emplace_back(std::string(fileName), pos.line, pos.column, dev::files::json::childPath("nodes", n - 1),
                                  motion::msg::make("grid.node_count_wrong", {motion::msg::integer("count", static_cast<long long>(n)),
                                                                      motion::msg::integer("expected", static_cast<long long>((n / nx + 1) * nx))}));
        return GridMapResultRead::refused(std::move(problems));
    }
    const double x0 = r.nodes.front().xMm, y0 = r.nodes.front().yMm;
    const double px = (r.nodes[nx - 1].xMm - x0) / static_cast<double>(nx - 1);
    const double py = (r.nodes[n - 1].yMm - y0) / static_cast<double>(n / nx - 1);
    for (std::size_t k = 0; k < n; ++k) {
        const double gx = x0 + px * static_cast<double>(k % nx), gy = y0 + py * static_cast<double>(k / nx);
        if (!(px > 0) || !(py > 0) || std::abs(r.nodes[k].xMm - gx) > kGridOnGridMm
            || std::abs(r.nodes[k].yMm - gy) > kGridOnGridMm) {
            const auto pos = nodeValues[k]->position();
            problems.emplace_back(std::string(fileName), pos.line, pos.column, dev::files::json::childPath("nodes", k),
                                      motion::msg::make("grid.node_off_grid", {motion::msg::real("x", r.nodes[k].xMm, motion::msg::Unit::Mm),
                                                                       motion::msg::real("y", r.nodes[k].yMm, motion::msg::Unit::Mm),
                                                                       motion::msg::real("expected_x", gx, motion::msg::Unit::Mm),
                                                                       motion::msg::real("expected_y", gy, motion::msg::Unit::Mm)}));
            return GridMapResultRead::refused(std::move(problems));
        }
    }
    return GridMapResultRead::from(f, std::move(problems));
}

GridMapResultRead loadGridMapResultFile(const QString& path)
{
    motion::msg::Problems problems;
    std::string name;
    const auto text = loadText(path, name, problems);
    return text ? gridMapResultFromJson(*text, name) : GridMapResultRead::refused(std::move(problems));
}

bool saveGridMapResultFile(const QString& path, const GridMapResultFile& f, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, gridMapResultToJson(f), error);
}

} // namespace dev::files::accuracy
