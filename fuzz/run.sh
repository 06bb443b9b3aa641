#!/usr/bin/env bash
# Runs each fuzz target and prints a table of executions and findings; exits
# 1 when any target found a crash, hang or runaway allocation (the input is
# kept in BUILD/fuzz-findings/NAME/).
#   fuzz/run.sh BUILD seconds=N fuzz_gmsh fuzz_png ...   explore for N s each
#   fuzz/run.sh BUILD runs=N fuzz_gmsh fuzz_png ...      replay N fixed mutations each
# Exploring starts from the committed seeds (fuzz/corpus/NAME, which also hold
# the inputs of fixed findings) and the corpus grown in earlier runs
# (BUILD/fuzz-corpus/NAME). Replaying starts from the seeds alone, with a
# fixed random seed and a count instead of a clock, so that it tries the same
# inputs on every machine: CI's smoke run can only fail on a change, never on luck
# (the import target's replays still differ with timing: docs/fuzzing.md).
set -uo pipefail
build=$1 limit=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
case $limit in
  seconds=*) stop=(-max_total_time="${limit#seconds=}") replay=0 ;;
  # Two things make libFuzzer's choices differ from run to run, so a replay
  # goes without both: comparison tracing feeds operand values, pointers
  # among them, back into the mutations, and the corpus is reloaded on a clock.
  runs=*) stop=(-runs="${limit#runs=}" -use_cmp=0 -reload=0) replay=1 ;;
  *) echo "fuzz/run.sh: the second argument is seconds=N or runs=N, not '$limit'" >&2; exit 2 ;;
esac
# A slow input is a finding after 10 s; 1 GiB in one allocation is a runaway (the inputs are a few KiB).
flags=("${stop[@]}" -seed=1 -timeout=10 -rss_limit_mb=2560 -malloc_limit_mb=1024 -print_final_stats=1)
failed=0
rows=()
for target in "$@"; do
  name=${target#fuzz_}
  corpus=$build/fuzz-corpus/$name findings=$build/fuzz-findings/$name log=$build/fuzz-logs/$name.log
  [[ $replay == 1 ]] && corpus=$(mktemp -d)  # what a replay adds is thrown away
  # The inputs are written under TMPDIR, and the readers parse that path.
  scratch=${TMPDIR:-/tmp}
  [[ $replay == 1 ]] && scratch=/tmp
  mkdir -p "$corpus" "$findings" "$(dirname "$log")"
  asan=${ASAN_OPTIONS:-}
  # assimp leaks a few KiB on some broken files (in its STL reader); not recoil's to fix.
  # It reads in a forked child, and a fork copies the parent's mapped memory, most
  # of which is ASan's quarantine of freed blocks (256 MiB by default).
  # The child also inherits libFuzzer's malloc hook, which would report assimp's
  # allocation of many GiB there as a finding: ASan refuses any allocation over
  # 1000 MiB first (-malloc_limit_mb is 1024), which ends the child only; in
  # the parent, recoil's own code, the refusal is a finding as before.
  [[ $name == mesh_import ]] && asan=detect_leaks=0:quarantine_size_mb=8:max_allocation_size_mb=1000${asan:+:$asan}
  marker=$(mktemp)  # findings of earlier runs stay in $findings but are not counted again
  start=$(date +%s)
  # libFuzzer writes what it finds into the first folder it is given: the
  # build's corpus (or a replay's throw-away one), never the committed seeds.
  inputs=("$corpus" "$here/corpus/$name")
  if [[ $replay == 1 ]]; then
    # libFuzzer takes a folder's files in the file system's listing order, which differs
    # between clones; a list in name order makes the replay the same everywhere.
    list=$(mktemp)
    find "$here/corpus/$name" -type f | LC_ALL=C sort | paste -sd, - >"$list"
    inputs=(-seed_inputs=@"$list" "$corpus")
  fi
  TMPDIR=$scratch ASAN_OPTIONS=$asan "$build/fuzz/$target" "${flags[@]}" -dict="$here/$name.dict" -artifact_prefix="$findings/" \
    "${inputs[@]}" >"$log" 2>&1
  rc=$?
  elapsed=$(( $(date +%s) - start ))
  execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$')
  found=$(find "$findings" -type f -newer "$marker" | wc -l)
  rm -f "$marker"
  [[ $replay == 1 ]] && rm -rf "$corpus" "$list"
  if [[ $rc -ne 0 || $found -ne 0 ]]; then
    failed=1
    echo "fuzz: $target failed (exit $rc); log: $log; findings in $findings:" >&2
    grep -m1 -E 'ERROR|SUMMARY|runtime error|deadly signal|out-of-memory|timeout' "$log" >&2
  fi
  rows+=("$(printf '%-18s %8s s %12s execs %8s crashes' "$target" "$elapsed" "${execs:-?}" "$found")")
done
printf '%s\n' "${rows[@]}"
exit $failed
