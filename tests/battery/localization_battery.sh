#!/usr/bin/env bash
# The localization battery of doc/results-localization.md (issue "Localization that holds").
#   bash tests/battery/localization_battery.sh OUT CONFIG [CONFIG ...]
# Worlds: the authors' office (../shared/data/simp-office, imported; skipped when absent) and the
# built-in office with seeds $WORLD_SEEDS; per world, sequences with 15 % and 30 % changed objects
# (seeds $SEQ_SEEDS, $DURATION s, 4 cameras) and $KIDNAP_SEEDS kidnapped sequences; every sequence
# localized with every CONFIG (5000 particles, localization seeds $LOC_SEEDS), on the ground-truth
# map (GT) and, with BUILT=1, on a map built by simp-map from a coverage run (BUILT). Prints the
# tables of tests/battery/analyze_runs.py. Runs $JOBS processes at once. Same inputs, same output.
# SIM_CONFIG: a simp-sim .ini for the tracking and kidnapped sequences (e.g. exact odometry,
# `[odometry] noise_scale = 0`); sequences already in OUT are reused, so an OUT keeps the SIM_CONFIG
# it was first simulated with (OUT/sim_config.stamp, its text) and refuses another one.
set -euo pipefail
OUT=${1:?usage: localization_battery.sh OUT CONFIG [CONFIG ...]}; shift
CONFIGS=("$@")
B=${B:-build/bin}
WORLD_SEEDS=${WORLD_SEEDS:-"21 22 23"}
SEQ_SEEDS=${SEQ_SEEDS:-"1 2"}
LOC_SEEDS=${LOC_SEEDS:-"1"}
KIDNAP_SEEDS=${KIDNAP_SEEDS:-"1"}
DURATION=${DURATION:-120}
PARTICLES=${PARTICLES:-5000}
JOBS=${JOBS:-2}
BUILT=${BUILT:-0}
MAPPING=${MAPPING:-config_ini/mapping.ini}  # the [mapping] config of the BUILT maps
SIM_CONFIG=${SIM_CONFIG:-}                  # simp-sim --config of the tracking and kidnapped sequences
SIM_OPTS=${SIM_CONFIG:+--config $SIM_CONFIG}
AUTHORS=${AUTHORS:-../shared/data/simp-office}
mkdir -p "$OUT"
if [ -n "$SIM_CONFIG" ] && [ ! -f "$SIM_CONFIG" ]; then echo "error: SIM_CONFIG '$SIM_CONFIG': no such file" >&2; exit 2; fi
sim_text=$([ -n "$SIM_CONFIG" ] && cat "$SIM_CONFIG" || true)
if [ -f "$OUT/sim_config.stamp" ]; then
  [ "$(cat "$OUT/sim_config.stamp")" = "$sim_text" ] || {
    echo "error: $OUT was simulated with another SIM_CONFIG ($OUT/sim_config.stamp); give this one an OUT of its own" >&2; exit 2; }
else
  printf '%s' "$sim_text" > "$OUT/sim_config.stamp"
fi
worlds=()
if [ -d "$AUTHORS" ]; then
  [ -d "$OUT/w_authors" ] || "$B/simp-import-map" --simp-dir "$AUTHORS" --out "$OUT/w_authors" >/dev/null
  worlds+=(authors)
else
  echo "battery: $AUTHORS not found, the authors' office is skipped" >&2
fi
for ws in $WORLD_SEEDS; do
  [ -d "$OUT/w_office$ws" ] || "$B/simp-sim" world --builtin office --seed "$ws" --out "$OUT/w_office$ws" >/dev/null
  worlds+=("office$ws")
done

# job and run lists named after the configs: batteries with other configs may share OUT (and its
# sequences) at the same time
tag=$(for c in "${CONFIGS[@]}"; do basename "$c" .ini; done | paste -sd_)
jobs_file="$OUT/jobs_$tag.txt"; : > "$jobs_file"
runs_file="$OUT/runs_$tag.tsv"; : > "$runs_file"
for w in "${worlds[@]}"; do
  W="$OUT/w_$w"
  seqs=()
  for ch in 0.15 0.30; do
    for s in $SEQ_SEEDS; do
      Q="$OUT/q_${w}_c${ch}_s$s"
      [ -f "$Q/sequence.rawlog" ] || echo "$B/simp-sim sequence --world $W --seed $s --out $Q --duration $DURATION --changes $ch $SIM_OPTS >/dev/null 2>&1" >> "$OUT/sim_jobs.txt"
      seqs+=("$Q")
    done
  done
  for s in $KIDNAP_SEEDS; do
    Q="$OUT/k_${w}_s$s"
    [ -f "$Q/sequence.rawlog" ] || echo "$B/simp-sim sequence --world $W --seed $((s + 100)) --out $Q --duration $DURATION --changes 0.15 --kidnap-at $((DURATION / 2)) $SIM_OPTS >/dev/null 2>&1" >> "$OUT/sim_jobs.txt"
    seqs+=("$Q")
  done
  maps=("GT:$W")
  if [ "$BUILT" = 1 ]; then
    C="$OUT/cov_$w"; M="$OUT/m_$w"
    [ -f "$C/sequence.rawlog" ] || echo "$B/simp-sim sequence --world $W --seed 900 --out $C --duration 1200 --coverage >/dev/null 2>&1 && $B/simp-map --world $W --rawlog $C/sequence.rawlog --poses $C/groundtruth.tum --out $M --config $MAPPING >/dev/null 2>&1" >> "$OUT/sim_jobs.txt"
    maps+=("BUILT:$M")
  fi
  for cfg in "${CONFIGS[@]}"; do
    cname=$(basename "$cfg" .ini)
    for mp in "${maps[@]}"; do
      mname=${mp%%:*}; mdir=${mp#*:}
      for Q in "${seqs[@]}"; do
        for ls in $LOC_SEEDS; do
          O="$OUT/r_${cname}_${mname}_$(basename "$Q")_l$ls"
          kind=track; case $(basename "$Q") in k_*) kind=kidnap;; esac
          echo "$B/simp-localize --world $mdir --rawlog $Q/sequence.rawlog --out $O --config $cfg --particles $PARTICLES --seed $ls --quiet" >> "$jobs_file"
          printf '%s\t%s\t%s\n' "$O" "$Q" "$cname/$mname/$kind" >> "$runs_file"
        done
      done
    done
  done
done
[ -f "$OUT/sim_jobs.txt" ] && xargs -P "$JOBS" -I{} sh -c '{}' < "$OUT/sim_jobs.txt" && rm -f "$OUT/sim_jobs.txt"
start=$(date +%s)
xargs -P "$JOBS" -I{} sh -c '{}' < "$jobs_file"
echo "battery: $(wc -l < "$jobs_file") runs in $(( $(date +%s) - start )) s" >&2
SIMP_EVAL="$B/simp-eval" python3 tests/battery/analyze_runs.py "$runs_file"
