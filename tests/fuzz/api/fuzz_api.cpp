// Fuzz driver for the scripting API's request reader (app/api/json_rpc.h) and the
// conversion of a call's params into a command's words (app/api/command_methods.h).
//
// Standalone (the default): `fuzz_api [--iterations N] [--seed S] [FILE...]` makes N
// deterministic inputs — valid request streams mutated by bit flips, truncation,
// splicing, garbage, deep nesting, huge and odd numbers, overlong lines — or replays
// FILEs, and exits 1 on the first violated invariant after writing the input to
// fuzz_api-failure.bin; `--corpus DIR` replays a kept corpus (tests/fuzz/corpus/api)
// before the generated inputs, `--emit DIR` writes the generated inputs out as seeds.
// Built with -DBP_LIBFUZZER=ON (clang; cmake/libfuzzer.cmake, docs/testing.md
// "Fuzzing") the same checks run as LLVMFuzzerTestOneInput.
//
// Invariants on every input:
//  - the line splitter gives the same lines fed whole, byte by byte or in random
//    chunks; no line is longer than 1 MiB; what it holds stays under 1 MiB; every
//    overlong line is reported once;
//  - every line reads to exactly one of: a call (an id that is a number, a string or
//    null, a non-empty method, object params), a notification (no id), or an error with
//    a JSON-RPC code (−32700, −32600, −32602) and a message — and reading it again gives
//    the same answer;
//  - the answer written for it is one line of JSON that reads back as a response;
//  - for a call to a command method, the params either convert to words or are refused
//    naming a field; converted words are options of that command ("--name" or
//    "--name=value", or after "--" the positional words), and converting again gives the
//    same words.
#include "app/api/command_methods.h"
#include "app/api/json_rpc.h"
#include "tests/fuzz/corpus_files.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>

#include <cinttypes>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace {

const QByteArray* g_input = nullptr;
std::uint64_t g_iteration = 0;
struct Coverage {
    std::uint64_t lines = 0, calls = 0, notifications = 0, invalid = 0, overlong = 0, converted = 0, refused = 0;
} g_cov;

[[noreturn]] void fail(const char* fmt, ...)
{
    std::fprintf(stderr, "fuzz_api: invariant violated (iteration %" PRIu64 "): ", g_iteration);
    va_list ap;
    va_start(ap, fmt);
    std::vfprintf(stderr, fmt, ap);
    va_end(ap);
    std::fputc('\n', stderr);
#ifdef BP_LIBFUZZER
    std::abort();  // libFuzzer saves the input itself
#else
    if (g_input)
        if (std::FILE* f = std::fopen("fuzz_api-failure.bin", "wb")) {
            std::fwrite(g_input->constData(), 1, static_cast<std::size_t>(g_input->size()), f);
            std::fclose(f);
            std::fprintf(stderr, "fuzz_api: input written to fuzz_api-failure.bin; replay with: fuzz_api fuzz_api-failure.bin\n");
        }
    std::exit(1);
#endif
}

#define CHECK(cond, ...)     \
    do {                     \
        if (!(cond))         \
            fail(__VA_ARGS__); \
    } while (0)

const QVector<app::api::CommandMethod>& methods()
{
    static const QVector<app::api::CommandMethod> m = app::api::commandMethods();
    return m;
}

QList<QByteArray> split(const QByteArray& bytes, const std::vector<int>& chunks, int* overlong)
{
    app::api::LineSplitter s;
    QList<QByteArray> lines;
    int from = 0;
    std::size_t k = 0;
    while (from < bytes.size()) {
        const int n = chunks.empty() ? static_cast<int>(bytes.size()) : std::max(1, chunks[k++ % chunks.size()]);
        s.feed(bytes.mid(from, n), [&](const QByteArray& l) { lines << l; }, [&] { ++*overlong; });
        CHECK(s.pending() <= app::api::kMaxLineBytes, "the splitter holds %d bytes", s.pending());
        from += n;
    }
    return lines;
}

void checkLine(const QByteArray& line)
{
    ++g_cov.lines;
    CHECK(line.size() <= app::api::kMaxLineBytes, "a line of %d bytes came through", static_cast<int>(line.size()));
    const app::api::Request r = app::api::readRequest(line);
    const app::api::Request again = app::api::readRequest(line);
    CHECK(r.kind == again.kind && r.errorCode == again.errorCode && r.method == again.method && r.id == again.id && r.params == again.params,
          "reading the same line twice gave two answers");
    QByteArray answer;
    switch (r.kind) {
    case app::api::Request::Kind::Invalid:
        ++g_cov.invalid;
        CHECK(r.errorCode == app::api::code::kParseError || r.errorCode == app::api::code::kInvalidRequest || r.errorCode == app::api::code::kInvalidParams,
              "error code %d", r.errorCode);
        CHECK(!r.errorMessage.isEmpty(), "an error without a message");
        CHECK(r.id.isNull() || r.id.isString() || r.id.isDouble(), "an invalid request answered with an id of another type");
        answer = app::api::errorLine(r.id, r.errorCode, r.errorMessage);
        break;
    case app::api::Request::Kind::Call:
        ++g_cov.calls;
        CHECK(r.id.isNull() || r.id.isString() || r.id.isDouble(), "a call's id is neither number, string nor null");
        [[fallthrough]];
    case app::api::Request::Kind::Notification:
        if (r.kind == app::api::Request::Kind::Notification)
            ++g_cov.notifications;
        CHECK(!r.method.isEmpty(), "a request without a method");
        answer = app::api::resultLine(r.id, QJsonObject{});
        if (const app::api::CommandMethod* m = app::api::findMethod(methods(), r.method)) {
            QStringList words, again2;
            bool positional = false, positional2 = false;
            app::api::ParamProblem problem, problem2;
            const bool ok = app::api::toWords(*m, r.params, &words, &positional, &problem);
            const bool ok2 = app::api::toWords(*m, r.params, &again2, &positional2, &problem2);
            CHECK(ok == ok2 && words == again2 && problem.field == problem2.field, "converting the same params twice differs");
            if (ok) {
                ++g_cov.converted;
                bool afterDashes = false;
                for (const QString& w : words) {
                    if (w == QLatin1String("--")) {
                        afterDashes = true;
                        continue;
                    }
                    if (afterDashes)
                        continue;
                    CHECK(w.startsWith(QLatin1String("--")), "an option word '%s' without --", qPrintable(w));
                    const QString name = w.mid(2).section(QLatin1Char('='), 0, 0);
                    bool known = name == QLatin1String("sim") || name == QLatin1String("instrument") || name == QLatin1String("timeout");
                    for (const auto& o : m->command->options)
                        known = known || o.names().contains(name);
                    CHECK(known, "'%s' is not an option of %s", qPrintable(name), qPrintable(m->method));
                }
                CHECK(positional == afterDashes, "positional words without their --");
            } else {
                ++g_cov.refused;
                CHECK(!problem.field.isEmpty() && !problem.message.isEmpty(), "params refused without naming the field");
            }
        }
        break;
    }
    CHECK(answer.endsWith('\n') && answer.count('\n') == 1, "an answer is not one line");
    const QJsonObject back = QJsonDocument::fromJson(answer).object();
    CHECK(back.value(QStringLiteral("jsonrpc")).toString() == QLatin1String("2.0"), "an answer that does not read back");
}

void checkInput(const QByteArray& bytes, std::mt19937_64& rng)
{
    g_input = &bytes;
    int overlongWhole = 0, overlongBytes = 0, overlongChunks = 0;
    const QList<QByteArray> whole = split(bytes, {}, &overlongWhole);
    std::vector<int> chunks;
    for (int i = 0; i < 16; ++i)
        chunks.push_back(static_cast<int>(rng() % 97) + 1);
    const QList<QByteArray> chunked = split(bytes, chunks, &overlongChunks);
    CHECK(whole == chunked && overlongWhole == overlongChunks, "chunked feeding gave other lines (%d vs %d)", static_cast<int>(whole.size()),
          static_cast<int>(chunked.size()));
    if (bytes.size() < 4096) {
        const QList<QByteArray> single = split(bytes, {1}, &overlongBytes);
        CHECK(single == whole && overlongBytes == overlongWhole, "byte-by-byte feeding gave other lines");
    }
    g_cov.overlong += static_cast<std::uint64_t>(overlongWhole);
    for (const QByteArray& l : whole)
        checkLine(l);
}

// ---- inputs ---------------------------------------------------------------------------

QByteArray validRequest(std::mt19937_64& rng)
{
    static const char* kSamples[] = {
        R"({"jsonrpc":"2.0","id":1,"method":"device.status","params":{"instrument":"stage"}})",
        R"({"jsonrpc":"2.0","id":"a","method":"device.move","params":{"targets":{"X":10,"Y":-5.5},"speed":2,"relative":true,"lease":"x"}})",
        R"({"jsonrpc":"2.0","id":3,"method":"device.jog","params":{"axis":"X","velocity":-2,"seconds":0.5}})",
        R"({"jsonrpc":"2.0","method":"control.heartbeat","params":{"lease":"abc"}})",
        R"({"jsonrpc":"2.0","id":4,"method":"subscribe","params":{"topics":{"positions":{"max_hz":50}}}})",
        R"({"jsonrpc":"2.0","id":5,"method":"scan.plan","params":{"roi":[20,30,44,42],"fov":[1.33,1.33],"overlap":[0.1],"format":"summary"}})",
        R"({"jsonrpc":"2.0","id":6,"method":"device.limits","params":{"limits":{"X":[0,50]}}})",
        R"({"jsonrpc":"2.0","id":7,"method":"motion.profile","params":{"kind":"trapezoid","distance":[2,3],"vmax":10}})",
        R"({"jsonrpc":"2.0","id":8,"method":"tuning.gains","params":{"gains":{"X":[1,2,3]}}})",
        R"({"jsonrpc":"2.0","id":9,"method":"motion.blocks","params":{"joint":["100:200:500","50:10:20"]}})",
        R"({"jsonrpc":"2.0","id":null,"method":"cli.run","params":{"argv":["status"]}})",
        R"({"jsonrpc":"2.0","id":10,"method":"device.home","params":{"axes":["X","Y"]}})",
    };
    return QByteArray(kSamples[rng() % std::size(kSamples)]);
}

QByteArray mutate(QByteArray s, std::mt19937_64& rng)
{
    const int n = static_cast<int>(rng() % 4);
    for (int k = 0; k < n && !s.isEmpty(); ++k) {
        const int at = static_cast<int>(rng() % static_cast<std::uint64_t>(s.size()));
        switch (rng() % 10) {
        case 0: s[at] = static_cast<char>(s[at] ^ (1 << (rng() % 8))); break;
        case 1: s.truncate(at); break;
        case 2: s.insert(at, validRequest(rng).mid(static_cast<int>(rng() % 40))); break;
        case 3: s.insert(at, QByteArray(static_cast<int>(rng() % 64), static_cast<char>(rng() % 256))); break;
        case 4: s.insert(at, QByteArray(static_cast<int>(rng() % 200), '[')); break;  // deep nesting
        case 5: s.insert(at, "1e308"); break;
        case 6: s.insert(at, "\"\\ud800\""); break;  // a lone surrogate
        case 7: s.insert(at, "-0.0e-400"); break;
        case 8: s.insert(at, '\n'); break;
        default: s.remove(at, static_cast<int>(rng() % 8)); break;
        }
    }
    return s;
}

QByteArray makeInput(std::mt19937_64& rng, std::uint64_t i)
{
    QByteArray out;
    const int lines = static_cast<int>(rng() % 6) + 1;
    for (int l = 0; l < lines; ++l) {
        if (i % 500 == 499 && l == 0)
            out += QByteArray(app::api::kMaxLineBytes + static_cast<int>(rng() % 100), 'x');  // an overlong line now and then
        else if (rng() % 8 == 0)
            out += QByteArray(static_cast<int>(rng() % 300), static_cast<char>(rng() % 256));
        else
            out += mutate(validRequest(rng), rng);
        out += (rng() % 5 == 0) ? "\r\n" : "\n";
    }
    return out;
}

} // namespace

#ifdef BP_LIBFUZZER
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static int argc = 1;
    static char name[] = "fuzz_api";
    static char* argv[] = {name, nullptr};
    static QCoreApplication app(argc, argv);
    std::mt19937_64 rng(size);
    checkInput(QByteArray(reinterpret_cast<const char*>(data), static_cast<int>(size)), rng);
    return 0;
}
#else
int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    std::uint64_t iterations = 5000, seed = 20;
    std::vector<std::string> files;
    std::string corpus, seedDir;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--iterations") && i + 1 < argc)
            iterations = std::strtoull(argv[++i], nullptr, 10);
        else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc)
            seed = std::strtoull(argv[++i], nullptr, 10);
        else if (!std::strcmp(argv[i], "--corpus") && i + 1 < argc)
            corpus = argv[++i];  // replayed before the generated inputs
        else if (!std::strcmp(argv[i], "--emit") && i + 1 < argc)
            seedDir = argv[++i];  // the generated inputs written out, as libFuzzer seeds
        else
            files.emplace_back(argv[i]);
    }
    std::mt19937_64 rng(seed);
    if (!seedDir.empty()) {
        for (std::uint64_t k = 0; k < iterations; ++k) {
            const QByteArray input = makeInput(rng, k);
            if (!fuzzcorpus::write(seedDir + "/gen-" + std::to_string(k), input.constData(), static_cast<std::size_t>(input.size()))) {
                std::fprintf(stderr, "fuzz_api: cannot write into %s\n", seedDir.c_str());
                return 2;
            }
        }
        return 0;
    }
    auto replay = [&](const std::string& f) {
        std::string bytes;
        if (!fuzzcorpus::read(f, bytes)) {
            std::fprintf(stderr, "fuzz_api: cannot read %s\n", f.c_str());
            std::exit(2);
        }
        checkInput(QByteArray(bytes.data(), static_cast<int>(bytes.size())), rng);
    };
    if (!files.empty()) {
        for (const auto& f : files)
            replay(f);
        return 0;
    }
    if (!corpus.empty()) {
        // A kept corpus that went missing would leave the test passing on less than it claims.
        const auto paths = fuzzcorpus::files(corpus);
        if (!paths || paths->empty()) {
            std::fprintf(stderr, "fuzz_api: no corpus in %s\n", corpus.c_str());
            return 2;
        }
        for (const auto& f : *paths)
            replay(f);
        std::printf("fuzz_api: %zu corpus inputs of %s replayed\n", paths->size(), corpus.c_str());
    }
    for (g_iteration = 0; g_iteration < iterations; ++g_iteration) {
        const QByteArray input = makeInput(rng, g_iteration);
        checkInput(input, rng);
    }
    std::printf("fuzz_api: %" PRIu64 " inputs, %" PRIu64 " lines: %" PRIu64 " calls, %" PRIu64 " notifications, %" PRIu64
                " invalid, %" PRIu64 " overlong; params converted %" PRIu64 ", refused %" PRIu64 "\n",
                iterations, g_cov.lines, g_cov.calls, g_cov.notifications, g_cov.invalid, g_cov.overlong, g_cov.converted, g_cov.refused);
    return 0;
}
#endif
