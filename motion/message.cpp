#include "motion/message.h"

#include <cmath>
#include <cstdio>

namespace motion::msg {

namespace {

const char* unitSymbol(Unit u)
{
    switch (u) {
    case Unit::None:
    case Unit::Count: return "";
    case Unit::Mm: return " mm";
    case Unit::Um: return " µm";
    case Unit::Nm: return " nm";
    case Unit::MmPerS: return " mm/s";
    case Unit::MmPerS2: return " mm/s²";
    case Unit::MmPerS3: return " mm/s³";
    case Unit::MmPerMin: return " mm/min";
    case Unit::Ul: return " µL";
    case Unit::UlPerS: return " µL/s";
    case Unit::S: return " s";
    case Unit::Ms: return " ms";
    case Unit::Us: return " µs";
    case Unit::Hz: return " Hz";
    case Unit::Percent: return " %";
    case Unit::Deg: return "°";
    case Unit::Rad: return " rad";
    case Unit::PerS: return " 1/s";
    case Unit::Baud: return " Bd";
    case Unit::Byte: return " B";
    }
    return "";
}

std::string valueString(const Arg& a)
{
    struct Visit {
        const Arg& arg;
        std::string operator()(std::monostate) const { return "(none)"; }
        std::string operator()(long long v) const { return std::to_string(v) + unitSymbol(arg.unit); }
        std::string operator()(double v) const
        {
            char buf[40];
            std::snprintf(buf, sizeof buf, "%.6g", v);
            return buf + std::string(unitSymbol(arg.unit));
        }
        std::string operator()(const Verbatim& v) const { return "\"" + v.text + "\""; }
        std::string operator()(const Term& t) const { return "term:" + t.id; }
        std::string operator()(const std::shared_ptr<const Message>& m) const { return m ? debugString(*m) : "(null)"; }
    };
    return std::visit(Visit{a}, a.value);
}

bool sameValue(const Arg& a, const Arg& b)
{
    if (a.value.index() != b.value.index() || a.unit != b.unit || a.name != b.name)
        return false;
    if (auto* x = std::get_if<long long>(&a.value))
        return *x == std::get<long long>(b.value);
    if (auto* x = std::get_if<double>(&a.value)) {
        const double y = std::get<double>(b.value);
        return *x == y || (std::isnan(*x) && std::isnan(y));
    }
    if (auto* x = std::get_if<Verbatim>(&a.value))
        return x->text == std::get<Verbatim>(b.value).text;
    if (auto* x = std::get_if<Term>(&a.value))
        return x->id == std::get<Term>(b.value).id;
    if (auto* x = std::get_if<std::shared_ptr<const Message>>(&a.value)) {
        const auto& y = std::get<std::shared_ptr<const Message>>(b.value);
        return (!*x && !y) || (*x && y && **x == *y);
    }
    return true;  // both monostate
}

} // namespace

const Arg* Message::arg(const std::string& name) const
{
    for (const Arg& a : args)
        if (a.name == name)
            return &a;
    return nullptr;
}

double Message::number(const std::string& name, double fallback) const
{
    const Arg* a = arg(name);
    if (!a)
        return fallback;
    if (auto* d = std::get_if<double>(&a->value))
        return *d;
    if (auto* i = std::get_if<long long>(&a->value))
        return static_cast<double>(*i);
    return fallback;
}

long long Message::integer(const std::string& name, long long fallback) const
{
    const Arg* a = arg(name);
    if (!a)
        return fallback;
    if (auto* i = std::get_if<long long>(&a->value))
        return *i;
    return fallback;
}

std::string Message::text(const std::string& name) const
{
    const Arg* a = arg(name);
    if (!a)
        return {};
    if (auto* v = std::get_if<Verbatim>(&a->value))
        return v->text;
    if (auto* t = std::get_if<Term>(&a->value))
        return t->id;
    return {};
}

Arg real(std::string name, double value, Unit unit) { return Arg{std::move(name), value, unit}; }
Arg integer(std::string name, long long value, Unit unit) { return Arg{std::move(name), value, unit}; }
Arg verbatim(std::string name, std::string text) { return Arg{std::move(name), Verbatim{std::move(text)}, Unit::None}; }
Arg term(std::string name, std::string id) { return Arg{std::move(name), Term{std::move(id)}, Unit::None}; }
Arg nested(std::string name, Message inner)
{
    return Arg{std::move(name), std::make_shared<const Message>(std::move(inner)), Unit::None};
}

Message make(std::string id, std::initializer_list<Arg> args) { return Message{std::move(id), std::vector<Arg>(args)}; }
Message make(std::string id, std::vector<Arg> args) { return Message{std::move(id), std::move(args)}; }

std::string debugString(const Message& m)
{
    std::string out = m.id + "{";
    for (std::size_t i = 0; i < m.args.size(); ++i) {
        if (i)
            out += ", ";
        out += m.args[i].name + "=" + valueString(m.args[i]);
    }
    return out + "}";
}

bool operator==(const Message& a, const Message& b)
{
    if (a.id != b.id || a.args.size() != b.args.size())
        return false;
    for (std::size_t i = 0; i < a.args.size(); ++i)
        if (!sameValue(a.args[i], b.args[i]))
            return false;
    return true;
}

} // namespace motion::msg
