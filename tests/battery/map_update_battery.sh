#!/usr/bin/env bash
# The map-update battery of doc/mapping.md "Map update across sessions" (issue #16).
#   bash tests/battery/map_update_battery.sh OUT
# Per built-in office world (seeds $WORLD_SEEDS): a first coverage session builds M0 with simp-map;
# a second coverage session after --changes $CHANGES (and one after --changes 0) updates M0 with
# simp-map --update; simp-eval changes scores the change report against the simulator's truth
# (removed / moved matched through M0's objects, see doc/evaluation.md) and simp-eval map scores the
# updated map against the changed world Q/world. Prints one TSV row per world and run, then the
# means. Runs $JOBS worlds at a time (default 1; shared 2-core machine). Same inputs, same output.
# DURATION0: the first session (M0); DURATION: the sessions after the change (issue #16: 600-900 s).
set -euo pipefail
OUT=${1:?usage: map_update_battery.sh OUT}
B=${B:-build/bin}
WORLD_SEEDS=${WORLD_SEEDS:-"1 2 3 4 5 6 7 8"}
DURATION0=${DURATION0:-1200}  # one coverage round of the 10-room office (doc/simulator.md)
DURATION=${DURATION:-900}
CHANGES=${CHANGES:-0.3}
CONFIG=${CONFIG:-config_ini/mapping.ini}
CLASSES=${CLASSES:-"board,cabinet,desk,drawers,fire extinguisher,oven,potted plant,sink,sofa,table"}  # Table I
JOBS=${JOBS:-1}     # worlds processed at once (shared 2-core machine: at most 2)
STAGE=${STAGE:-all}   # data: only simulate and build M0; all: also update and score
LOCALIZE=${LOCALIZE:-0}  # 1: also localize on M and on Q/world (issue #16's last target)
mkdir -p "$OUT"
rows="$OUT/runs.jsonl"; : > "$rows"; : > "$OUT/localization.tsv"
one_world() {
  local ws=$1
  W="$OUT/w$ws"; Q1="$OUT/q1_w$ws"; M0="$OUT/m0_w$ws"
  [ -d "$W" ] || "$B/simp-sim" world --builtin office --seed "$ws" --out "$W" >/dev/null
  # Session 1: the map of an earlier visit.
  [ -f "$Q1/sequence.rawlog" ] || "$B/simp-sim" sequence --world "$W" --seed "$((ws + 100))" --out "$Q1" \
      --duration "$DURATION0" --coverage >/dev/null
  [ -f "$M0/objects.json" ] || "$B/simp-map" --world "$W" --rawlog "$Q1/sequence.rawlog" --poses "$Q1/groundtruth.tum" \
      --out "$M0" --config "$CONFIG" >/dev/null
  for ch in "$CHANGES" 0; do
    Q="$OUT/q2_w${ws}_c$ch"; M="$OUT/m_w${ws}_c$ch"
    [ -f "$Q/sequence.rawlog" ] || "$B/simp-sim" sequence --world "$W" --seed "$((ws + 200))" --out "$Q" \
        --duration "$DURATION" --coverage --changes "$ch" >/dev/null
    [ "$STAGE" = all ] || continue
    "$B/simp-map" --world "$W" --rawlog "$Q/sequence.rawlog" --poses "$Q/groundtruth.tum" --update "$M0" --out "$M" \
        --config "$CONFIG" > "$M.log"
    ev=( "$B/simp-eval" changes --truth "$Q/changes.json" --report "$M/changes.json" --before-world "$W"
         --before-map "$M0" --classes "$CLASSES" --json )
    all=$("${ev[@]}" | tail -n 1)
    vis=$("${ev[@]}" --visited "$Q/groundtruth.tum" | tail -n 1)
    mp=$("$B/simp-eval" map --gt "$Q/world" --map "$M" --classes "$CLASSES" --json | tail -n 1)
    st=$(python3 "$(dirname "$0")/stale_objects.py" "$M/objects.json" "$Q/world/objects.json" "$Q/changes.json" "$CLASSES")
    echo "{\"world\": $ws, \"changes\": $ch, \"all\": $all, \"visited\": $vis, \"map\": $mp, \"stale\": $st}" >> "$rows"
  done
  [ "$STAGE" = all ] && [ "$LOCALIZE" = 1 ] || return 0
  # Localization (default method and config) on the updated map M and on the changed ground truth
  # Q/world: two 120 s sequences in Q/world (seeds 300 + S, 400 + S), localization seed 1.
  Q="$OUT/q2_w${ws}_c$CHANGES"; M="$OUT/m_w${ws}_c$CHANGES"
  for s in 300 400; do
    L="$OUT/loc_w${ws}_s$s"
    [ -f "$L/sequence.rawlog" ] || "$B/simp-sim" sequence --world "$Q/world" --seed $((s + ws)) --duration 120 --out "$L" >/dev/null
    for mp in "M:$M" "GT:$Q/world"; do
      O="$OUT/loc_w${ws}_s${s}_${mp%%:*}"
      "$B/simp-localize" --world "${mp#*:}" --rawlog "$L/sequence.rawlog" --out "$O" --seed 1 --quiet >/dev/null
      ok=$("$B/simp-eval" traj --gt "$L/groundtruth.tum" --est "$O/estimate.tum" --json | tail -n 1 |
           python3 -c 'import json,sys; print(int(json.load(sys.stdin)["success"]))')
      printf '%s\t%s\t%s\t%s\n' "$ws" "$s" "${mp%%:*}" "$ok" >> "$OUT/localization.tsv"
    done
  done
}
running=0
for ws in $WORLD_SEEDS; do  # $JOBS worlds at once; each appends its rows (sorted when summarized)
  one_world "$ws" &
  running=$((running + 1))
  if [ "$running" -ge "$JOBS" ]; then wait -n; running=$((running - 1)); fi
done
wait
[ "$STAGE" = all ] || exit 0
python3 - "$rows" <<'PY'
import json, sys
runs = sorted((json.loads(l) for l in open(sys.argv[1])), key=lambda r: (r["world"], r["changes"]))
kinds = ("removed", "moved", "added")
print("world changes | scope   | removed P/R (true) | moved P/R (true) | added P/R (true) | map IoU Pr Rc")
for r in runs:
    for scope in ("all", "visited"):
        e = r[scope]
        cells = ["%.2f/%.2f (%d)" % (e[k]["precision"], e[k]["recall"], e[k]["n_true"]) for k in kinds]
        print("%5d %7s | %-7s | %s | %.3f %.3f %.3f" % (r["world"], r["changes"], scope, " | ".join(cells),
                                                     r["map"]["iou"], r["map"]["precision"], r["map"]["recall"]))
for ch in sorted({r["changes"] for r in runs}):
    rs = [r for r in runs if r["changes"] == ch]
    print("\n--changes %s, %d worlds (pooled counts):" % (ch, len(rs)))
    for scope in ("all", "visited"):
        parts = []
        for k in kinds:
            t = sum(r[scope][k]["n_true"] for r in rs); rep = sum(r[scope][k]["n_reported"] for r in rs)
            c = sum(r[scope][k]["n_correct"] for r in rs)
            parts.append("%s P %.3f R %.3f (%d true, %d reported, %d correct)" % (k, c / rep if rep else 1, c / t if t else 1, t, rep, c))
        print("  %-7s: %s" % (scope, "; ".join(parts)))
    m = lambda key: sum(r["map"][key] for r in rs) / len(rs)
    print("  updated map vs Q/world (mean over worlds): IoU %.3f, Pr %.3f, Rc %.3f" % (m("iou"), m("precision"), m("recall")))
    ns, nm = sum(r["stale"]["n_stale"] for r in rs), sum(r["stale"]["n_map"] for r in rs)
    print("  stale objects (tests/battery/stale_objects.py): %d of %d (%.1f %%), per world %s" %
          (ns, nm, 100.0 * ns / nm if nm else 0, [r["stale"]["n_stale"] for r in rs]))
    if float(ch) == 0:
        false = [sum(r["all"][k]["n_reported"] for k in kinds) for r in rs]
        print("  false changes per world (Table I classes): %s, max %d" % (false, max(false)))
PY
if [ "$LOCALIZE" = 1 ]; then
  awk -F'\t' '{n[$3]++; k[$3]+=$4} END {for (m in n) printf "localization success on %s: %d of %d sequences\n", (m == "M" ? "the updated map M" : "Q/world"), k[m], n[m]}' \
      "$OUT/localization.tsv" | sort
fi
