#include "device/camera/camera_source.h"

namespace dev::camera {

namespace {
bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
} // namespace

bool parseSource(const std::string& text, SourceSpec* spec, msg::Message* error)
{
    struct Prefix {
        const char* word;
        SourceKind kind;
        bool needsArgument;
    };
    static const Prefix kPrefixes[] = {{"sim", SourceKind::Sim, false},         {"uvc", SourceKind::Uvc, false},
                                       {"command", SourceKind::Command, true}, {"folder", SourceKind::Folder, true}};
    for (const Prefix& p : kPrefixes) {
        const std::string word = p.word;
        if (text == word || startsWith(text, (word + ":").c_str())) {
            spec->kind = p.kind;
            spec->argument = text.size() > word.size() ? text.substr(word.size() + 1) : std::string();
            if (p.kind == SourceKind::Sim && !spec->argument.empty())
                spec->kind = SourceKind::SimSocket;
            if (p.needsArgument && spec->argument.find_first_not_of(' ') == std::string::npos) {
                *error = msg::make("camera.source.needs_argument", {msg::verbatim("source", text), msg::verbatim("kind", word)});
                return false;
            }
            return true;
        }
    }
    *error = msg::make("camera.source.unknown", {msg::verbatim("source", text)});
    return false;
}

std::unique_ptr<Camera> makeCamera(const std::string& text, const SimContext& sim, msg::Message* error, QObject* parent)
{
    SourceSpec spec;
    if (!parseSource(text, &spec, error))
        return nullptr;
    switch (spec.kind) {
    case SourceKind::Sim:
        if (!sim.workPoint) {
            *error = msg::make("camera.sim.needs_simulator");
            return nullptr;
        }
        return std::make_unique<SimCamera>(sim.workPoint, sim.settings, parent);
    case SourceKind::SimSocket:
    case SourceKind::Uvc:
    case SourceKind::Command:
    case SourceKind::Folder:
        break;
    }
    *error = msg::make("camera.source.not_available", {msg::verbatim("source", text)});
    return nullptr;
}

} // namespace dev::camera
