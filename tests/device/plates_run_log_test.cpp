// The run log: what a resume trusts. Each op's state from its lines, a torn last
// line after a crash, and the lines that make a log untrustworthy.
#include "device/english_words.h"
#include "device/files/recipes/run_log.h"
#include "device/files/recipes/run_log_writer.h"
#include "device/files/text_file.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace dev::files::plates;

namespace {
const char* kHeader = R"({"schema":"benchpilot.run-log","version":1,"event":"run","recipe":"r","fingerprint":"00ff","ops":4,"time":"t"})";
std::string log(std::initializer_list<const char*> lines)
{
    std::string s = std::string(kHeader) + "\n";
    for (const char* l : lines)
        s += std::string(l) + "\n";
    return s;
}
} // namespace

TEST(PlateRunLog, EachOpsStateComesFromItsLines)
{
    const RunLogState st = readRunLog(log({
        R"({"event":"start","op":0,"kind":"aspirate","plate":"p","well":"A1","volume_ul":10})",
        R"({"event":"pump","op":0,"p_ul":0})",
        R"({"event":"done","op":0,"p_ul":10})",
        R"({"event":"start","op":1,"kind":"aspirate","plate":"p","well":"A2","volume_ul":10})",
        R"({"event":"pump","op":1,"p_ul":10})",
        R"({"event":"done","op":1,"p_ul":20})",
        R"({"event":"start","op":2,"kind":"aspirate","plate":"p","well":"A3","volume_ul":10})",
        R"({"event":"pump","op":2,"p_ul":20})",
    }));
    ASSERT_TRUE(st.problems.empty()) << i18ntest::englishFormat(st.problems, "run.jsonl");
    EXPECT_EQ(st.fingerprint, "00ff");
    EXPECT_EQ(st.opCount, 4);
    EXPECT_EQ(st.ops[0].state, OpState::Done);
    EXPECT_EQ(st.ops[1].state, OpState::Done);
    EXPECT_EQ(st.ops[2].state, OpState::Interrupted);
    EXPECT_EQ(st.ops[2].well, "A3");
    EXPECT_DOUBLE_EQ(*st.ops[2].pumpStartUl, 20);
    EXPECT_EQ(st.ops[3].state, OpState::NotStarted);
    EXPECT_EQ(st.doneCount(), 2);
    EXPECT_EQ(st.firstOpenOp(), 2);
    EXPECT_DOUBLE_EQ(*st.lastPumpUl, 20);
    EXPECT_FALSE(st.finished);
}

TEST(PlateRunLog, AStartWithoutPumpMovedNoLiquid)
{
    const RunLogState st = readRunLog(log({R"({"event":"start","op":0,"kind":"dispense","well":"A1"})"}));
    EXPECT_EQ(st.ops[0].state, OpState::Started);
}

TEST(PlateRunLog, ATornLastLineIsACrashMidWriteNotAnError)
{
    std::string text = log({R"({"event":"start","op":0,"kind":"aspirate","well":"A1"})", R"({"event":"pump","op":0,"p_ul":0})"});
    text += R"({"event":"done","op":0,"p_)";  // SIGKILL mid-write
    const RunLogState st = readRunLog(text);
    EXPECT_TRUE(st.problems.empty()) << i18ntest::englishFormat(st.problems, "run.jsonl");
    EXPECT_TRUE(st.tornTail);
    EXPECT_EQ(st.ops[0].state, OpState::Interrupted);
}

TEST(PlateRunLog, AnOpDoneTwiceMakesTheLogUntrustworthy)
{
    const RunLogState st = readRunLog(log({
        R"({"event":"start","op":0,"kind":"aspirate","well":"A1"})",
        R"({"event":"done","op":0,"p_ul":10})",
        R"({"event":"start","op":0,"kind":"aspirate","well":"A1"})",
    }));
    ASSERT_FALSE(st.problems.empty());
    EXPECT_NE(i18ntest::englishFormat(st.problems, "run.jsonl").find("run.jsonl:4:1: op: op 0 starts again after it was done"), std::string::npos)
        << i18ntest::englishFormat(st.problems, "run.jsonl");
}

TEST(PlateRunLog, SkipAndRedoAreTheOperatorsDecisions)
{
    const RunLogState st = readRunLog(log({
        R"({"event":"start","op":0,"kind":"dispense","well":"A1"})",
        R"({"event":"pump","op":0,"p_ul":100})",
        R"({"event":"stop","reason":"link lost"})",
        R"({"event":"resume"})",
        R"({"event":"skip","op":0,"p_ul":90,"reason":"operator"})",
        R"({"event":"start","op":1,"kind":"dispense","well":"A2"})",
        R"({"event":"pump","op":1,"p_ul":90})",
        R"({"event":"stop","reason":"aborted"})",
        R"({"event":"resume"})",
        R"({"event":"redo","op":1,"reason":"operator"})",
        R"({"event":"start","op":1,"kind":"dispense","well":"A2"})",
    }));
    ASSERT_TRUE(st.problems.empty()) << i18ntest::englishFormat(st.problems, "run.jsonl");
    EXPECT_EQ(st.ops[0].state, OpState::Skipped);
    EXPECT_EQ(st.ops[1].state, OpState::Started);
    EXPECT_EQ(st.ops[1].starts, 2);
    EXPECT_EQ(st.runs, 3);
    EXPECT_EQ(st.lastStop, "aborted");
    EXPECT_DOUBLE_EQ(*st.lastPumpUl, 90);
}

TEST(PlateRunLog, WhatIsNotARunLogIsRefused)
{
    EXPECT_FALSE(readRunLog("").problems.empty());
    EXPECT_FALSE(readRunLog("{\"event\":\"start\",\"op\":0}\n").problems.empty());
    EXPECT_FALSE(readRunLog(log({R"({"event":"start","op":9})"})).problems.empty()) << "op beyond the header's count";
    EXPECT_FALSE(readRunLog(log({R"({"event":"launch"})"})).problems.empty());
    EXPECT_FALSE(readRunLog(log({"not json", R"({"event":"resume"})"})).problems.empty()) << "a bad line that is not the last";
}

TEST(PlateRunLog, TheWriterAppendsSyncedLinesAndNeverOverwrites)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("run.jsonl"));
    {
        RunLogWriter w;
        motion::msg::Message error;
        ASSERT_TRUE(w.create(path, &error)) << error;
        dev::files::json::Value head = dev::files::json::schemaObject(kRunLogSchema, kRunLogVersion);
        head.set("event", "run");
        head.set("fingerprint", "ab");
        head.set("ops", 2);
        ASSERT_TRUE(w.write(head));
        dev::files::json::Value start = dev::files::json::Value::object();
        start.set("event", "start");
        start.set("op", 0);
        ASSERT_TRUE(w.write(start));
    }
    RunLogWriter again;
    motion::msg::Message error;
    EXPECT_FALSE(again.create(path, &error)) << "a log is a record: never overwritten";
    ASSERT_TRUE(again.append(path, &error));
    dev::files::json::Value resume = dev::files::json::Value::object();
    resume.set("event", "resume");
    ASSERT_TRUE(again.write(resume));
    std::string text;
    ASSERT_TRUE(dev::files::readText(path, &text, &error));
    const RunLogState st = readRunLog(text);
    EXPECT_TRUE(st.problems.empty()) << i18ntest::englishFormat(st.problems, "run.jsonl");
    EXPECT_EQ(st.ops[0].state, OpState::Started);
    EXPECT_EQ(st.runs, 2);
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3);
    EXPECT_NE(text.find("\"time\":\""), std::string::npos);
}
