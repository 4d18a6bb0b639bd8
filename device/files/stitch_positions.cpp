#include "device/files/stitch_positions.h"

#include "device/files/json_fields.h"
#include "device/files/json_lines.h"
#include "device/files/scan_run_log.h"

#include <set>

namespace dev::files::scan {

using dev::files::json::ObjectReader;
using dev::files::json::Value;

motion::msg::Checked<std::vector<TakenTile>> parseTakenTiles(std::string_view text, const std::string& fileName)
{
    using Result = motion::msg::Checked<std::vector<TakenTile>>;
    std::vector<TakenTile> tiles;
    dev::files::json::Problems problems;
    std::set<int> seen;
    std::set<std::string> images;
    bool header = false;
    dev::files::json::TextLines lines(text);
    while (const auto line = lines.next()) {
        const int lineNo = line->number;
        dev::files::json::ParseResult parsed;
        if (dev::files::json::parseLine(*line, header, parsed, problems) != dev::files::json::LineOutcome::Value)
            break;  // an error, or a last line torn by a crash: that tile was not taken
        dev::files::json::Problems lp;
        if (!header) {
            dev::files::json::checkSchema(*parsed.value, kRunLogSchema, kRunLogVersion, lp);
            header = true;
        } else {
            ObjectReader o(*parsed.value, "", lp);
            const auto tile = o.integer("tile", true, 0, 1000000000);
            const Value* image = o.get("image", Value::Type::String, false);
            const auto label = image ? std::optional<std::string>(image->asString()) : o.string("label", true);
            const Value* measured = o.get("measured_mm", Value::Type::Array, true);
            if (measured && (measured->items().size() != 2 || !measured->items()[0].isNumber() || !measured->items()[1].isNumber()))
                lp.add(*measured, "measured_mm", motion::msg::make("file.json.array_of_numbers", {motion::msg::integer("count", 2)}));
            else if (tile && label && measured) {
                if (label->empty() || label->find('/') != std::string::npos || label->find('\\') != std::string::npos)
                    lp.add(image ? *image : *parsed.value->find("label"), image ? "image" : "label",
                           motion::msg::make("imaging.positions.bad_image_name", {motion::msg::verbatim("file", *label)}));
                else if (!seen.insert(static_cast<int>(*tile)).second || !images.insert(*label).second)
                    lp.add(*parsed.value, "", motion::msg::make("imaging.positions.duplicate", {motion::msg::verbatim("file", *label)}));
                else
                    tiles.push_back({static_cast<int>(*tile), *label, measured->items()[0].asNumber(), measured->items()[1].asNumber(), lineNo});
            }
        }
        dev::files::json::addAtLine(problems, lp, lineNo);
    }
    if (!header && problems.empty())
        problems.add(dev::files::json::Position{1, 1}, "", motion::msg::make("file.log.empty"));
    if (problems.hasErrors()) {
        motion::msg::Problems out;
        dev::files::json::appendSorted(out, problems, fileName);
        return Result::refused(std::move(out));
    }
    if (tiles.empty())
        return Result::fail(motion::msg::make("imaging.positions.no_tiles", {motion::msg::verbatim("file", fileName)}));
    return Result::ok(std::move(tiles));
}

} // namespace dev::files::scan
