// Fuzz target "grbl_lines": what a GRBL or grblHAL controller sends, read by the GRBL
// backend's parsers (device/backends/grbl/). A transcript is not a file people keep, but it is
// text from outside whose mutations the file driver's engine makes well: lines deleted,
// repeated, truncated, spliced, bytes changed.
// Invariants: nothing crashes or hangs; the line reader never holds more than its bound and
// gives the same lines whatever the chunking; every line classifies; an accepted status report
// has 3–6 axes of finite numbers and a known state, and the tracker's vectors agree in length;
// build info never yields a zero or absurd buffer size; settings never yield limits ≤ 0.
#include "fuzz_files.h"

#include "device/backends/grbl/grbl_build_info.h"
#include "device/backends/grbl/grbl_lines.h"
#include "device/backends/grbl/grbl_settings.h"
#include "device/backends/grbl/grbl_status.h"

#include <cmath>

namespace {

std::vector<std::string> seeds()
{
    return {
        "\r\nGrbl 1.1h ['$' for help]\r\n[MSG:'$H'|'$X' to unlock]\r\nok\r\n<Alarm|MPos:0.000,0.000,0.000|FS:0,0|WCO:0.000,0.000,0.000>\r\n",
        "[VER:1.1h.20190830:]\r\n[OPT:V,15,128]\r\nok\r\n$0=10\r\n$10=1\r\n$13=0\r\n$20=1\r\n$22=1\r\n$110=500.000\r\n$111=500.000\r\n"
        "$112=500.000\r\n$120=10.000\r\n$121=10.000\r\n$122=10.000\r\n$130=200.000\r\n$131=200.000\r\n$132=200.000\r\nok\r\n",
        "<Hold:1|WPos:-2.500,0.000,11.000|A:SFM|Ov:120,50,100|Pn:XZP|FS:1500.5,8000|Ln:99999|Bf:15,128|WCO:0.000,1.551,5.664>\r\n"
        "<Run|MPos:1.000,2.000,3.000|FS:600,0>\r\nok\r\nok\r\nerror:22\r\n<Jog|MPos:1,2,3,4,5,6|F:0>\r\n",
        "GrblHAL 1.1f ['$' or '$HELP' for help]\r\n[VER:1.1f.20231210:]\r\n[OPT:VNMZHSL,35,1024,3,0]\r\n[AXS:3:XYZ]\r\n"
        "[NEWOPT:ENUMS,RT+,HOME,SED]\r\n[FIRMWARE:grblHAL]\r\n[DRIVER:STM32F401CC]\r\nok\r\n"
        "<Idle|MPos:10.000,20.000,-1.000|Bf:35,1023|FS:0,0,0|Pn:PXY|WCO:0.000,0.000,0.000|WCS:G54|Ov:100,100,100|A:|H:1,7|FW:grblHAL>\r\n",
        "ok\r\n<Run|MPos:1.0ALARM:3\r\n\r\nGrbl 1.1h ['$' for help]\r\n[MSG:'$H'|'$X' to unlock]\r\n[PRB:0.000,0.000,-1.250:1]\r\n"
        "[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]\r\n>G54G20:ok\r\n$N0=\r\n[echo:G1X0.540Y10.4F100]\r\n",
    };
}

void checkLine(const std::string& text, dev::grbl::StatusTracker& tracker, dev::grbl::BuildInfo& info, dev::grbl::Settings& settings)
{
    const dev::grbl::Line l = dev::grbl::classifyLine(text);
    if ((l.kind == dev::grbl::LineKind::Error || l.kind == dev::grbl::LineKind::Alarm) && (l.code < 0 || l.code > 999))
        fuzzfiles::fail("a code out of range: " + text);
    if (l.kind == dev::grbl::LineKind::Status) {
        const dev::grbl::StatusParse p = dev::grbl::parseStatusReport(l.payload);
        if (!p.report) {
            if (p.problem.id != "grbl.status.malformed")
                fuzzfiles::fail("a refused report without its reason");
            return;
        }
        const auto& r = *p.report;
        if (r.position.size() < dev::grbl::kMinStatusAxes || r.position.size() > dev::grbl::kMaxStatusAxes
            || r.state == dev::grbl::MachineState::Unknown)
            fuzzfiles::fail("an accepted report with a bad shape: " + text);
        for (const double v : r.position)
            if (!std::isfinite(v))
                fuzzfiles::fail("a non-finite position: " + text);
        if (tracker.update(r)) {
            if (!tracker.machineMm().empty() && !tracker.workMm().empty() && tracker.machineMm().size() != tracker.workMm().size())
                fuzzfiles::fail("machine and work vectors disagree in length");
            if (tracker.haveWorkOffset() && tracker.workOffsetMm().size() != r.position.size())
                fuzzfiles::fail("a work offset of another axis count was kept");
        }
    }
    dev::grbl::addBuildInfoLine(info, l);
    if (info.rxBufferBytes == 0 || info.rxBufferBytes > 65536 || info.plannerBlocks == 0)
        fuzzfiles::fail("an absurd buffer size was believed: " + text);
    if (l.kind == dev::grbl::LineKind::Setting)
        if (const auto s = dev::grbl::parseSettingLine(text))
            settings.add(*s);
    if (l.kind == dev::grbl::LineKind::Probe)
        dev::grbl::parseProbeLine(l.payload);
    dev::grbl::parseBanner(text);
}

void check(std::string_view input)
{
    // Whole, then in chunks of every size from 1 to 7: the same lines either way.
    dev::grbl::LineReader whole;
    std::vector<dev::grbl::LineReader::Line> a;
    whole.feed(input, a);
    if (whole.partial().size() > dev::grbl::LineReader::kMaxLineBytes)
        fuzzfiles::fail("the line reader grew past its bound");
    dev::grbl::LineReader chunked;
    std::vector<dev::grbl::LineReader::Line> b;
    const std::size_t step = 1 + input.size() % 7;
    for (std::size_t i = 0; i < input.size(); i += step)
        chunked.feed(input.substr(i, step), b);
    if (a.size() != b.size())
        fuzzfiles::fail("chunking changed the number of lines");
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        if (a[i].text != b[i].text || a[i].truncated != b[i].truncated)
            fuzzfiles::fail("chunking changed a line");

    dev::grbl::StatusTracker tracker;
    dev::grbl::BuildInfo info;
    dev::grbl::Settings settings;
    for (const auto& line : a) {
        if (line.text.size() > dev::grbl::LineReader::kMaxLineBytes)
            fuzzfiles::fail("a line longer than the reader's bound");
        checkLine(line.text, tracker, info, settings);
    }
    const dev::grbl::LimitsRead limits = dev::grbl::machineLimits(settings, info.axisLetters);
    if (limits.limits)
        for (const auto& ax : limits.limits->axes)
            if (!(ax.maxRateMmS > 0) || !(ax.accelMmS2 > 0) || !(ax.maxTravelMm > 0))
                fuzzfiles::fail("limits at or below zero were accepted");
}

} // namespace

BP_FUZZ_FILE_TARGET({"grbl_lines", seeds, check});
