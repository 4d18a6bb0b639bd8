#include "device/files/scan_exports.h"

#include "device/files/json.h"
#include "device/files/json_fields.h"
#include "device/files/position_csv.h"
#include "device/files/text_file.h"
#include "motion/plans/scan/scan_naming.h"

#include <QCoreApplication>
#include <QDir>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dev::files::scan {


using motion::PositionRecord;
using motion::scan::Point2;
using motion::scan::ScanLayout;
using motion::scan::ScanPlan;
using dev::files::json::Value;

std::vector<PositionRecord> plannedRecords(const ScanPlan& plan, const ScanLayout& layout)
{
    std::vector<PositionRecord> out;
    out.reserve(layout.tiles.size());
    for (const auto& t : layout.tiles) {
        PositionRecord r;
        r.target = t.index;
        r.label = motion::scan::tileFileName(plan.naming, t.index, t.row, t.col);
        r.plannedMm = {t.centre.xMm, t.centre.yMm};
        const Point2 c = motion::scan::commandedTarget(plan, t.centre);
        r.commandedMm = {c.xMm, c.yMm};
        out.push_back(std::move(r));
    }
    return out;
}

Point2 stitchPosition(const ScanPlan& plan, const PositionRecord& r)
{
    if (!r.measured() || r.measuredMm.size() < 2)
        return {r.plannedMm.at(0), r.plannedMm.at(1)};
    // A compensated stage reports its grating in the nominal frame (the device takes its
    // correction off): the reading is where the work point was.
    (void)plan;
    return {r.measuredMm[0], r.measuredMm[1]};
}

Point2 stageToPixels(const motion::scan::Camera& camera, Point2 stageMm)
{
    // The image's x axis lies at rotation_deg from stage +X; its y axis (downwards on
    // screen) a quarter turn clockwise from that for stage-minus-y, anticlockwise for plus.
    const double th = camera.rotationDeg * M_PI / 180.0;
    const double exX = std::cos(th), exY = std::sin(th);
    const bool minus = camera.imageY == motion::scan::ImageY::StageMinusY;
    const double eyX = minus ? std::sin(th) : -std::sin(th);
    const double eyY = minus ? -std::cos(th) : std::cos(th);
    const double perMm = 1000.0 / motion::scan::pixelAtSampleUm(camera);
    return {(stageMm.xMm * exX + stageMm.yMm * exY) * perMm, (stageMm.xMm * eyX + stageMm.yMm * eyY) * perMm};
}

std::string tileConfiguration(const ScanPlan& plan, const std::vector<PositionRecord>& records)
{
    std::vector<Point2> px;
    px.reserve(records.size());
    for (const PositionRecord& r : records)
        px.push_back(stageToPixels(plan.camera, stitchPosition(plan, r)));
    // Fiji places each image's top-left corner at its coordinates; only differences
    // matter, so the mosaic's top-left tile is put at the origin.
    double minX = 0, minY = 0;
    if (!px.empty()) {
        minX = std::min_element(px.begin(), px.end(), [](auto a, auto b) { return a.xMm < b.xMm; })->xMm;
        minY = std::min_element(px.begin(), px.end(), [](auto a, auto b) { return a.yMm < b.yMm; })->yMm;
    }
    std::string out = "# Stitching scan \"" + plan.name + "\" from BenchPilot: tile positions in pixels ("
        + dev::files::json::formatNumber(motion::scan::pixelAtSampleUm(plan.camera)) + " µm each)\n";
    out += "# Define the number of dimensions we are working on\ndim = 2\n\n# Define the image coordinates\n";
    char buf[96];
    for (std::size_t i = 0; i < records.size(); ++i) {
        std::snprintf(buf, sizeof buf, "; ; (%.3f, %.3f)\n", px[i].xMm - minX, px[i].yMm - minY);
        out += records[i].label + buf;
    }
    return out;
}

namespace {

/// A Property Map 2.0 value: {"type": T, "scalar": v} or {"type": T, "array": [...]}.
Value typed(const char* type, const char* shape, Value v)
{
    Value o = Value::object();
    o.set("type", Value(type));
    o.set(shape, std::move(v));
    return o;
}

} // namespace

std::string microManagerPositions(const ScanPlan& plan, const ScanLayout& layout)
{
    // Micro-Manager's PropertyMap JSON serializer: a versioned envelope around the
    // map; PositionList's map holds "StagePositions", a list of MultiStagePosition
    // maps (members in its alphabetical order) whose "DevicePositions" list one
    // StagePosition per device: "Device" and "Position_um". Positions are the planned
    // targets: Micro-Manager drives its stage there itself.
    Value list = Value::array();
    for (const auto& t : layout.tiles) {
        Value xy = Value::array();
        xy.push(t.centre.xMm * 1000.0);
        xy.push(t.centre.yMm * 1000.0);
        Value device = Value::object();
        device.set("Device", typed("STRING", "scalar", Value(plan.naming.mmXyStage)));
        device.set("Position_um", typed("DOUBLE", "array", std::move(xy)));
        Value devices = Value::array();
        devices.push(std::move(device));
        Value msp = Value::object();
        msp.set("DefaultXYStage", typed("STRING", "scalar", Value(plan.naming.mmXyStage)));
        msp.set("DefaultZStage", typed("STRING", "scalar", Value("")));
        msp.set("DevicePositions", typed("PROPERTY_MAP", "array", std::move(devices)));
        msp.set("GridCol", typed("INTEGER", "scalar", Value(t.col)));
        msp.set("GridRow", typed("INTEGER", "scalar", Value(t.row)));
        std::string label = motion::scan::tileFileName(plan.naming, t.index, t.row, t.col);
        label = label.substr(0, label.rfind('.'));
        msp.set("Label", typed("STRING", "scalar", Value(label)));
        msp.set("Properties", typed("PROPERTY_MAP", "scalar", Value::object()));
        list.push(std::move(msp));
    }
    Value map = Value::object();
    map.set("StagePositions", typed("PROPERTY_MAP", "array", std::move(list)));
    Value doc = Value::object();
    doc.set("encoding", Value("UTF-8"));
    doc.set("format", Value("Micro-Manager Property Map"));
    doc.set("major_version", Value(2));
    doc.set("minor_version", Value(0));
    doc.set("map", std::move(map));
    return dev::files::json::write(doc) + "\n";
}

std::string scanCsv(const ScanPlan& plan, const ScanLayout& layout, const std::vector<PositionRecord>& records)
{
    dev::files::CsvColumn row{"row", {}}, col{"col", {}}, workX{"stitch_x_mm", {}}, workY{"stitch_y_mm", {}};
    char buf[48];
    for (std::size_t i = 0; i < records.size(); ++i) {
        const auto& t = layout.tiles.at(i);
        row.cells.push_back(std::to_string(t.row));
        col.cells.push_back(std::to_string(t.col));
        const Point2 p = stitchPosition(plan, records[i]);
        std::snprintf(buf, sizeof buf, "%.6f", p.xMm);
        workX.cells.push_back(buf);
        std::snprintf(buf, sizeof buf, "%.6f", p.yMm);
        workY.cells.push_back(buf);
    }
    return dev::files::positionRecordsCsv(records, "XY", {row, col, workX, workY});
}

bool writeExports(const QString& folder, const ScanPlan& plan, const ScanLayout& layout,
                  const std::vector<PositionRecord>& records, QStringList* written, motion::msg::Message* error)
{
    if (!QDir().mkpath(folder)) {
        *error = motion::msg::make("file.cannot_make_folder", {motion::msg::verbatim("folder", folder.toStdString())});
        return false;
    }
    const QDir dir(folder);
    const std::pair<const char*, std::string> outputs[] = {
        {kTileConfigFile, tileConfiguration(plan, records)},
        {kPositionsFile, microManagerPositions(plan, layout)},
        {kCsvFile, scanCsv(plan, layout, records)},
    };
    for (const auto& [name, text] : outputs) {
        const QString path = dir.filePath(QString::fromLatin1(name));
        if (!dev::files::writeAtomically(path, text, error))
            return false;
        if (written)
            *written << path;
    }
    return true;
}

} // namespace dev::files::scan
