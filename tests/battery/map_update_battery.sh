#!/usr/bin/env bash
# The map-update battery of doc/mapping.md "Map update across sessions" (issue #16).
#   bash tests/battery/map_update_battery.sh OUT
# Per built-in office world (seeds $WORLD_SEEDS): a first coverage session builds M0 with simp-map;
# a second coverage session after --changes $CHANGES (and one after --changes 0) updates M0 with
# simp-map --update; simp-eval changes scores the change report against the simulator's truth
# (removed / moved matched through M0's objects, see doc/evaluation.md) and simp-eval map scores the
# updated map against the changed world Q/world. Prints one TSV row per world and run, then the
# means. Runs one process at a time (shared 2-core machine). Same inputs, same output.
set -euo pipefail
OUT=${1:?usage: map_update_battery.sh OUT}
B=${B:-build/bin}
WORLD_SEEDS=${WORLD_SEEDS:-"1 2 3 4 5 6 7 8"}
DURATION=${DURATION:-600}
CHANGES=${CHANGES:-0.3}
CONFIG=${CONFIG:-config_ini/mapping.ini}
CLASSES=${CLASSES:-"board,cabinet,desk,drawers,fire extinguisher,oven,potted plant,sink,sofa,table"}  # Table I
STAGE=${STAGE:-all}   # data: only simulate and build M0; all: also update and score
mkdir -p "$OUT"
rows="$OUT/rows.tsv"
printf 'world\trun\tn_true\tn_report\trm_P\trm_R\tmv_P\tmv_R\tad_P\tad_R\tfalse_changes\tiou\tprecision\trecall\n' > "$rows"
for ws in $WORLD_SEEDS; do
  W="$OUT/w$ws"; Q1="$OUT/q1_w$ws"; M0="$OUT/m0_w$ws"
  [ -d "$W" ] || "$B/simp-sim" world --builtin office --seed "$ws" --out "$W" >/dev/null
  # Session 1: the map of an earlier visit.
  [ -f "$Q1/sequence.rawlog" ] || "$B/simp-sim" sequence --world "$W" --seed "$((ws + 100))" --out "$Q1" \
      --duration "$DURATION" --coverage >/dev/null
  [ -f "$M0/objects.json" ] || "$B/simp-map" --world "$W" --rawlog "$Q1/sequence.rawlog" --poses "$Q1/groundtruth.tum" \
      --out "$M0" --config "$CONFIG" >/dev/null
  for ch in "$CHANGES" 0; do
    Q="$OUT/q2_w${ws}_c$ch"; M="$OUT/m_w${ws}_c$ch"
    [ -f "$Q/sequence.rawlog" ] || "$B/simp-sim" sequence --world "$W" --seed "$((ws + 200))" --out "$Q" \
        --duration "$DURATION" --coverage --changes "$ch" >/dev/null
    [ "$STAGE" = all ] || continue
    "$B/simp-map" --world "$W" --rawlog "$Q/sequence.rawlog" --poses "$Q/groundtruth.tum" --update "$M0" --out "$M" \
        --config "$CONFIG" > "$M.log"
    ev=$("$B/simp-eval" changes --truth "$Q/changes.json" --report "$M/changes.json" --before-world "$W" \
        --before-map "$M0" --classes "$CLASSES" --json | tail -n 1)
    mp=$("$B/simp-eval" map --gt "$Q/world" --map "$M" --classes "$CLASSES" --json | tail -n 1)
    python3 - "$ws" "$ch" "$ev" "$mp" >> "$rows" <<'PY'
import json, sys
ws, ch, ev, mp = sys.argv[1:5]
e, m = json.loads(ev), json.loads(mp)
kinds = ("removed", "moved", "added")
# Scored entries (Table I classes; truth relative to M0, doc/evaluation.md).
t = sum(e[k]["n_true"] for k in kinds)
r = [None] * sum(e[k]["n_reported"] for k in kinds)
f = lambda v: "nan" if v is None else "%.3f" % v
print("\t".join([ws, ch, str(t), str(len(r))] + [f(e[k][q]) for k in kinds for q in ("precision", "recall")]
                + [str(len(r)) if float(ch) == 0 else "-", f(m["iou"]), f(m["precision"]), f(m["recall"])]))
PY
  done
done
[ "$STAGE" = all ] || exit 0
cat "$rows"
python3 - "$rows" <<'PY'
import csv, sys, math
rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
for run in sorted({r["run"] for r in rows}):
    rs = [r for r in rows if r["run"] == run]
    def mean(k):
        v = [float(r[k]) for r in rs if r[k] not in ("nan", "-")]
        return sum(v) / len(v) if v else float("nan")
    keys = ["rm_P", "rm_R", "mv_P", "mv_R", "ad_P", "ad_R", "iou", "precision", "recall"]
    extra = ""
    if float(run) == 0:
        extra = "  false changes per world: max %d, mean %.2f" % (max(int(r["false_changes"]) for r in rs), mean("false_changes"))
    print("changes %s (%d worlds): " % (run, len(rs)) + ", ".join("%s %.3f" % (k, mean(k)) for k in keys) + extra)
PY
