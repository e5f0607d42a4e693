#!/bin/bash
# Paired A/B of two builds' benchmarks on a machine whose speed drifts: N pairs of short runs, the
# two builds back to back in alternating order; per benchmark the median and quartiles of the
# ratio new / old of each pair (the pairing cancels the drift), and each build's median CPU time.
#   tests/benchmarks/paired_ab.sh OLD_BUILD NEW_BUILD [FILTER] [PAIRS]
# OLD_BUILD / NEW_BUILD: build directories (or copies of their bin/ and lib/): OLD's binary runs with
# LD_LIBRARY_PATH=OLD/lib so that it loads its own libraries. Keep a copy of the unchanged build
# (cp -a build/bin build/lib /tmp/before/) before rebuilding.
set -euo pipefail
OLD=${1:?old build dir}; NEW=${2:?new build dir}; FILTER=${3:-Simp_Tracking}; PAIRS=${4:-12}
for d in "$OLD" "$NEW"; do
  [ -x "$d/bin/simp-benchmarks" ] || { echo "paired_ab: $d/bin/simp-benchmarks not found" >&2; exit 2; }
done
tmp=$(mktemp); trap 'rm -f "$tmp"' EXIT
run() {  # build label pair
  LD_LIBRARY_PATH="$1/lib" "$1/bin/simp-benchmarks" --benchmark_filter="$FILTER" --benchmark_min_time=0.2 2>/dev/null |
    awk -v v="$2" -v p="$3" '/^BM_/ {print p, v, $1, $4}' >> "$tmp"
}
for p in $(seq "$PAIRS"); do
  if [ $((p % 2)) = 0 ]; then run "$OLD" old "$p"; run "$NEW" new "$p"; else run "$NEW" new "$p"; run "$OLD" old "$p"; fi
  echo "paired_ab: pair $p of $PAIRS" >&2
done
python3 - "$tmp" <<'PY'
import collections, statistics, sys
runs = collections.defaultdict(dict)
for line in open(sys.argv[1]):
    pair, build, name, cpu = line.split()
    runs[(name, pair)][build] = float(cpu)
by = collections.defaultdict(list)
for (name, _), t in runs.items():
    if 'old' in t and 'new' in t:
        by[name].append((t['old'], t['new']))
print("| benchmark | old median | new median | ratio new/old median (q25-q75) |")
print("| --- | --- | --- | --- |")
for name in sorted(by):
    r = sorted(n / o for o, n in by[name])
    print(f"| {name} | {statistics.median(o for o, _ in by[name]):.4g} | {statistics.median(n for _, n in by[name]):.4g} "
          f"| {statistics.median(r):.3f} ({r[len(r) // 4]:.3f}-{r[3 * len(r) // 4]:.3f}) |")
PY
