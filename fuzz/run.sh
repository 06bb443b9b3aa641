#!/usr/bin/env bash
# Runs each fuzz target for a bounded time and prints a table of executions
# and findings; exits 1 when any target found a crash, hang or runaway
# allocation (the input is kept in BUILD/fuzz-findings/NAME/).
#   fuzz/run.sh BUILD SECONDS fuzz_gmsh fuzz_png ...
# Each target starts from its committed seeds (fuzz/corpus/NAME, which also
# hold the inputs of fixed findings) and the corpus it grew in earlier runs
# (BUILD/fuzz-corpus/NAME), with the dictionary fuzz/NAME.dict.
set -uo pipefail
build=$1 seconds=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
# A slow input is a finding after 10 s; 1 GiB in one allocation is a runaway
# (the inputs are a few KiB). A fixed seed makes each run try the same mutations.
flags=(-max_total_time="$seconds" -seed=1 -timeout=10 -rss_limit_mb=2560 -malloc_limit_mb=1024 -print_final_stats=1)
failed=0
rows=()
for target in "$@"; do
  name=${target#fuzz_}
  corpus=$build/fuzz-corpus/$name findings=$build/fuzz-findings/$name log=$build/fuzz-logs/$name.log
  mkdir -p "$corpus" "$findings" "$(dirname "$log")"
  asan=${ASAN_OPTIONS:-}
  # assimp leaks a few KiB on some broken files (in its STL reader); not recoil's to fix.
  [[ $name == mesh_import ]] && asan=detect_leaks=0${asan:+:$asan}
  marker=$(mktemp)  # findings of earlier runs stay in $findings but are not counted again
  start=$(date +%s)
  ASAN_OPTIONS=$asan "$build/fuzz/$target" "${flags[@]}" -dict="$here/$name.dict" -artifact_prefix="$findings/" \
    "$corpus" "$here/corpus/$name" >"$log" 2>&1
  rc=$?
  elapsed=$(( $(date +%s) - start ))
  execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$')
  found=$(find "$findings" -type f -newer "$marker" | wc -l)
  rm -f "$marker"
  if [[ $rc -ne 0 || $found -ne 0 ]]; then
    failed=1
    echo "fuzz: $target failed (exit $rc); log: $log; findings in $findings:" >&2
    grep -m1 -E 'ERROR|SUMMARY|runtime error|deadly signal|out-of-memory|timeout' "$log" >&2
  fi
  rows+=("$(printf '%-18s %8s s %12s execs %8s crashes' "$target" "$elapsed" "${execs:-?}" "$found")")
done
printf '%s\n' "${rows[@]}"
exit $failed
