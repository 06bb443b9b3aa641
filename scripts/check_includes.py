#!/usr/bin/env python3
"""Fails when product code includes a header from a layer above its own.

The layers, lowest first: a file may include its own folder and the folders
before it in its row of ALLOWED; nothing in the product includes tests/ or
fuzz/. `make test` runs this over the tree (CTest Layout.IncludesRunOneWay),
and with --self-test over a scratch tree holding one back-include, which it
must refuse (Layout.IncludeCheckRefusesABackInclude).
"""
import os
import re
import sys
import tempfile

SIM_LAYERS = ["core", "sim/geometry", "sim/body", "sim/collision", "sim/fem", "sim/rigid", "sim/solver", "sim/contact",
              "sim"]
ALLOWED = {folder: set(SIM_LAYERS[: i + 1]) for i, folder in enumerate(SIM_LAYERS)}
ALLOWED["render"] = {"core", "render"}
ALLOWED["cli"] = set(SIM_LAYERS) | {"render", "cli"}
PRODUCT = list(ALLOWED)
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def folder_of(path):
    """The layer a repository-relative path belongs to (its longest known folder)."""
    parent = os.path.dirname(path)
    while parent and parent not in ALLOWED:
        parent = os.path.dirname(parent)
    return parent or None


def violations(root):
    found = []
    for top in sorted({p.split("/")[0] for p in PRODUCT}):
        for directory, _, files in os.walk(os.path.join(root, top)):
            for name in sorted(files):
                if not name.endswith((".h", ".cpp")):
                    continue
                path = os.path.relpath(os.path.join(directory, name), root)
                layer = folder_of(path)
                with open(os.path.join(root, path), encoding="utf-8") as source:
                    for number, line in enumerate(source, 1):
                        match = INCLUDE.match(line)
                        if not match:
                            continue
                        header = match.group(1)
                        target = folder_of(header)
                        if header.startswith(("tests/", "fuzz/")):
                            found.append(f"{path}:{number}: {layer}/ includes {header}, which is not product code")
                        elif target is not None and target not in ALLOWED[layer]:
                            found.append(f"{path}:{number}: {layer}/ includes {header}, which is above it "
                                         f"(allowed: {', '.join(sorted(ALLOWED[layer]))})")
    return found


def self_test():
    with tempfile.TemporaryDirectory() as root:
        for path, text in {"sim/world.h": "#pragma once\n",
                           "sim/geometry/shape.h": '#pragma once\n#include "sim/world.h"\n'}.items():
            os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
            with open(os.path.join(root, path), "w", encoding="utf-8") as out:
                out.write(text)
        found = violations(root)
    print("\n".join(found))
    if len(found) != 1 or "sim/geometry/shape.h:2" not in found[0]:
        print("check_includes: the deliberate back-include was not refused", file=sys.stderr)
        return 1
    return 0


def main():
    if sys.argv[1:2] == ["--self-test"]:
        return self_test()
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    found = violations(root)
    for line in found:
        print(line, file=sys.stderr)
    print(f"check_includes: {len(found)} include(s) running back up" if found else "check_includes: every include runs one way")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
