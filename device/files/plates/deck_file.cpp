#include "device/files/plates/deck_file.h"

#include "device/files/plates/json_path.h"

namespace dev::files::plates {

using dev::files::json::ObjectReader;
using dev::files::json::Value;

namespace {
constexpr double kDeckBig = 1e6;

void readAxis(const Value& axes, const char* letter, motion::plates::AxisMotion& a, dev::files::json::Problems& problems)
{
    const Value* v = axes.find(letter);
    if (!v) {
        problems.add(axes, dev::files::json::childPath("axes", letter), motion::msg::make("file.json.missing"));
        return;
    }
    ObjectReader o(*v, dev::files::json::childPath("axes", letter), problems);
    o.refuseUnknown({"max_speed", "default_speed", "accel_time_s", "max_accel"});
    a.maxSpeed = o.number("max_speed", true, 0, kDeckBig).value_or(0);
    a.defaultSpeed = o.number("default_speed", true, 0, kDeckBig).value_or(0);
    a.accelTimeS = o.number("accel_time_s", true, 0, 100).value_or(0);
    a.maxAccel = o.number("max_accel", true, 0, 1e9).value_or(0);
}

Value axisJson(const motion::plates::AxisMotion& a)
{
    Value v = Value::object();
    v.set("max_speed", a.maxSpeed);
    v.set("default_speed", a.defaultSpeed);
    v.set("accel_time_s", a.accelTimeS);
    v.set("max_accel", a.maxAccel);
    return v;
}
} // namespace

DeckRead parseDeck(std::string_view text)
{
    DeckRead r;
    const std::optional<Value> parsed = parseOrReport(text, r.problems);
    if (!parsed)
        return r;
    const Value& root = *parsed;
    if (!dev::files::json::checkSchema(root, kDeckSchema, kDeckVersion, r.problems))
        return r;
    ObjectReader o(root, "", r.problems);
    o.refuseUnknown({"schema", "version", "id", "name", "travel_x_mm", "travel_y_mm", "travel_z_mm", "table_z_mm", "syringe_ul",
                     "move_overhead_s", "axes", "slots", "stations"});
    motion::plates::Deck d;
    d.id = o.string("id", true).value_or("");
    d.name = o.string("name", false).value_or("");
    d.travelXMm = o.number("travel_x_mm", true, 0, kDeckBig).value_or(0);
    d.travelYMm = o.number("travel_y_mm", true, 0, kDeckBig).value_or(0);
    d.travelZMm = o.number("travel_z_mm", true, 0, kDeckBig).value_or(0);
    d.tableZMm = o.number("table_z_mm", true, 0, kDeckBig).value_or(0);
    d.syringeUl = o.number("syringe_ul", true, 0, 1e9).value_or(0);
    d.moveOverheadS = o.number("move_overhead_s", false, 0, 1).value_or(d.moveOverheadS);
    if (const Value* axes = o.get("axes", Value::Type::Object, true)) {
        ObjectReader a(*axes, "axes", r.problems);
        a.refuseUnknown({"X", "Y", "Z", "P"});
        readAxis(*axes, "X", d.x, r.problems);
        readAxis(*axes, "Y", d.y, r.problems);
        readAxis(*axes, "Z", d.z, r.problems);
        readAxis(*axes, "P", d.p, r.problems);
    }
    if (const Value* list = o.get("slots", Value::Type::Array, true)) {
        for (std::size_t k = 0; k < list->items().size() && k < 64; ++k) {
            ObjectReader s(list->items()[k], dev::files::json::childPath("slots", k), r.problems);
            s.refuseUnknown({"id", "name", "origin_x_mm", "origin_y_mm", "rotation_deg"});
            motion::plates::Slot slot;
            slot.id = s.string("id", true).value_or("");
            slot.name = s.string("name", false).value_or("");
            slot.originXMm = s.number("origin_x_mm", true, -kDeckBig, kDeckBig).value_or(0);
            slot.originYMm = s.number("origin_y_mm", true, -kDeckBig, kDeckBig).value_or(0);
            slot.rotationDeg = s.number("rotation_deg", false, -360, 360).value_or(0);
            d.plateSlots.push_back(slot);
        }
        if (list->items().empty())
            r.problems.add(*list, "slots", motion::msg::make("plate.deck.no_slots"));
    }
    if (const Value* stations = o.get("stations", Value::Type::Array, false)) {
        for (std::size_t k = 0; k < stations->items().size() && k < 64; ++k) {
            ObjectReader s(stations->items()[k], dev::files::json::childPath("stations", k), r.problems);
            s.refuseUnknown({"id", "name", "x_mm", "y_mm", "safe_z_mm", "depth_z_mm"});
            motion::plates::Station st;
            st.id = s.string("id", true).value_or("");
            st.name = s.string("name", false).value_or("");
            st.xMm = s.number("x_mm", true, -kDeckBig, kDeckBig).value_or(0);
            st.yMm = s.number("y_mm", true, -kDeckBig, kDeckBig).value_or(0);
            st.safeZMm = s.number("safe_z_mm", true, -kDeckBig, kDeckBig).value_or(0);
            st.depthZMm = s.number("depth_z_mm", true, -kDeckBig, kDeckBig).value_or(0);
            d.stations.push_back(st);
        }
    }
    if (!r.problems.empty())
        return r;
    for (const motion::msg::Problem& p : motion::plates::validateDeck(d))
        r.problems.add(positionOfPath(root, p.path), p.path, p.message);
    if (r.problems.empty())
        r.deck = std::move(d);
    return r;
}

std::string writeDeck(const motion::plates::Deck& d)
{
    Value v = dev::files::json::schemaObject(kDeckSchema, kDeckVersion);
    v.set("id", d.id);
    v.set("name", d.name);
    v.set("travel_x_mm", d.travelXMm);
    v.set("travel_y_mm", d.travelYMm);
    v.set("travel_z_mm", d.travelZMm);
    v.set("table_z_mm", d.tableZMm);
    v.set("syringe_ul", d.syringeUl);
    v.set("move_overhead_s", d.moveOverheadS);
    Value axes = Value::object();
    axes.set("X", axisJson(d.x));
    axes.set("Y", axisJson(d.y));
    axes.set("Z", axisJson(d.z));
    axes.set("P", axisJson(d.p));
    v.set("axes", std::move(axes));
    Value slotList = Value::array();
    for (const motion::plates::Slot& s : d.plateSlots) {
        Value x = Value::object();
        x.set("id", s.id);
        x.set("name", s.name);
        x.set("origin_x_mm", s.originXMm);
        x.set("origin_y_mm", s.originYMm);
        x.set("rotation_deg", s.rotationDeg);
        slotList.push(std::move(x));
    }
    v.set("slots", std::move(slotList));
    Value stations = Value::array();
    for (const motion::plates::Station& s : d.stations) {
        Value x = Value::object();
        x.set("id", s.id);
        x.set("name", s.name);
        x.set("x_mm", s.xMm);
        x.set("y_mm", s.yMm);
        x.set("safe_z_mm", s.safeZMm);
        x.set("depth_z_mm", s.depthZMm);
        stations.push(std::move(x));
    }
    v.set("stations", std::move(stations));
    return dev::files::json::write(v);
}

motion::plates::Deck builtinDeck()
{
    DeckRead r = parseDeck(builtinDeckText());
    return r.deck ? *r.deck : motion::plates::Deck{};
}

} // namespace dev::files::plates
