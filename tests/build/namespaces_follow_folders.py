#!/usr/bin/env python3
"""A name says where it lives: each top folder of the product has one namespace.

    motion/  -> motion::…     device/ -> dev::…     imaging/ -> imaging::…
    widgets/ -> ui::…         app/    -> app::…

Fails, naming each file and line, where product code opens a namespace whose first
part is none of these (a seventh `somethingfiles`), or where a source file (.cpp)
defines things in another folder's namespace. Headers may open another folder's
namespace to forward-declare its types. Run from CTest (label build) or by hand:

    python3 tests/build/namespaces_follow_folders.py [SOURCE_DIR]
"""
import os
import re
import sys

FOLDER_NAMESPACE = {"motion": "motion", "device": "dev", "imaging": "imaging", "widgets": "ui", "app": "app"}
# Opened to specialise or extend what a library owns, not to hold our names.
FOREIGN = {"std", "QTest", "Eigen"}
OPENS = re.compile(r"^\s*(?:inline\s+)?namespace\s+([A-Za-z_][\w:]*)\s*\{")
# What is left of a line for counting braces: no comments, strings or characters.
NOT_CODE = re.compile(r'//.*|/\*.*?\*/|"(?:\\.|[^"\\])*"|\'(?:\\.|[^\'\\])*\'')


def main(root):
    bad = []
    for top, own in FOLDER_NAMESPACE.items():
        for folder, _, files in os.walk(os.path.join(root, top)):
            for name in sorted(files):
                if not name.endswith((".h", ".cpp")):
                    continue
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, root)
                depth = 0  # only namespaces opened at file scope say where a name lives
                with open(path, encoding="utf-8") as f:
                    for number, line in enumerate(f, 1):
                        m = OPENS.match(line) if depth == 0 else None
                        code = NOT_CODE.sub("", line)
                        depth += code.count("{") - code.count("}")
                        if not m:
                            continue
                        first = m.group(1).split("::")[0]
                        if first in FOREIGN:
                            continue
                        if first not in FOLDER_NAMESPACE.values():
                            bad.append(f"{rel}:{number}: namespace {m.group(1)}: a name under {top}/ lives in {own}::")
                        elif name.endswith(".cpp") and first != own:
                            bad.append(f"{rel}:{number}: namespace {m.group(1)}: {top}/ defines its names in {own}::")
    if bad:
        print("\n".join(bad))
        print(f"{len(bad)} namespace(s) do not follow their folder")
        return 1
    print("every namespace follows its folder")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")))
