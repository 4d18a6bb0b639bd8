#!/usr/bin/env python3
"""Comments and docs describe the product as it is, not the work that made it.

Fails, naming each file and line, where a source, build file, script or doc names
an issue or a work stop by number: the reason belongs in the comment, the history
in git and the issue notes. Run from CTest (label build) or by hand:

    python3 tests/build/no_history_refs.py [SOURCE_DIR]

It lists the files with `git ls-files` (tracked and untracked, not ignored) when
SOURCE_DIR is a git checkout, and walks the tree otherwise (skipping build*/ and
hidden folders), so it also runs on a tarball.
"""
import os
import re
import subprocess
import sys

# What is scanned: C++ sources and headers, the build files, the scripts, the
# Python client, the READMEs and docs/. Not resources/ or the fuzz corpora: their
# bytes are data, not prose.
SUFFIXES = (".cpp", ".h", ".cmake", ".py", ".sh", ".md")
NAMES = ("CMakeLists.txt",)
FOLDERS_WITHOUT_SUFFIX = ("scripts/", ".ci/")
SKIPPED_FOLDERS = ("resources/", "tests/fuzz/corpus/")

# A history reference: "issue" or "stop" as a word, a space, a number. Not when the
# word is the end of a hyphenated one (the operator's E-stop, "e-stop 2" as a name).
HISTORY = re.compile(r"(?<![\w-])(issue|stop) [0-9]+", re.IGNORECASE)
# True matches that are the product's own words, each as narrow as it can be:
#  - an accuracy test's sequence has stops (target positions): "stop 2 is at 20.590 mm",
#    "stop 3 (at 30 mm)".
ALLOWED = [
    re.compile(r"\bstop [0-9]+ (is at|\(at) ", re.IGNORECASE),
]


def wanted(path):
    if path.startswith(SKIPPED_FOLDERS):
        return False
    name = os.path.basename(path)
    if name in NAMES or path.endswith(SUFFIXES):
        return not path.endswith(".md") or path.startswith("docs/") or "/" not in path
    return path.startswith(FOLDERS_WITHOUT_SUFFIX)


def listed_by_git(src):
    try:
        out = subprocess.run(
            ["git", "-C", src, "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
            check=True, capture_output=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    return sorted({p for p in out.decode("utf-8", "replace").split("\0") if p})


def walked(src):
    paths = []
    for root, dirs, files in os.walk(src):
        rel = os.path.relpath(root, src)
        if rel == ".":
            dirs[:] = [d for d in dirs if not d.startswith(("build", "."))]
            rel = ""
        else:
            dirs[:] = [d for d in dirs if not d.startswith(".")]
            rel += "/"
        paths += [rel + f for f in files]
    return sorted(paths)


def hits_in(src, path):
    try:
        with open(os.path.join(src, path), encoding="utf-8", errors="replace") as f:
            lines = f.read().splitlines()
    except OSError:  # listed by git but deleted in the working tree
        return []
    found = []
    for number, line in enumerate(lines, 1):
        for m in HISTORY.finditer(line):
            if any(a.match(line, m.start()) for a in ALLOWED):
                continue
            found.append(f"{path}:{number}: {m.group(0)!r} in: {line.strip()}")
            break
    return found


def main():
    src = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
    paths = listed_by_git(src)
    if paths is None:
        paths = walked(src)
    paths = [p for p in paths if wanted(p)]
    if not paths:
        print(f"no sources found under {src}", file=sys.stderr)
        return 2
    hits = [h for p in paths for h in hits_in(src, p)]
    for h in hits:
        print(h)
    if hits:
        print(f"\n{len(hits)} line(s) name an issue or a work stop by number. Say the reason or the "
              "fact instead; the history is in git and the issue notes.", file=sys.stderr)
        return 1
    print(f"{len(paths)} files: no issue or stop numbers")
    return 0


if __name__ == "__main__":
    sys.exit(main())
