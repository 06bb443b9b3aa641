#!/usr/bin/env bash
# The render farm test: a real single-node Slurm (single-node.sh) runs a 7-item recoil batch as a
# 3-task array (recoil-array.sbatch); every item must come out exactly once, from task index mod 3.
#   farm/slurm/test-farm.sh [RECOIL]   RECOIL: the recoil binary (default: env RECOIL, else build/recoil)
# Needs root and the farm packages (bash scripts/install-deps.sh --farm); make test-farm does both.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
recoil=${1:-${RECOIL:-$root/build/recoil}}
shards=3

fail() { echo "test-farm: FAIL: $*" >&2; exit 1; }
# The Slurm daemons run as root (SlurmUser=root), which keeps the cluster free of any account setup.
[[ $(id -u) -eq 0 ]] || fail "needs root, to run the Slurm daemons"
[[ -x $recoil ]] || fail "no recoil binary at $recoil (make build)"
# The jobs start in another folder, so they need the binary's absolute path.
recoil=$(realpath "$recoil")
"$recoil" batch --help >/dev/null 2>&1 || fail "$recoil has no batch command"

# Mesh and the item folder recoil must name it; the two Wuson stems check that every shard
# makes the same names unique, although each one runs only its own items.
items=(
  /usr/share/assimp/models/OFF/Cube.off Cube
  /usr/share/assimp/models/PLY/Wuson.ply Wuson
  /usr/share/assimp/models/OFF/Wuson.off Wuson-2
  /usr/share/assimp/models/STL/Spider_binary.stl Spider_binary
  /usr/share/assimp/models/STL/sphereWithHole.stl sphereWithHole
  "$root/assets/meshes/bunny.obj" bunny
  /usr/share/assimp/models/PLY/cube_binary.ply cube_binary
)

work=$(mktemp -d "${TMPDIR:-/tmp}/recoil-farm.XXXXXX")
# munged refuses a socket inside a folder that other users cannot enter, and mktemp makes it private.
chmod 755 "$work"
passed=
finish() {
  bash "$here/single-node.sh" stop "$work/slurm" || true
  # A failed or interrupted run keeps its folder: the task logs and the daemons' logs say what went wrong.
  if [[ -n $passed ]]; then rm -rf "$work"; else echo "test-farm: logs kept in $work" >&2; fi
}
trap finish EXIT

{
  echo "["
  for ((i = 0; i < ${#items[@]}; i += 2)); do
    [[ -r ${items[i]} ]] || fail "test mesh ${items[i]} missing (bash scripts/install-deps.sh)"
    sep=,
    [[ $((i + 2)) -lt ${#items[@]} ]] || sep=
    printf '  {"mesh": "%s", "mode": "turntable", "turn-frames": 2, "resolution": "64x48"}%s\n' "${items[i]}" "$sep"
  done
  echo "]"
} >"$work/manifest.json"
printf '%s\n' "${items[@]}" | paste - - >"$work/expected.tsv"

bash "$here/single-node.sh" start "$work/slurm"
export SLURM_CONF=$work/slurm/slurm.conf
mkdir -p "$work/logs"
cd "$work"

echo "test-farm: sbatch --array=0-$((shards - 1)) --wait recoil-array.sbatch ($(wc -l <expected.tsv) items)"
# --time caps a hung render; timeout caps a job that never gets scheduled at all.
sbatch_status=0
RECOIL=$recoil timeout 300 sbatch --array=0-$((shards - 1)) --wait --time=5 --quiet \
  --output="$work/logs/task-%a.out" --error="$work/logs/task-%a.err" \
  "$here/recoil-array.sbatch" "$work/manifest.json" "$work/out" || sbatch_status=$?
[[ $sbatch_status -eq 0 ]] || echo "test-farm: sbatch --wait exited $sbatch_status (a task failed or timed out)" >&2

python3 - "$work" "$shards" "$sbatch_status" <<'PY'
import json, pathlib, sys

work, shards, sbatch_status = pathlib.Path(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
out = work / "out"
expected = [line.split("\t") for line in (work / "expected.tsv").read_text().splitlines()]
errors = []

batch = json.loads((out / "batch.json").read_text()) if (out / "batch.json").is_file() else {"items": []}
names = {i["index"]: i["name"] for i in batch["items"]}
if not names:
    errors.append(f"{out}/batch.json is missing or lists no items")

# Every "item" event of every task's JSON log, with the task that wrote it.
events = {}
for task in range(shards):
    log = work / "logs" / f"task-{task}.err"
    if not log.is_file():
        errors.append(f"task {task} wrote no log ({log})")
        continue
    for line in log.read_text().splitlines():
        try:
            event = json.loads(line)
        except ValueError:
            continue
        if isinstance(event, dict) and event.get("event") == "item":
            events.setdefault(event.get("index"), []).append((task, event))

rows = []
for index, (mesh, name) in enumerate(expected):
    if names.get(index) != name:
        errors.append(f"item {index} ({mesh}): batch.json names it {names.get(index)!r}, expected {name!r}")
    record_path = out / name / "item.json"
    record = json.loads(record_path.read_text()) if record_path.is_file() else {}
    if not record:
        errors.append(f"item {index} {name}: no {record_path}")
    elif record.get("status") != "succeeded":
        errors.append(f"item {index} {name}: {record_path} says {record.get('status')!r}: {record.get('message', '')!r}")
    elif record.get("index") != index:
        errors.append(f"item {index} {name}: {record_path} has index {record.get('index')}")
    frames = len(list((out / name).glob("*.png")))
    if record.get("status") == "succeeded" and frames == 0:
        errors.append(f"item {index} {name}: succeeded but {out / name} holds no PNG frame")
    seen = events.get(index, [])
    if len(seen) != 1:
        errors.append(f"item {index} {name}: {len(seen)} 'item' log lines (tasks {[t for t, _ in seen]}), expected 1")
    for task, event in seen:
        if task != index % shards:
            errors.append(f"item {index} {name}: ran in task {task}, expected task {index % shards} (index mod {shards})")
        if event.get("shard") != f"{task}/{shards}" or event.get("name") != name or event.get("status") != "succeeded":
            errors.append(f"item {index} {name}: task {task} logged {json.dumps(event)}")
    task, event = seen[0] if seen else (None, {})
    rows.append((index, name, "-" if task is None else task, record.get("status", "missing"),
                 event.get("seconds", 0.0), frames))
for index in sorted(set(events) - set(range(len(expected))), key=str):
    errors.append(f"log lines for item {index}, which the manifest does not have")

print(f"{'index':>5}  {'item':<16} {'task':>4}  {'status':<10} {'seconds':>7}  frames")
for index, name, task, status, seconds, frames in rows:
    print(f"{index:>5}  {name:<16} {task:>4}  {status:<10} {seconds:>7.2f}  {frames:>6}")
if sbatch_status != 0:
    errors.append(f"sbatch --wait exited {sbatch_status}")
if errors:
    print("\n".join(["test-farm: FAIL:"] + [f"  {e}" for e in errors]), file=sys.stderr)
    sys.exit(1)
print(f"test-farm: ok: {len(expected)} items, each exactly once, in {shards} Slurm array tasks")
PY
passed=1
