#pragma once
// A scripted GRBL on the far end of a transport, for transcript tests of the GRBL client: it
// answers the handshake ($I, $$, $#) and '?' from canned text, answers every other line from a
// queue the test fills (ok by default), and lets the test push any line at any moment — a
// report with every field, an error mid-stream, a banner after a reset, garbage, half a line.
#include "device/link/transport.h"

#include <QTimer>

#include <deque>
#include <functional>
#include <string>
#include <vector>

namespace itest {

class ScriptedGrbl final : public dev::Transport {
public:
    explicit ScriptedGrbl(QObject* parent = nullptr) : dev::Transport(parent) {}

    // What it answers.
    bool silent = false;                  ///< answers nothing at all (a board that never answers)
    std::string banner = "Grbl 1.1h ['$' for help]";
    std::string buildInfo = "[VER:1.1h.20190830:]\r\n[OPT:VZ,15,128]\r\n";
    std::string settings = "$10=1\r\n$11=0.010\r\n$12=0.002\r\n$13=0\r\n$20=1\r\n$21=0\r\n$22=1\r\n$23=7\r\n$27=1.000\r\n"
                           "$100=400.000\r\n$101=400.000\r\n$102=400.000\r\n$110=1200.000\r\n$111=1200.000\r\n$112=600.000\r\n"
                           "$120=200.000\r\n$121=200.000\r\n$122=100.000\r\n$130=100.000\r\n$131=100.000\r\n$132=50.000\r\n";
    std::string offsets = "[G54:0.000,0.000,0.000]\r\n[G92:0.000,0.000,0.000]\r\n[TLO:0.000]\r\n";
    std::string report = "<Idle|MPos:0.000,0.000,0.000|FS:0,0|WCO:0.000,0.000,0.000>";
    /// Answers for lines other than the handshake, in order; "ok" once it runs dry.
    std::deque<std::string> answers;
    /// Lines the client sent (without '\n'), and its realtime bytes.
    std::vector<std::string> lines;
    std::string realtime;
    /// Called for each line before it is answered; return true to leave it unanswered.
    std::function<bool(const std::string&)> hold;

    void open() override
    {
        QTimer::singleShot(0, this, [this] {
            m_open = true;
            emit opened();
        });
    }
    void close() override { m_open = false; }
    bool isOpen() const override { return m_open; }
    QString describe() const override { return QStringLiteral("scripted GRBL"); }

    void write(const QByteArray& bytes) override
    {
        if (!m_open)
            return;
        for (const char c : bytes) {
            const auto b = static_cast<unsigned char>(c);
            if (b == '?' || b == '!' || b == '~' || b == 0x18 || b >= 0x80) {
                realtime.push_back(c);
                if (!silent && b == '?')
                    push(report);
                continue;
            }
            if (c == '\n') {
                const std::string line = m_line;
                m_line.clear();
                lines.push_back(line);
                answer(line);
                continue;
            }
            m_line.push_back(c);
        }
    }

    /// Sends text as if the controller had ("\r\n" added).
    void push(const std::string& line) { pushRaw(line + "\r\n"); }
    void pushRaw(const std::string& bytes)
    {
        if (!m_open)
            return;
        const QByteArray b(bytes.data(), static_cast<qsizetype>(bytes.size()));
        QTimer::singleShot(0, this, [this, b] {
            if (m_open)
                emit bytesReceived(b);
        });
    }

private:
    void answer(const std::string& line)
    {
        if (silent || (hold && hold(line)))
            return;
        if (line == "$I")
            return pushRaw(buildInfo + "ok\r\n");
        if (line == "$$")
            return pushRaw(settings + "ok\r\n");
        if (line == "$#")
            return pushRaw(offsets + "ok\r\n");
        if (line == "$G")
            return pushRaw("[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]\r\nok\r\n");
        if (line.empty() || line == "G54 G17 G94")
            return push("ok");  // the client's sync line and its modal preamble
        if (answers.empty())
            return push("ok");
        push(answers.front());
        answers.pop_front();
    }

    bool m_open = false;
    std::string m_line;
};

} // namespace itest
