// The file-reader fuzz driver's engine: target registry, seeded mutations of
// the targets' seed documents, replay of saved inputs, and main().
#include "fuzz_files.h"
#include "tests/fuzz/corpus_files.h"

#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <fstream>
#include <iterator>
#include <sstream>
#include <sys/stat.h>

namespace fuzzfiles {
namespace {

std::vector<Target>& registry()
{
    static std::vector<Target> r;
    return r;
}

const std::string* g_input = nullptr;
std::string g_target;
std::uint64_t g_iteration = 0;

/// SplitMix64: the same sequence with every compiler and standard library.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : m_s(seed) {}
    std::uint64_t next()
    {
        std::uint64_t z = (m_s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    std::size_t below(std::size_t n) { return n ? static_cast<std::size_t>(next() % n) : 0; }
    bool chance(unsigned percent) { return below(100) < percent; }

private:
    std::uint64_t m_s;
};

struct Span {
    std::size_t begin, end;
    bool number;
};

/// Number and string tokens of a JSON-ish text (valid or not), for value mutations.
std::vector<Span> tokens(const std::string& s)
{
    std::vector<Span> out;
    for (std::size_t i = 0; i < s.size();) {
        if (s[i] == '"') {
            std::size_t j = i + 1;
            while (j < s.size() && s[j] != '"')
                j += s[j] == '\\' ? 2 : 1;
            out.push_back({i, std::min(j + 1, s.size()), false});
            i = j + 1;
        } else if (s[i] == '-' || (s[i] >= '0' && s[i] <= '9')) {
            std::size_t j = i + 1;
            while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.' || s[j] == 'e' || s[j] == 'E'
                                    || s[j] == '+' || s[j] == '-'))
                ++j;
            out.push_back({i, j, true});
            i = j;
        } else {
            ++i;
        }
    }
    return out;
}

const char* kNumbers[] = {"0", "-0", "1", "-1", "2.5", "-2.5", "1e308", "-1e308", "1e-320", "4294967296", "-2147483649",
                          "9007199254740993", "0.0001", "100", "384", "96", "1000000", "1e5", "12", "8", "-0.5"};
const char* kValues[] = {"null", "true", "false", "[]", "{}", "\"\"", "[[[[]]]]", "{\"a\":1}", "[1,2,3]", "\"x\"", "0"};
const char* kStrings[] = {"\"\"", "\"A1\"", "\"H12\"", "\"I13\"", "\"P24\"", "\"A1:H12\"", "\"A1:A1\"", "\"H12:A1\"",
                          "\"row B\"", "\"row Z\"", "\"column 3\"", "\"column 99\"", "\"A0\"", "\"a1\"", "\"🙂\"",
                          "\"\\u0000\"", "\"line\"", "\"arc\"", "\"aspirate\"", "\"dispense\"", "\"mix\"", "\"wash\"",
                          "\"rows\"", "\"snake-rows\"", "\"fopdt:K=1,tau=1,L=0.1\"", "\"benchpilot.recipe\""};

void mutate(Rng& r, std::string& s, const std::vector<std::string>& seeds)
{
    const int rounds = 1 + static_cast<int>(r.below(4));
    for (int k = 0; k < rounds; ++k) {
        switch (r.below(10)) {
        case 0:
        case 1:
        case 2: {  // a number or string replaced by a hostile one
            const auto t = tokens(s);
            if (t.empty())
                break;
            const Span sp = t[r.below(t.size())];
            std::string with;
            if (r.chance(15))
                with = kValues[r.below(std::size(kValues))];
            else if (sp.number)
                with = kNumbers[r.below(std::size(kNumbers))];
            else
                with = kStrings[r.below(std::size(kStrings))];
            s.replace(sp.begin, sp.end - sp.begin, with);
            break;
        }
        case 3: {  // a line deleted
            std::vector<std::size_t> starts{0};
            for (std::size_t i = 0; i < s.size(); ++i)
                if (s[i] == '\n')
                    starts.push_back(i + 1);
            const std::size_t a = starts[r.below(starts.size())];
            const std::size_t b = s.find('\n', a);
            s.erase(a, b == std::string::npos ? std::string::npos : b - a + 1);
            break;
        }
        case 4: {  // a line repeated (duplicate keys, extra array items)
            std::vector<std::size_t> starts{0};
            for (std::size_t i = 0; i < s.size(); ++i)
                if (s[i] == '\n')
                    starts.push_back(i + 1);
            const std::size_t a = starts[r.below(starts.size())];
            const std::size_t b = s.find('\n', a);
            const std::string line = s.substr(a, b == std::string::npos ? std::string::npos : b - a + 1);
            s.insert(a, line);
            break;
        }
        case 5:  // truncated
            s.resize(r.below(s.size() + 1));
            break;
        case 6: {  // a byte changed, inserted or removed
            if (s.empty())
                break;
            const std::size_t i = r.below(s.size());
            const int op = static_cast<int>(r.below(3));
            if (op == 0)
                s[i] = static_cast<char>(r.next());
            else if (op == 1)
                s.insert(i, 1, "{}[],:\"\\0e-."[r.below(12)]);
            else
                s.erase(i, 1);
            break;
        }
        case 7: {  // spliced with another seed
            if (seeds.empty())
                break;
            const std::string& o = seeds[r.below(seeds.size())];
            const std::size_t a = r.below(s.size() + 1), b = r.below(o.size() + 1);
            s = s.substr(0, a) + o.substr(b);
            break;
        }
        case 8: {  // a range of lines repeated many times (size, counts)
            if (s.empty())
                break;
            const std::size_t a = r.below(s.size());
            const std::size_t n = std::min<std::size_t>(200, s.size() - a);
            const std::string chunk = s.substr(a, r.below(n + 1));
            for (int rep = static_cast<int>(r.below(50)); rep > 0; --rep)
                s.insert(a, chunk);
            break;
        }
        default: {  // a value wrapped in an array or object
            const auto t = tokens(s);
            if (t.empty())
                break;
            const Span sp = t[r.below(t.size())];
            const std::string v = s.substr(sp.begin, sp.end - sp.begin);
            s.replace(sp.begin, sp.end - sp.begin, r.chance(50) ? "[" + v + "]" : "{\"v\": " + v + "}");
            break;
        }
        }
    }
}

bool readFile(const std::string& path, std::string& out)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return false;
    out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}

void runOne(const Target& t, const std::string& input)
{
    g_input = &input;
    g_target = t.name;
    t.check(input);
    g_input = nullptr;
}

} // namespace

bool registerTarget(Target t)
{
    registry().push_back(std::move(t));
    return true;
}

const std::vector<Target>& targets() { return registry(); }

std::vector<std::string> exampleFiles(std::string_view suffix)
{
    std::vector<std::string> out;
    const std::string dir = std::string(BP_SOURCE_DIR) + "/resources/examples";
    if (DIR* d = ::opendir(dir.c_str())) {
        while (const dirent* e = ::readdir(d)) {
            const std::string name = e->d_name;
            if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
                std::string text;
                if (readFile(dir + "/" + name, text))
                    out.push_back(std::move(text));
            }
        }
        ::closedir(d);
    }
    return out;
}

void fail(const std::string& message)
{
    std::fprintf(stderr, "fuzz_files: target %s, iteration %" PRIu64 ": %s\n", g_target.c_str(), g_iteration, message.c_str());
#ifdef BP_LIBFUZZER
    std::abort();
#else
    if (g_input) {
        const std::string path = "fuzz_files-failure-" + g_target + ".txt";
        if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
            std::fwrite(g_input->data(), 1, g_input->size(), f);
            std::fclose(f);
            std::fprintf(stderr, "fuzz_files: input (%zu bytes) written to %s; replay with `fuzz_files --target %s %s`\n",
                         g_input->size(), path.c_str(), g_target.c_str(), path.c_str());
        }
    }
    std::exit(1);
#endif
}

} // namespace fuzzfiles

#ifdef BP_LIBFUZZER
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const char* want = std::getenv("BP_FUZZ_TARGET");
    const std::string input(reinterpret_cast<const char*>(data), size);
    for (const auto& t : fuzzfiles::targets())
        if (!want || t.name == want)
            fuzzfiles::runOne(t, input);
    return 0;
}
#else
int main(int argc, char** argv)
{
    using namespace fuzzfiles;
    std::uint64_t iterations = 20000, seed = 0xF11E5;
    std::string only;
    unsigned shard = 0, shards = 1;  // --shard K/N: every N-th target by name, so CTest runs N at once
    std::vector<std::string> files;
    std::string corpus, seedDir;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--corpus" && i + 1 < argc) {
            corpus = argv[++i];
        } else if (a == "--emit" && i + 1 < argc) {
            seedDir = argv[++i];
        } else if (a == "--iterations" && i + 1 < argc) {
            iterations = std::strtoull(argv[++i], nullptr, 10);
        } else if (a == "--seed" && i + 1 < argc) {
            seed = std::strtoull(argv[++i], nullptr, 0);
        } else if (a == "--target" && i + 1 < argc) {
            only = argv[++i];
        } else if (a == "--shard" && i + 1 < argc) {
            if (std::sscanf(argv[++i], "%u/%u", &shard, &shards) != 2 || shards == 0 || shard >= shards) {
                std::fprintf(stderr, "fuzz_files: --shard needs K/N with K < N (got %s)\n", argv[i]);
                return 2;
            }
        } else if (a == "--help" || a == "-h") {
            std::printf("usage: fuzz_files [--iterations N] [--seed S] [--target NAME | --shard K/N] [--corpus DIR] [FILE...]\n"
                        "       fuzz_files --emit DIR [--target NAME]   (writes each target's seeds to DIR/NAME/, for libFuzzer)\n"
                        "  --corpus DIR  replays DIR/NAME/* (a kept corpus, if NAME has one) before NAME's mutated inputs\n"
                        "targets:");
            for (const auto& t : targets())
                std::printf(" %s", t.name.c_str());
            std::printf("\n");
            return 0;
        } else if (!a.empty() && a[0] == '-') {
            std::fprintf(stderr, "fuzz_files: unknown option %s\n", a.c_str());
            return 2;
        } else {
            files.push_back(a);
        }
    }
    std::vector<const Target*> chosen;
    for (const auto& t : targets())
        if (only.empty() || t.name == only)
            chosen.push_back(&t);
    std::sort(chosen.begin(), chosen.end(), [](const Target* a, const Target* b) { return a->name < b->name; });
    if (shards > 1) {
        std::vector<const Target*> mine;
        for (std::size_t k = shard; k < chosen.size(); k += shards)
            mine.push_back(chosen[k]);
        chosen.swap(mine);
    }
    if (chosen.empty()) {
        std::fprintf(stderr, "fuzz_files: no target named '%s'\n", only.c_str());
        return 2;
    }
    if (!seedDir.empty()) {
        for (const Target* t : chosen) {
            const std::string dir = seedDir + "/" + t->name;
            ::mkdir(dir.c_str(), 0777);
            const std::vector<std::string> seeds = t->seeds();
            for (std::size_t k = 0; k < seeds.size(); ++k)
                if (!fuzzcorpus::write(dir + "/seed-" + std::to_string(k), seeds[k].data(), seeds[k].size())) {
                    std::fprintf(stderr, "fuzz_files: cannot write into %s\n", dir.c_str());
                    return 2;
                }
        }
        return 0;
    }
    if (!corpus.empty() && !fuzzcorpus::files(corpus)) {
        std::fprintf(stderr, "fuzz_files: no corpus folder %s\n", corpus.c_str());
        return 2;
    }
    if (!files.empty()) {
        for (const auto& path : files) {
            std::string text;
            if (!readFile(path, text)) {
                std::fprintf(stderr, "fuzz_files: cannot read %s\n", path.c_str());
                return 2;
            }
            for (const Target* t : chosen)
                runOne(*t, text);
            std::printf("fuzz_files: %s (%zu bytes) ok\n", path.c_str(), text.size());
        }
        return 0;
    }
    // Every target gets the same number of inputs, so adding a format does not
    // thin out the others' share.
    for (const Target* t : chosen) {
        const std::vector<std::string> seeds = t->seeds();
        if (seeds.empty()) {
            std::fprintf(stderr, "fuzz_files: target %s has no seed documents\n", t->name.c_str());
            return 1;
        }
        Rng rng(seed ^ std::hash<std::string>{}(t->name));
        for (const auto& s : seeds)
            runOne(*t, s);  // the seeds themselves, unmutated
        std::size_t replayed = 0;
        if (!corpus.empty())
            if (const auto paths = fuzzcorpus::files(corpus + "/" + t->name))
                for (const std::string& path : *paths) {
                    std::string text;
                    if (!fuzzcorpus::read(path, text)) {
                        std::fprintf(stderr, "fuzz_files: cannot read %s\n", path.c_str());
                        return 2;
                    }
                    runOne(*t, text);
                    ++replayed;
                }
        for (g_iteration = 0; g_iteration < iterations; ++g_iteration) {
            std::string input = seeds[rng.below(seeds.size())];
            mutate(rng, input, seeds);
            runOne(*t, input);
        }
        std::printf("fuzz_files: %s: %zu seeds, %zu corpus inputs, %" PRIu64 " mutated inputs: all invariants held\n",
                    t->name.c_str(), seeds.size(), replayed, iterations);
    }
    return 0;
}
#endif
