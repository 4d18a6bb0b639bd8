#pragma once
// Readers of the formats the scan exports, written from their published rules
// (not from our writers), so a round trip through them shows the stitching and
// acquisition tools would read our files:
//  - Fiji's Grid/Collection stitching TileConfiguration: lines are trimmed; those
//    starting with '#' or of three characters or fewer are skipped; "dim = n"
//    (split at '=' into exactly two parts, n a whole number, 2 or 3) must come
//    before any tile; a tile line splits at ';' (Java's split: trailing empty
//    parts dropped) into exactly three fields — file name, image name (not both
//    empty), and "(x, y…)" with exactly dim comma-separated numbers;
//  - Micro-Manager's Property Map 2.0 (PropertyMapJSONSerializer): a JSON object
//    with "encoding": "UTF-8", "format": "Micro-Manager Property Map",
//    "major_version" 2 (a newer major is refused), "minor_version", and "map";
//    every value in a map is {"type": T, "scalar": v} or {"type": T, "array": […]};
//    a position list's map holds "StagePositions", each with "DevicePositions"
//    whose entries name a "Device" and give "Position_um";
//  - CSV (RFC 4180).
#include "device/english_words.h"
#include "device/files/json.h"

#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace scanread {

inline std::string trim(const std::string& s)
{
    const auto a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos)
        return {};
    const auto b = s.find_last_not_of(" \t\r\n");
    return s.substr(a, b - a + 1);
}

/// java.lang.String.split with a one-character pattern.
inline std::vector<std::string> javaSplit(const std::string& s, char sep)
{
    std::vector<std::string> parts;
    std::string cur;
    for (char c : s) {
        if (c == sep) {
            parts.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    parts.push_back(cur);
    while (!parts.empty() && parts.back().empty())
        parts.pop_back();
    return parts;
}

/// Float.parseFloat on a trimmed string: a decimal number, optionally with an exponent.
inline bool javaParseFloat(const std::string& text, double* out)
{
    const std::string s = trim(text);
    if (s.empty())
        return false;
    char* end = nullptr;
    *out = std::strtod(s.c_str(), &end);
    std::string rest(end);
    if (rest == "f" || rest == "F" || rest == "d" || rest == "D")
        rest.clear();
    return end != s.c_str() && rest.empty();
}

struct FijiTile {
    std::string file;
    std::vector<double> coords;
};
struct FijiLayout {
    int dim = -1;
    std::vector<FijiTile> tiles;
    std::string error;  ///< empty when Fiji would accept the file
};

inline FijiLayout readTileConfiguration(const std::string& text)
{
    FijiLayout out;
    std::size_t at = 0;
    int lineNo = 0;
    while (at <= text.size()) {
        const std::size_t nl = text.find('\n', at);
        const std::string raw = text.substr(at, nl == std::string::npos ? std::string::npos : nl - at);
        at = nl == std::string::npos ? text.size() + 1 : nl + 1;
        ++lineNo;
        const std::string line = trim(raw);
        const std::string where = "line " + std::to_string(lineNo) + ": ";
        if (line.rfind('#', 0) == 0 || line.size() <= 3)
            continue;
        if (line.rfind("dim", 0) == 0) {
            const auto parts = javaSplit(line, '=');
            if (parts.size() != 2) {
                out.error = where + "does not look like [ dim = n ]";
                return out;
            }
            const std::string n = trim(parts[1]);
            if (n.empty() || n.find_first_not_of("0123456789") != std::string::npos) {
                out.error = where + "cannot parse dimensionality";
                return out;
            }
            out.dim = std::atoi(n.c_str());
            continue;
        }
        if (out.dim < 0) {
            out.error = where + "header missing, should look like [dim = n]";
            return out;
        }
        if (out.dim < 2 || out.dim > 3) {
            out.error = where + "only dimensions of 2 and 3 are supported";
            return out;
        }
        const auto entries = javaSplit(line, ';');
        if (entries.size() != 3) {
            out.error = where + "does not have 3 entries [fileName; ImagePlus; (x,y,...)]";
            return out;
        }
        FijiTile t;
        t.file = trim(entries[0]);
        if (t.file.empty() && trim(entries[1]).empty()) {
            out.error = where + "a file name or an ImagePlus is needed";
            return out;
        }
        std::string point = trim(entries[2]);
        if (point.size() < 2 || point.front() != '(' || point.back() != ')') {
            out.error = where + "wrong format of coordinates: " + point;
            return out;
        }
        const auto values = javaSplit(point.substr(1, point.size() - 2), ',');
        if (static_cast<int>(values.size()) != out.dim) {
            out.error = where + "wrong number of coordinates for dim = " + std::to_string(out.dim);
            return out;
        }
        for (const auto& v : values) {
            double x = 0;
            if (!javaParseFloat(v, &x)) {
                out.error = where + "cannot parse number: " + v;
                return out;
            }
            t.coords.push_back(x);
        }
        out.tiles.push_back(std::move(t));
    }
    return out;
}

struct MmPosition {
    std::string label, defaultXyStage;
    int gridRow = -1, gridCol = -1;
    struct Device {
        std::string name;
        std::vector<double> positionUm;
    };
    std::vector<Device> devices;
};
struct MmPositionList {
    std::vector<MmPosition> positions;
    std::string error;
};

inline bool mmTypedValue(const dev::files::json::Value& v, std::string* error);

inline bool mmMap(const dev::files::json::Value& map, std::string* error)
{
    if (!map.isObject()) {
        *error = "a property map must be a JSON object";
        return false;
    }
    for (const auto& m : map.members())
        if (!mmTypedValue(m.value, error)) {
            *error = m.key + ": " + *error;
            return false;
        }
    return true;
}

/// {"type": T, "scalar": v} or {"type": T, "array": [...]}, T one of the serializer's value types.
inline bool mmTypedValue(const dev::files::json::Value& v, std::string* error)
{
    static const std::set<std::string> types = {"BOOLEAN", "BYTE", "SHORT", "INTEGER", "LONG", "FLOAT", "DOUBLE", "STRING",
                                                "UUID", "COLOR", "AFFINE_TRANSFORM", "PROPERTY_MAP", "RECTANGLE", "DIMENSION",
                                                "POINT"};
    const dev::files::json::Value* type = v.find("type");
    if (!v.isObject() || !type || !type->isString() || !types.count(type->asString())) {
        *error = "a value must be {\"type\": T, ...} with a known type";
        return false;
    }
    const std::string t = type->asString();
    const dev::files::json::Value* scalar = v.find("scalar");
    const dev::files::json::Value* array = v.find("array");
    auto one = [&](const dev::files::json::Value& x) {
        if (t == "PROPERTY_MAP")
            return mmMap(x, error);
        if (t == "STRING" || t == "UUID")
            return x.isString() || (*error = "a " + t + " must be a string", false);
        if (t == "BOOLEAN")
            return x.isBool() || (*error = "a BOOLEAN must be true or false", false);
        if (t == "INTEGER" || t == "LONG" || t == "SHORT" || t == "BYTE")
            return (x.isNumber() && std::floor(x.asNumber()) == x.asNumber()) || (*error = "a " + t + " must be whole", false);
        if (t == "DOUBLE" || t == "FLOAT")
            return x.isNumber() || (*error = "a " + t + " must be a number", false);
        return true;
    };
    if (scalar && !scalar->isNull())
        return one(*scalar);
    if (!array || !array->isArray()) {
        *error = "a value needs \"scalar\" or \"array\"";
        return false;
    }
    for (const auto& item : array->items())
        if (!one(item))
            return false;
    return true;
}

inline MmPositionList readMicroManagerPositions(const std::string& text)
{
    MmPositionList out;
    const auto parsed = dev::files::json::parse(text);
    if (!parsed) {
        out.error = "not JSON: " + i18ntest::english(parsed.error.message);
        return out;
    }
    const dev::files::json::Value& doc = *parsed.value;
    const auto* enc = doc.find("encoding");
    const auto* fmt = doc.find("format");
    const auto* major = doc.find("major_version");
    const auto* minor = doc.find("minor_version");
    const auto* map = doc.find("map");
    if (!enc || !enc->isString() || enc->asString() != "UTF-8" || !fmt || !fmt->isString()
        || fmt->asString() != "Micro-Manager Property Map") {
        out.error = "not a Property Map 2 document (encoding and format)";
        return out;
    }
    if (!major || !major->isNumber() || major->asNumber() != 2 || !minor || !minor->isNumber()
        || std::floor(minor->asNumber()) != minor->asNumber()) {
        out.error = "major_version must be 2 and minor_version a whole number";
        return out;
    }
    if (!map || !mmMap(*map, &out.error)) {
        out.error = "map: " + out.error;
        return out;
    }
    const auto* list = map->find("StagePositions");
    if (!list || list->find("type")->asString() != "PROPERTY_MAP" || !list->find("array")) {
        out.error = "no StagePositions list";
        return out;
    }
    for (const auto& msp : list->find("array")->items()) {
        MmPosition p;
        auto scalar = [&](const char* key) -> const dev::files::json::Value* {
            const auto* v = msp.find(key);
            return v ? v->find("scalar") : nullptr;
        };
        if (const auto* l = scalar("Label"))
            p.label = l->asString();
        if (const auto* s = scalar("DefaultXYStage"))
            p.defaultXyStage = s->asString();
        if (const auto* r = scalar("GridRow"))
            p.gridRow = static_cast<int>(r->asNumber());
        if (const auto* c = scalar("GridCol"))
            p.gridCol = static_cast<int>(c->asNumber());
        const auto* devs = msp.find("DevicePositions");
        if (!devs || devs->find("type")->asString() != "PROPERTY_MAP" || !devs->find("array")) {
            out.error = "a position without DevicePositions";
            return out;
        }
        for (const auto& d : devs->find("array")->items()) {
            MmPosition::Device dev;
            const auto* name = d.find("Device");
            const auto* pos = d.find("Position_um");
            if (!name || !pos || pos->find("type")->asString() != "DOUBLE" || !pos->find("array")) {
                out.error = "a device position needs Device and a DOUBLE array Position_um";
                return out;
            }
            dev.name = name->find("scalar")->asString();
            for (const auto& x : pos->find("array")->items())
                dev.positionUm.push_back(x.asNumber());
            p.devices.push_back(std::move(dev));
        }
        out.positions.push_back(std::move(p));
    }
    return out;
}

/// RFC 4180: rows of fields; quoted fields may hold commas, quotes ("") and line breaks.
inline std::vector<std::vector<std::string>> readCsv(const std::string& text)
{
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> row;
    std::string field;
    bool quoted = false, any = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
                field += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                field += c;
            }
            continue;
        }
        any = true;
        if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            row.push_back(field);
            field.clear();
        } else if (c == '\r' || c == '\n') {
            if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n')
                ++i;
            row.push_back(field);
            rows.push_back(row);
            row.clear();
            field.clear();
            any = false;
        } else {
            field += c;
        }
    }
    if (any) {
        row.push_back(field);
        rows.push_back(row);
    }
    return rows;
}

} // namespace scanread
