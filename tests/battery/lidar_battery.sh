#!/usr/bin/env bash
# LiDAR in localization (doc/lidar.md "Results"): on the built-in office with seeds $WORLD_SEEDS (and the
# authors' office when AUTHORS_DIR exists), one sequence per world with $CHANGES changed objects,
# $DURATION s, 4 cameras and the simulated LiDAR (--lidar); each localized globally with every
# method of $METHODS (config_ini/simp.ini, 5000 particles, seed 1) and scored with simp-eval traj.
# Runs one process at a time. Prints one TSV row per run and a summary per method.
#   bash tests/battery/lidar_battery.sh OUT
set -euo pipefail
OUT=${1:?usage: lidar_battery.sh OUT}
B=${B:-build/bin}
WORLD_SEEDS=${WORLD_SEEDS:-"21 22 23 24 25 26"}
METHODS=${METHODS:-"simp+lidar lidar simp"}
CHANGES=${CHANGES:-0.3}
DURATION=${DURATION:-120}
SEQ_SEED=${SEQ_SEED:-1}
AUTHORS_DIR=${AUTHORS_DIR:-../shared/data/simp-office}
CONFIG=${CONFIG:-config_ini/simp.ini}
mkdir -p "$OUT"
worlds=()
for ws in $WORLD_SEEDS; do
  [ -d "$OUT/w_office$ws" ] || "$B/simp-sim" world --builtin office --seed "$ws" --out "$OUT/w_office$ws" >/dev/null
  worlds+=("office$ws")
done
if [ -d "$AUTHORS_DIR" ]; then
  [ -d "$OUT/w_authors" ] || "$B/simp-import-map" --simp-dir "$AUTHORS_DIR" --out "$OUT/w_authors" >/dev/null
  worlds+=(authors)
fi
runs="$OUT/runs.tsv"
printf "world\tmethod\tsuccess\tconverged_s\tate_m\tate_rad\tseconds\n" > "$runs"
for w in "${worlds[@]}"; do
  W="$OUT/w_$w"; Q="$OUT/q_$w"
  [ -f "$Q/sequence.rawlog" ] || "$B/simp-sim" sequence --world "$W" --seed "$SEQ_SEED" --out "$Q" --duration "$DURATION" \
    --changes "$CHANGES" --lidar >/dev/null 2>&1
  for m in $METHODS; do
    O="$OUT/o_${w}_${m}"
    t0=$(date +%s.%N)
    "$B/simp-localize" --world "$W" --rawlog "$Q/sequence.rawlog" --out "$O" --config "$CONFIG" --method "$m" \
      --seed 1 --quiet >/dev/null 2>&1
    t1=$(date +%s.%N)
    json=$("$B/simp-eval" traj --gt "$Q/groundtruth.tum" --est "$O/estimate.tum" --json 2>/dev/null | tail -1 || echo '{}')
    python3 - "$w" "$m" "$json" "$t0" "$t1" >> "$runs" <<'PY'
import json, sys
w, m, j, t0, t1 = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
try:
    d = json.loads(j)
except ValueError:
    d = {}
f = lambda k, fmt: (fmt % d[k]) if d.get(k) is not None else "-"
print("\t".join([w, m, str(d.get("success", False)).lower(), f("convergence_time_s", "%.1f"), f("ate_trans_m", "%.3f"),
                 f("ate_rot_rad", "%.3f"), "%.0f" % (t1 - t0)]))
PY
    tail -1 "$runs"
  done
done
python3 - "$runs" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
for m in dict.fromkeys(r["method"] for r in rows):
    rs = [r for r in rows if r["method"] == m]
    ok = [r for r in rs if r["success"] == "true"]
    ates = [float(r["ate_m"]) for r in ok if r["ate_m"] != "-"]
    conv = [float(r["converged_s"]) for r in ok if r["converged_s"] != "-"]
    print("%-11s success %d/%d, mean ATE of successes %s m, mean convergence %s s" % (
        m, len(ok), len(rs), "%.3f" % (sum(ates) / len(ates)) if ates else "-",
        "%.1f" % (sum(conv) / len(conv)) if conv else "-"))
PY
