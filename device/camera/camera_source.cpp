#include "device/camera/camera_source.h"

#include "device/camera/command_camera.h"
#include "device/camera/folder_camera.h"
#include "device/camera/sim_socket_camera.h"
#if BP_WITH_UVC
#include "device/camera/uvc_camera.h"
#endif

namespace dev::camera {

namespace {
bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
} // namespace

bool parseSource(const std::string& text, SourceSpec* spec, motion::msg::Message* error)
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
                *error = motion::msg::make("camera.source.needs_argument", {motion::msg::verbatim("source", text), motion::msg::verbatim("kind", word)});
                return false;
            }
            return true;
        }
    }
    *error = motion::msg::make("camera.source.unknown", {motion::msg::verbatim("source", text)});
    return false;
}

std::unique_ptr<Camera> makeCamera(const std::string& text, const SimContext& sim, motion::msg::Message* error, QObject* parent)
{
    SourceSpec spec;
    if (!parseSource(text, &spec, error))
        return nullptr;
#if BP_WITH_UVC
    if (spec.kind == SourceKind::Uvc)
        return std::make_unique<UvcCamera>(QString::fromStdString(spec.argument), parent);
#endif
    switch (spec.kind) {
    case SourceKind::Sim:
        if (!sim.workPoint) {
            *error = motion::msg::make("camera.sim.needs_simulator");
            return nullptr;
        }
        return std::make_unique<SimCamera>(sim.workPoint, sim.settings, parent);
    case SourceKind::Command:
        return std::make_unique<CommandCamera>(QString::fromStdString(spec.argument), parent);
    case SourceKind::Folder:
        return std::make_unique<FolderCamera>(QString::fromStdString(spec.argument), parent);
    case SourceKind::SimSocket:
        return std::make_unique<SimSocketCamera>(QString::fromStdString(spec.argument), parent);
    case SourceKind::Uvc:
        break;
    }
    *error = motion::msg::make("camera.source.not_available", {motion::msg::verbatim("source", text)});
    return nullptr;
}

} // namespace dev::camera
