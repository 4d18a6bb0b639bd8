// Words for the grid map, the stage-error file and the 2D compensation table: ids
// grid.*, stage_errors.*, compensation2d.* and the terms compensation2d.request.*
// (docs/accuracy.md, appendix).
#include "widgets/wording/areas.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

class GridWords {
    Q_DECLARE_TR_FUNCTIONS(ui::words::GridWords)
public:
    static QString sentence(const motion::msg::Message& m);
    static QString term(const std::string& id);
};

QString gridArg(const motion::msg::Message& m, const char* name) { return ui::words::arg(m, name); }

QString GridWords::sentence(const motion::msg::Message& m)
{
    const std::string& id = m.id;
    if (id == "grid.too_few_nodes")
        return tr("%1 × %2 nodes: a map needs at least %3 a side").arg(gridArg(m, "columns"), gridArg(m, "rows"), gridArg(m, "min"));
    if (id == "grid.positions_not_increasing")
        return tr("position %1 does not come after %2: a grid's positions must increase").arg(gridArg(m, "value"), gridArg(m, "previous"));
    if (id == "grid.node_count_wrong")
        return tr("%1 nodes, where the grid has %2").arg(gridArg(m, "count"), gridArg(m, "expected"));
    if (id == "grid.node_off_grid")
        return tr("the node at (%1, %2) is off the grid, whose node here is at (%3, %4)")
            .arg(gridArg(m, "x"), gridArg(m, "y"), gridArg(m, "expected_x"), gridArg(m, "expected_y"));
    if (id == "grid.too_many_nodes")
        return tr("%1 × %2 nodes: a map has at most %3 a side").arg(gridArg(m, "columns"), gridArg(m, "rows"), gridArg(m, "max"));
    if (id == "grid.pitch_not_on_plate")
        return tr("a pitch of %1 is not a whole multiple of the plate's pitch %2: a node would find another node's dot")
            .arg(gridArg(m, "pitch"), gridArg(m, "plate_pitch"));
    if (id == "grid.leaves_travel")
        return tr("the grid reaches %2 on %1, beyond the travel's end at %3").arg(gridArg(m, "axis"), gridArg(m, "end"), gridArg(m, "limit"));
    if (id == "grid.run.no_start_dot")
        return tr("no dot to start from under the camera: %1").arg(gridArg(m, "cause"));
    if (id == "grid.run.start_leaves_travel")
        return tr("from the dot found at (%1, %2) the grid leaves the travel: %3").arg(gridArg(m, "x"), gridArg(m, "y"), gridArg(m, "detail"));
    if (id == "grid.run.node_failed")
        return tr("node %1 (column %2, row %3) has no reading: %4").arg(gridArg(m, "node"), gridArg(m, "column"), gridArg(m, "row"), gridArg(m, "cause"));
    if (id == "grid.run.incomplete")
        return tr("%1 of %2 nodes have no reading: no map until they are read (run again into the same folder to try them again)")
            .arg(gridArg(m, "failed"), gridArg(m, "total"));
    if (id == "grid.run.needs_xy")
        return tr("a grid map needs an instrument with X and Y axes");
    if (id == "grid.run.source_one_axis")
        return tr("this reading source reads one axis at a time; a grid map needs X and Y in one reading (the camera on a grid plate)");
    if (id == "grid.run.log_line")
        return tr("a line that is not part of a grid map's run log");
    if (id == "stage_errors.too_many_coefficients")
        return tr("%1 coefficients: at most %2 (order 5)").arg(gridArg(m, "count"), gridArg(m, "max"));
    if (id == "stage_errors.curve_too_large")
        return tr("the curve reaches %1 at %2, beyond ±%3").arg(gridArg(m, "value"), gridArg(m, "position"), gridArg(m, "max"));
    if (id == "compensation2d.nodes_out_of_range")
        return tr("%1 nodes: a 2D table has %2 to %3 a side").arg(gridArg(m, "count"), gridArg(m, "min"), gridArg(m, "max"));
    if (id == "compensation2d.node_count_wrong")
        return tr("%1 nodes, where the grid has %2").arg(gridArg(m, "count"), gridArg(m, "expected"));
    if (id == "compensation2d.not_supported")
        return tr("this instrument keeps no 2D compensation table");
    if (id == "compensation2d.upload_unreadable")
        return tr("the device answered COMP2D_UPLOAD with something unreadable");
    if (id == "compensation2d.state_unreadable")
        return tr("the device answered COMP2D_ENABLE with something unreadable");
    if (id == "compensation2d.map_not_a_grid")
        return tr("the nodes of %1 are not on one regular grid: no 2D table can be made of them").arg(gridArg(m, "file"));
    return {};
}

QString GridWords::term(const std::string& id)
{
    if (id == "compensation2d.request.upload")
        return tr("upload the 2D compensation table");
    if (id == "compensation2d.request.enable")
        return tr("enable the 2D compensation table");
    if (id == "compensation2d.request.disable")
        return tr("disable the 2D compensation table");
    if (id == "compensation2d.request.state")
        return tr("read the 2D compensation table's state");
    return {};
}

} // namespace

QString grid(const motion::msg::Message& m) { return GridWords::sentence(m); }
QString gridTerm(const std::string& id) { return GridWords::term(id); }

} // namespace ui::words::areas
