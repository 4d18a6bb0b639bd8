#pragma once
// The fuzz drivers' side of the kept corpora (tests/fuzz/corpus/<target>/, docs/testing.md
// "Fuzzing"): the files of a folder, in name order so a replay is the same every run, and
// writing inputs out as files (seeds for libFuzzer, a failing input).
#include <algorithm>
#include <cstdio>
#include <dirent.h>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

namespace fuzzcorpus {

/// Paths of the regular files in `dir` (no dot files), sorted; nullopt when `dir` cannot be opened.
inline std::optional<std::vector<std::string>> files(const std::string& dir)
{
    DIR* d = ::opendir(dir.c_str());
    if (!d)
        return std::nullopt;
    std::vector<std::string> out;
    while (const dirent* e = ::readdir(d)) {
        const std::string name = e->d_name;
        if (name.empty() || name[0] == '.')
            continue;
        out.push_back(dir + "/" + name);
    }
    ::closedir(d);
    std::sort(out.begin(), out.end());
    return out;
}

inline bool read(const std::string& path, std::string& out)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return false;
    out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}

inline bool write(const std::string& path, const void* data, std::size_t size)
{
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f)
        return false;
    const bool ok = std::fwrite(data, 1, size, f) == size;
    return std::fclose(f) == 0 && ok;
}

} // namespace fuzzcorpus
