#pragma once
// The file-reader fuzz driver: every reader of a file people keep (recipes,
// plates, patterns, scan plans, tuning results, …) registers a target here from
// its own .cpp with BP_FUZZ_FILE_TARGET. The driver mutates each target's seed
// documents (its examples under resources/examples/, or built ones) and hands
// every input to the target's check, which must never crash, hang or accept
// something it cannot write back and read again the same.
//
//   fuzz_files [--iterations N] [--seed S] [--target NAME] [--corpus DIR] [FILE...]
//
// With FILEs, each is replayed through every target (or --target). With --corpus DIR,
// DIR/NAME/* (tests/fuzz/corpus/NAME, kept by libFuzzer's campaigns) is replayed before
// NAME's mutated inputs; `--emit DIR` writes each target's seeds to DIR/NAME/. Built with
// -DBP_LIBFUZZER=ON (clang; cmake/libfuzzer.cmake, docs/testing.md "Fuzzing") it is a
// libFuzzer target, and BP_FUZZ_TARGET=NAME chooses the target LLVMFuzzerTestOneInput runs
// (all of them when unset).
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fuzzfiles {

struct Target {
    std::string name;
    /// Seed documents; mutations of these are the inputs.
    std::function<std::vector<std::string>()> seeds;
    /// Reads one input; calls fail() on a violated invariant.
    std::function<void(std::string_view input)> check;
};

bool registerTarget(Target t);
const std::vector<Target>& targets();

/// Text of every resources/examples file whose name ends with `suffix` (".recipe.json").
std::vector<std::string> exampleFiles(std::string_view suffix);

[[noreturn]] void fail(const std::string& message);

#define BP_FUZZ_CONCAT2(a, b) a##b
#define BP_FUZZ_CONCAT(a, b) BP_FUZZ_CONCAT2(a, b)
/// At namespace scope: BP_FUZZ_FILE_TARGET({"recipe", seedsFn, checkFn});
#define BP_FUZZ_FILE_TARGET(...) \
    static const bool BP_FUZZ_CONCAT(bpFuzzRegistered, __LINE__) = ::fuzzfiles::registerTarget(::fuzzfiles::Target __VA_ARGS__)

} // namespace fuzzfiles
