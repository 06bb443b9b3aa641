#!/usr/bin/env python3
"""Writes docs/validation.md from the validation suite's gtest JSON output.

Each validation test prints and records what it measured
(tests/validation/measured.h); this turns those records into the page, so
the page says what the tests found and nothing typed by hand.
Usage: validation_doc.py SUITE.json OUT.md (`make validation-doc` runs it).
"""
import json
import sys


def main():
    if len(sys.argv) != 3:
        print("usage: validation_doc.py SUITE.json OUT.md", file=sys.stderr)
        return 2
    with open(sys.argv[1], encoding="utf-8") as source:
        report = json.load(source)
    lines = [
        "# Validation",
        "",
        "The physical checks of `build/recoil_tests_validation` and what each measured",
        "in its last run, written by `make validation-doc` from the suite's own output",
        "(do not edit by hand). Each check's scene and bound are in its test, under",
        "`tests/validation/`; the scenes a user can render are in",
        "`assets/scenes/validation/`.",
        "",
        f"{report['tests']} checks, {report['failures']} failed, {report.get('disabled', 0)} disabled; "
        f"run of {report['timestamp']}, {report['time']}.",
    ]
    for suite in report["testsuites"]:
        lines += ["", f"## {suite['name']}", ""]
        for test in suite["testsuite"]:
            result = test.get("result")
            status = ("failed" if test.get("failures") else "skipped" if result == "SKIPPED"
                      else "disabled" if result == "SUPPRESSED" or test.get("status") == "NOTRUN" else "passed")
            lines.append(f"- **{test['name']}**: {status} ({test['time']})")
            measured = sorted((k for k in test if k.startswith("measured_")), key=lambda k: int(k.split("_")[1]))
            lines += [f"  - {test[k]}" for k in measured]
    with open(sys.argv[2], "w", encoding="utf-8") as out:
        out.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
