#!/usr/bin/env bash
# LiDAR in localization (doc/lidar.md "Results"): the built-in office with seeds $WORLD_SEEDS and the
# authors' office (imported; skipped when $AUTHORS is absent); per world, sequences with seeds $SEQ_SEEDS,
# $CHANGES changed objects, $DURATION s, the simulated LiDAR (--lidar) and $CAMERAS cameras (a copy of
# config_ini/sim.ini with [cameras] count changed; 4 = the shipped rig); each localized globally with every
# method of $METHODS ($CONFIG, $PARTICLES particles, seed 1). Scored by tests/battery/analyze_runs.py
# (simp-eval traj), grouped as method/cameras; --runs prints one row per run. KIDNAP_AT=SEC: the sequences
# teleport the robot once at SEC (simp-sim --kidnap-at; directories q_..._k); the kidnap columns score the
# recovery.
# Runs $JOBS processes at once. Same inputs, same output.
#   bash tests/battery/lidar_battery.sh OUT
set -euo pipefail
OUT=${1:?usage: lidar_battery.sh OUT}
B=${B:-build/bin}
WORLD_SEEDS=${WORLD_SEEDS:-"21 22 23 24 25 26"}
SEQ_SEEDS=${SEQ_SEEDS:-"1"}
METHODS=${METHODS:-"simp+lidar lidar"}
CHANGES=${CHANGES:-0.3}
DURATION=${DURATION:-120}
CAMERAS=${CAMERAS:-4}
PARTICLES=${PARTICLES:-5000}
JOBS=${JOBS:-2}
AUTHORS=${AUTHORS:-../shared/data/simp-office}
CONFIG=${CONFIG:-config_ini/simp.ini}
KIDNAP_AT=${KIDNAP_AT:-}
TAG=${TAG:-$(basename "$CONFIG" .ini)}
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
simcfg="$OUT/sim_cam$CAMERAS.ini"
sed "/^\[cameras\]/,/^\[/ s/^count = .*/count = $CAMERAS/" config_ini/sim.ini > "$simcfg"
grep -q "^count = $CAMERAS\$" "$simcfg" || { echo "battery: could not set [cameras] count in $simcfg" >&2; exit 1; }

sim_jobs="$OUT/sim_jobs.txt"; : > "$sim_jobs"
jobs_file="$OUT/jobs_$TAG.txt"; : > "$jobs_file"
runs_file="$OUT/runs_$TAG.tsv"; : > "$runs_file"
for w in "${worlds[@]}"; do
  for s in $SEQ_SEEDS; do
    Q="$OUT/q_${w}_cam${CAMERAS}_s$s${KIDNAP_AT:+_k}"
    [ -f "$Q/sequence.rawlog" ] || echo "$B/simp-sim sequence --world $OUT/w_$w --seed $s --out $Q --config $simcfg --duration $DURATION --changes $CHANGES --lidar ${KIDNAP_AT:+--kidnap-at $KIDNAP_AT} >/dev/null 2>&1" >> "$sim_jobs"
    for m in $METHODS; do
      O="$OUT/r_${TAG}_${m}_$(basename "$Q")"
      echo "$B/simp-localize --world $OUT/w_$w --rawlog $Q/sequence.rawlog --out $O --config $CONFIG --method '$m' --particles $PARTICLES --seed 1 --quiet >/dev/null 2>&1" >> "$jobs_file"
      printf '%s\t%s\t%s\n' "$O" "$Q" "$TAG/$m/cam$CAMERAS" >> "$runs_file"
    done
  done
done
xargs -P "$JOBS" -I{} sh -c '{}' < "$sim_jobs"
start=$(date +%s)
xargs -P "$JOBS" -I{} sh -c '{}' < "$jobs_file"
echo "battery: $(wc -l < "$jobs_file") runs in $(( $(date +%s) - start )) s" >&2
SIMP_EVAL="$B/simp-eval" python3 tests/battery/analyze_runs.py "$runs_file" --runs
