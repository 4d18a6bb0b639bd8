#pragma once
// What the GRBL simulator tests share: a host that talks to dev::sim::GrblFirmware in-process the
// way a serial host would (bytes in, lines out), on the firmware's virtual clock.
#include "device/backends/grbl/grbl_lines.h"
#include "device/backends/grbl/grbl_status.h"
#include "device/sim/grbl_firmware.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace grbltest {

struct Host {
    dev::sim::GrblFirmware fw;
    dev::grbl::LineReader reader;
    std::vector<std::string> lines;  ///< every line received, in order
    std::size_t seen = 0;            ///< lines already handed out by fresh()

    explicit Host(const dev::sim::MachineConfig& c = dev::sim::analyzerConfig(),
                  dev::sim::GrblFirmware::Dialect d = dev::sim::GrblFirmware::Dialect::Grbl)
        : fw(c, d)
    {
        pump();
    }

    void write(const std::string& bytes)
    {
        fw.receive(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    }
    void pump()
    {
        std::vector<std::uint8_t> out;
        fw.drainOutput(out);
        std::vector<dev::grbl::LineReader::Line> got;
        reader.feed(std::string_view(reinterpret_cast<const char*>(out.data()), out.size()), got);
        for (auto& l : got)
            lines.push_back(std::move(l.text));
    }
    double now() const { return fw.machine().timeS(); }
    /// Runs `seconds` of machine time in 1 ms steps, calling `each` after every step.
    void run(double seconds, const std::function<void()>& each = {})
    {
        for (double t = 0; t < seconds - 1e-9; t += 0.001) {
            fw.advance(0.001);
            pump();
            if (each)
                each();
        }
    }
    /// Runs until `done` or `limitS` passes; true if `done` came.
    bool runUntil(const std::function<bool()>& done, double limitS)
    {
        for (double t = 0; t < limitS; t += 0.001) {
            if (done())
                return true;
            fw.advance(0.001);
            pump();
        }
        return done();
    }
    /// Lines received since the last call.
    std::vector<std::string> fresh()
    {
        std::vector<std::string> out(lines.begin() + static_cast<std::ptrdiff_t>(seen), lines.end());
        seen = lines.size();
        return out;
    }
    /// Sends one line and waits for its ok / error:N (every line before it answered first).
    std::string command(const std::string& line, double limitS = 60)
    {
        fresh();
        write(line + "\n");
        std::string answer;
        runUntil(
            [&] {
                for (std::size_t i = seen; i < lines.size(); ++i) {
                    const auto k = dev::grbl::classifyLine(lines[i]).kind;
                    if (k == dev::grbl::LineKind::Ok || k == dev::grbl::LineKind::Error) {
                        answer = lines[i];
                        return true;
                    }
                }
                return false;
            },
            limitS);
        return answer;
    }
    /// Asks for a status report and parses it.
    dev::grbl::StatusReport status()
    {
        const std::size_t before = lines.size();
        write("?");
        run(0.001);
        for (std::size_t i = lines.size(); i-- > before;) {
            const dev::grbl::Line l = dev::grbl::classifyLine(lines[i]);
            if (l.kind == dev::grbl::LineKind::Status) {
                const auto p = dev::grbl::parseStatusReport(l.payload);
                EXPECT_TRUE(p.report) << lines[i];
                if (p.report)
                    return *p.report;
            }
        }
        return {};
    }
    bool received(const std::string& line) const
    {
        for (const auto& l : lines)
            if (l == line)
                return true;
        return false;
    }
    /// Unlocks (power-up alarm) and homes, so machine position 0 is at the switches.
    void home()
    {
        ASSERT_EQ(command("$H"), "ok");
        ASSERT_EQ(fw.state(), dev::sim::GrblFirmware::State::Idle);
    }
};

} // namespace grbltest
