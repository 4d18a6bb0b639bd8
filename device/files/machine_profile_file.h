#pragma once
// Machine profiles (docs/grbl.md, "The machine profile"): how one connection's controller is
// wired to an instrument — which GRBL axis is which instrument axis, the plunger pump as an
// axis with its µL per mm, the output a camera trigger is wired to, how often to poll status,
// what to do with inch reports, and the figures the continuous-jog promise rests on. JSON with
// "schema": "benchpilot.machine-profile", "version": 1. Reading reports every problem at once
// (each with its line, column and field). The text functions are plain C++ (fuzzed); the file
// functions add the atomic write and the size-capped read.
//
// A connection without a profile gets defaultProfile(kind): the instrument's axes on GRBL's
// axes of the same letter, the analyzer's pump on A at 1 µL per mm (the simulator's wiring),
// no trigger, 10 Hz status polls.
#include "device/files/json_fields.h"
#include "device/protocol/messages.h"
#include "motion/problem.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::files {

constexpr std::string_view kMachineProfileSchema = "benchpilot.machine-profile";
constexpr int kMachineProfileVersion = 1;
/// Machine profiles are named NAME.machine.json.
constexpr std::string_view kMachineProfileSuffix = ".machine.json";

struct MachineProfile {
    /// Which protocol the port speaks: detect it (a BenchPilot HELLO or a GRBL banner), or
    /// say it (a GRBL board that resets slowly, or a port where probing is unwelcome).
    enum class Protocol { Auto, BenchPilot, Grbl };
    enum class TriggerOutput {
        GrblHalDigital,  ///< M64/M65 P<port> (grblHAL's auxiliary digital outputs)
        CoolantFlood,    ///< M8/M9: stock GRBL's only spare output
    };
    enum class InchReports {
        Convert,  ///< $13=1: reports are multiplied by 25.4 (settings are mm anyway)
        Refuse,   ///< $13=1 refuses the connection until the controller reports mm
    };
    struct AxisMap {
        char axis = 'X';      ///< the instrument's axis: X, Y or Z
        char grblAxis = 'X';  ///< the controller's axis letter: X, Y, Z, A, B or C
    };
    struct Pump {
        char grblAxis = 'A';
        double ulPerMm = 1.0;  ///< µL the plunger displaces per "mm" the controller moves its axis
    };
    struct Trigger {
        TriggerOutput output = TriggerOutput::GrblHalDigital;
        int port = 0;  ///< grblHAL digital output number (M64 P<port>)
    };
    struct Jog {
        double linkLatencyS = 0.02;   ///< host write → controller acts (USB serial: a few ms; 20 ms is generous)
        double refreshS = 0.05;       ///< how often the host tops the jog queue up
        double stopBudgetS = 0.25;    ///< release → at rest, and the most a lost host may overrun
    };

    std::string name;
    dev::proto::DeviceKind instrument = dev::proto::DeviceKind::Analyzer;
    Protocol protocol = Protocol::Auto;
    double statusPollHz = 10;     ///< '?' queries per second (the GRBL document: 5 Hz, 10 may work)
    std::vector<AxisMap> axes;    ///< in the instrument's order
    std::optional<Pump> pump;     ///< the analyzer's P axis
    std::optional<Trigger> trigger;
    InchReports inchReports = InchReports::Convert;
    Jog jog;

    /// The controller axis behind instrument axis `axis` ('P' is the pump); 0 when unmapped.
    char grblAxisOf(char axis) const;
};

/// The profile a connection uses when none is chosen.
MachineProfile defaultProfile(dev::proto::DeviceKind kind);

/// Rules a profile keeps whatever file it came from; each problem names its field
/// (grbl.profile.*, or file.json.out_of_range{value, min, max}).
motion::msg::Problems validate(const MachineProfile& p);

struct MachineProfileReadResult {
    std::optional<MachineProfile> profile;
    dev::files::json::Problems problems;  ///< empty when profile is set
};
MachineProfileReadResult parseMachineProfile(std::string_view text);
/// Two-space indented JSON: the header, then every field.
std::string writeMachineProfile(const MachineProfile& p);

/// False with every problem in *problems (ui::words::fileProblems words them with the file's name).
bool loadMachineProfileFile(const QString& path, MachineProfile* profile, dev::files::json::Problems* problems);
bool saveMachineProfileFile(const QString& path, const MachineProfile& profile, motion::msg::Message* error);

const char* protocolName(MachineProfile::Protocol p);  ///< "auto", "benchpilot", "grbl"
const char* triggerOutputName(MachineProfile::TriggerOutput t);  ///< "grblhal-digital", "coolant-flood"

} // namespace dev::files
