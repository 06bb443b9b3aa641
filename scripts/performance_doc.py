#!/usr/bin/env python3
"""Writes docs/performance.md from the tables `recoil_bench` printed.

    performance_doc.py BENCH_OUTPUT.md docs/performance.md

The page is the bench's output under a header naming the machine and the
commit; nothing in it is typed by hand, so it says what this tree measures.
"""
import os
import subprocess
import sys


def machine():
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as info:
            for line in info:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{os.cpu_count()} cores ({model})"


def commit(source):
    try:
        return subprocess.run(["git", "-C", source, "describe", "--always", "--dirty"], capture_output=True,
                              text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    bench_output, page = sys.argv[1], sys.argv[2]
    with open(bench_output, encoding="utf-8") as source:
        tables = source.read().strip()
    source_dir = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    header = (
        "# Performance\n\n"
        "Written by `make bench` (every bench of `build/recoil_bench`, one run) on "
        f"{machine()}, at commit `{commit(source_dir)}`. Times are wall-clock on that machine; compare them as "
        "ratios within this page. What changed a figure, measured before and after, is in "
        "`docs/solver-log.md` and `docs/decisions/`.\n")
    with open(page + ".tmp", "w", encoding="utf-8") as out:
        out.write(header + "\n" + tables + "\n")
    os.replace(page + ".tmp", page)


if __name__ == "__main__":
    main()
