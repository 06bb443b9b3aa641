#!/usr/bin/env python3
"""Writes the hostile-input corpus (make_corpus.py) into CORPUS_DIR and runs
it against a recoil binary.
Usage: run_corpus.py RECOIL CORPUS_DIR [--memory-limit-mib N] [NAME_SUBSTRING]

Each case runs in an empty working folder under a time limit; it passes when
the exit code is the expected one, stderr is one `recoil: error:` line that
contains every expected substring, peak memory stayed under the limit (1 GiB), and
nothing was written outside output/<name>/ in the working folder (nothing at
all when the input was refused).
"""
import json
import os
import resource
import shutil
import signal
import subprocess
import sys
import time

TIME_LIMIT_S = 120       # a hang, not a slow case: every case finishes in seconds alone

args = sys.argv[1:]
memory_limit_mib = 1024  # sanitizer builds need more for their shadow memory
if "--memory-limit-mib" in args:
    at = args.index("--memory-limit-mib")
    memory_limit_mib = int(args[at + 1])
    del args[at:at + 2]
recoil, corpus = os.path.abspath(args[0]), os.path.abspath(args[1])
only = args[2] if len(args) > 2 else ""
shutil.rmtree(corpus, ignore_errors=True)
subprocess.run([sys.executable, os.path.join(os.path.dirname(os.path.abspath(__file__)), "make_corpus.py"), corpus],
               check=True)
cases = json.load(open(os.path.join(corpus, "cases.json")))
failures = []
for case in cases:
    if only not in case["name"]:
        continue
    work = os.path.join(corpus, "work", case["name"])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    args = [recoil] + [a.replace("{dir}", corpus) for a in case["args"].split()]
    start = time.monotonic()
    with open(os.path.join(work, ".stderr"), "wb") as err:
        child = subprocess.Popen(args, cwd=work, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=err,
                                 start_new_session=True)
        timed_out = False
        while True:
            pid, status, usage = os.wait4(child.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() - start > TIME_LIMIT_S:
                os.killpg(child.pid, signal.SIGKILL)
                timed_out = True
            time.sleep(0.02)
    seconds = time.monotonic() - start
    code = os.waitstatus_to_exitcode(status)
    stderr = open(os.path.join(work, ".stderr"), encoding="utf-8", errors="replace").read()
    os.remove(os.path.join(work, ".stderr"))
    problems = []
    if timed_out:
        problems.append(f"still running after {TIME_LIMIT_S} s")
    if code != case["exit"]:
        problems.append(f"exit {code}, expected {case['exit']}")
    errors = [line for line in stderr.splitlines() if line.startswith("recoil: error:")]
    if len(errors) != (0 if case["exit"] == 0 else 1):
        problems.append(f"{len(errors)} 'recoil: error:' lines")
    for part in case["expect"]:
        if part not in stderr:
            problems.append(f"stderr lacks {part!r}")
    if usage.ru_maxrss > memory_limit_mib * 1024:
        problems.append(f"peak memory {usage.ru_maxrss / 1024:.0f} MiB")
    written = []
    for root, dirs, files in os.walk(work):
        for f in files:
            relative = os.path.relpath(os.path.join(root, f), work)
            parts = relative.split(os.sep)
            inside_output = len(parts) >= 3 and parts[0] == "output" and parts[1] not in (".", "..")
            if case["exit"] == 2 or not inside_output:
                written.append(relative)
    if written:
        problems.append("wrote " + ", ".join(sorted(written)[:3]))
    shutil.rmtree(work, ignore_errors=True)
    line = stderr.strip().splitlines()[-1] if stderr.strip() else ""
    status_word = "FAIL" if problems else "ok"
    print(f"{status_word:4} {case['name']:36} exit {code:3} {seconds:6.2f} s {usage.ru_maxrss / 1024:6.0f} MiB  {line[:150]}")
    if problems:
        failures.append(case["name"])
        print("     " + "; ".join(problems))
print(f"{len(failures)} of {len([c for c in cases if only in c['name']])} cases failed" +
      (": " + " ".join(failures) if failures else ""))
sys.exit(1 if failures else 0)
