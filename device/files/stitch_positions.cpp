#include "device/files/stitch_positions.h"

#include "device/files/json_fields.h"
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
    std::size_t at = 0;
    int lineNo = 0;
    bool header = false;
    while (at < text.size()) {
        const std::size_t nl = text.find('\n', at);
        const bool complete = nl != std::string_view::npos;
        const std::string_view line = text.substr(at, complete ? nl - at : std::string_view::npos);
        at = complete ? nl + 1 : text.size();
        ++lineNo;
        dev::files::json::ParseResult parsed = dev::files::json::parse(line);
        if (!parsed.value) {
            if (!complete && header)
                break;  // torn by a crash: the tile was not taken
            problems.add(dev::files::json::Position{lineNo, parsed.error.position.column}, "", parsed.error.message);
            break;
        }
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
        for (const auto& p : lp.list())
            problems.add(dev::files::json::Position{lineNo, p.column}, p.path, p.message);
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
