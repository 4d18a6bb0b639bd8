#pragma once
// Where "Set home here" was, per GRBL controller, between connections. A controller without
// homing knows no home of its own: the host takes the present position as home (G10 L20 P1) on
// the operator's word, and remembers here the G54 offset that gave and the machine position it
// last saw, so that the next connection to the same controller can tell whether it restarted
// since (a restart zeroes GRBL's machine position) and keep the home if it did not.
//
// This is the host's own state, not one of the files people keep: nobody edits, carries or
// shares it, and losing it costs only setting home again — the state every connection starts in
// without it. So anything it cannot read (no file, another schema or version, a damaged entry)
// counts as nothing remembered, silently; there is no reader that reports problems, and no
// format page beyond docs/grbl.md's paragraph. It is still JSON with a schema name and a
// version, written atomically, so a reader of a later version can tell it from its own.
#include <QString>

#include <optional>
#include <string>
#include <vector>

namespace dev {

struct GrblHome {
    std::string controller;         ///< the key: port, firmware and instrument (GrblClient::controllerKey)
    std::string axes;               ///< the controller's axis letters whose home was set here ("XY")
    std::vector<double> g54Mm;      ///< the G54 offset $# gave once the home was set, per controller axis
    std::vector<double> machineMm;  ///< the machine position last seen, per controller axis
};

class GrblHomeMemory {
public:
    static constexpr const char* kSchema = "benchpilot.grbl-homes";
    static constexpr int kVersion = 1;
    /// Controllers remembered at most; the oldest entry goes first.
    static constexpr std::size_t kMaxControllers = 32;

    explicit GrblHomeMemory(QString path) : m_path(std::move(path)) {}
    /// The host's state directory: $XDG_DATA_HOME/BenchPilot/grbl-homes.json (or the platform's like).
    static QString defaultPath();
    const QString& path() const { return m_path; }

    std::optional<GrblHome> recall(const std::string& controller) const;
    /// Replaces the controller's entry. False when the file cannot be written.
    bool remember(const GrblHome& home) const;
    bool forget(const std::string& controller) const;

    /// The file's text, and back; parse() drops whatever it cannot read.
    static std::string serialize(const std::vector<GrblHome>& homes);
    static std::vector<GrblHome> parse(const std::string& text);

private:
    std::vector<GrblHome> readAll() const;
    bool writeAll(const std::vector<GrblHome>& homes) const;

    QString m_path;
};

} // namespace dev
