#!/usr/bin/env bash
# Scan-matched poses and the maps built from them (doc/lidar.md section 2, issue #17): per world (the
# built-in office with seeds $WORLD_SEEDS and the authors' office, imported; skipped when $AUTHORS is
# absent) one coverage run of $DURATION s with the simulated LiDAR and no change (seed $SEQ_SEED);
# simp-icp-poses from the true start; simp-map with the true poses (KP) and with the ICP poses (ICP);
# simp-eval map of both on the ten Table I classes. Prints one row per world and the pooled means.
# Runs $JOBS worlds at once. Same inputs, same output.
#   bash tests/battery/icp_battery.sh OUT
set -euo pipefail
OUT=${1:?usage: icp_battery.sh OUT}
B=${B:-build/bin}
WORLD_SEEDS=${WORLD_SEEDS:-"1 2 3 4 5 6"}
SEQ_SEED=${SEQ_SEED:-3}
DURATION=${DURATION:-900}
JOBS=${JOBS:-2}
AUTHORS=${AUTHORS:-../shared/data/simp-office}
SIMCFG=${SIMCFG:-config_ini/sim.ini}  # the simulator's .ini (e.g. another [trajectory] coverage)
CLASSES="sink,oven,board,table,potted plant,drawers,sofa,cabinet,fire extinguisher,desk"
mkdir -p "$OUT"
worlds=()
for ws in $WORLD_SEEDS; do
  [ -d "$OUT/w_office$ws" ] || "$B/simp-sim" world --builtin office --seed "$ws" --out "$OUT/w_office$ws" >/dev/null
  worlds+=("office$ws")
done
if [ -d "$AUTHORS" ]; then
  [ -d "$OUT/w_authors" ] || "$B/simp-import-map" --simp-dir "$AUTHORS" --out "$OUT/w_authors" >/dev/null
  worlds+=(authors)
else
  echo "battery: $AUTHORS not found, the authors' office is skipped" >&2
fi
one_world() {
  local w=$1 W="$OUT/w_$1" Q="$OUT/q_$1"
  [ -f "$Q/sequence.rawlog" ] || "$B/simp-sim" sequence --world "$W" --seed "$SEQ_SEED" --coverage --duration "$DURATION" \
      --lidar --config "$SIMCFG" --out "$Q" >/dev/null 2>&1
  local start
  start=$(grep -v '^#' "$Q/groundtruth.tum" | head -1 | python3 -c "import sys,math; t,x,y,z,qx,qy,qz,qw=map(float,sys.stdin.read().split()); print(f'{x},{y},{2*math.atan2(qz,qw)}')")
  "$B/simp-icp-poses" --world "$W" --rawlog "$Q/sequence.rawlog" --initial-pose "$start" --out "$OUT/icp_$w.tum" \
      --gt "$Q/groundtruth.tum" > "$OUT/icp_$w.log" 2>&1
  for p in kp icp; do
    local poses="$Q/groundtruth.tum"; [ $p = icp ] && poses="$OUT/icp_$w.tum"
    "$B/simp-map" --world "$W" --rawlog "$Q/sequence.rawlog" --poses "$poses" --out "$OUT/m_${p}_$w" \
        --config config_ini/mapping.ini > "$OUT/m_${p}_$w.log" 2>&1
    "$B/simp-eval" map --gt "$W" --map "$OUT/m_${p}_$w" --classes "$CLASSES" --json | tail -1 > "$OUT/eval_${p}_$w.json"
  done
}
export -f one_world
export OUT B SEQ_SEED DURATION CLASSES SIMCFG
printf '%s\n' "${worlds[@]}" | xargs -P "$JOBS" -I{} bash -c 'one_world {}'
python3 - "$OUT" "${worlds[@]}" <<'PY'
import json, re, sys
out, worlds = sys.argv[1], sys.argv[2:]
print("| world | ICP ATE m | KP IoU / Pr / Rc | ICP IoU / Pr / Rc | IoU KP - ICP |")
print("|---|---:|---|---|---:|")
tot = {"kp": [0, 0, 0], "icp": [0, 0, 0]}; ates = []
for w in worlds:
    log = open(f"{out}/icp_{w}.log").read()
    m = re.search(r"ATE[^0-9]*([0-9.]+) m", log) or re.search(r"([0-9.]+) m", log)
    ate = float(m.group(1)) if m else float("nan"); ates.append(ate)
    r = {p: json.load(open(f"{out}/eval_{p}_{w}.json")) for p in ("kp", "icp")}
    for p in r:
        for i, k in enumerate(("iou", "precision", "recall")): tot[p][i] += r[p][k]
    f = lambda d: f"{d['iou']:.3f} / {d['precision']:.3f} / {d['recall']:.3f}"
    print(f"| {w} | {ate:.3f} | {f(r['kp'])} | {f(r['icp'])} | {r['kp']['iou'] - r['icp']['iou']:.3f} |")
n = len(worlds)
g = lambda p: " / ".join(f"{v / n:.3f}" for v in tot[p])
print(f"| mean of {n} | {sum(ates) / n:.3f} (max {max(ates):.3f}) | {g('kp')} | {g('icp')} | {(tot['kp'][0] - tot['icp'][0]) / n:.3f} |")
PY
