#!/usr/bin/env bash
# Peak RSS of every reader app of untrusted files on tiny valid and hostile inputs, against the same
# app's --help (a process that only loads MRPT's and the project's libraries: the constant of
# "constant + O(N)"). Issue #14; figures in doc/fuzzing.md "Peak memory of every reader app".
# Usage: tests/fuzz/measure_app_rss.sh BIN_DIR OUT      (prints: app, input, bytes, peak KB, over --help KB, exit)
set -uo pipefail
bin="$(cd "$1" && pwd)"; out="$2"
src="$(cd "$(dirname "$0")/../.." && pwd)"
mkdir -p "$out"; cd "$out"
peak() {  # app input-label input-bytes command...
  local app=$1 label=$2 bytes=$3; shift 3
  /usr/bin/time -o rss.tmp -f '%M %x' "$@" > /dev/null 2>&1
  read -r kb rc < <(tail -n 1 rss.tmp)
  echo "$app $label $bytes $kb $((kb - ${base[$app]})) $rc"
}
declare -A base
apps=(simp-export-detections simp-localize simp-map simp-icp-poses simp-export-map simp-import-map simp-eval
      simp-import-omni3d simp-import-ros-detections)
for a in "${apps[@]}"; do
  /usr/bin/time -o rss.tmp -f '%M' "$bin/$a" --help > /dev/null 2>&1
  base[$a]=$(tail -n 1 rss.tmp); echo "$a --help 0 ${base[$a]} 0 0"
done
# Tiny valid inputs: a 50 m^2 world, 2 s of sequence with LiDAR.
[ -d W ] || "$bin/simp-sim" world --builtin office --seed 1 --size-m2 50 --out W > /dev/null
[ -d Q ] || "$bin/simp-sim" sequence --world W --seed 1 --duration 2 --lidar --out Q > /dev/null
[ -d D ] || "$bin/simp-export-map" --world W --out D > /dev/null
# Hostile inputs: every saved fuzz finding and crafted rawlog (tests/data/fuzz_regressions/rawlog:
# the largest peak is printed), 1 MB of random bytes, a LiDAR scan claiming 2^26 ranges.
head -c 1000000 /dev/urandom > random.rawlog
python3 - "$out/Q/sequence.rawlog" "$out/lidar-2e26.rawlog" <<'P'
import sys
b = bytearray(open(sys.argv[1], 'rb').read())
i = b.index(b'mrpt::poses::CPose3D') + len('mrpt::poses::CPose3D') + 1 + 96 + 1  # MRPT 2.5: the scan size
b[i:i+4] = (1 << 26).to_bytes(4, 'little')
open(sys.argv[2], 'wb').write(b)
P
sz() { stat -c %s "$1"; }
# simp-icp-poses starts at the true first pose (x,y from the TUM line, phi = 2 atan2(qz, qw)).
start=$(awk 'NR==2{printf "%s,%s,%.6f", $2, $3, 2*atan2($7, $8)}' Q/groundtruth.tum)
rawlog_apps() {  # label file
  peak simp-export-detections "$1" "$(sz "$2")" "$bin/simp-export-detections" --rawlog "$2" --out-csv x.csv
  peak simp-localize "$1" "$(sz "$2")" "$bin/simp-localize" --world W --rawlog "$2" --out O --quiet
  peak simp-map "$1" "$(sz "$2")" "$bin/simp-map" --world W --rawlog "$2" --poses Q/groundtruth.tum --out M
  peak simp-icp-poses "$1" "$(sz "$2")" "$bin/simp-icp-poses" --world W --rawlog "$2" --initial-pose "$start" --out p.tum
}
rawlog_apps tiny Q/sequence.rawlog
rawlog_apps random random.rawlog
rawlog_apps lidar-2e26 lidar-2e26.rawlog
for f in "$src"/tests/data/fuzz_regressions/rawlog/*; do rawlog_apps "$(basename "$f")" "$f"; done
peak simp-export-map tiny "$(du -sb W | cut -f1)" "$bin/simp-export-map" --world W --gridmap x.gridmap
peak simp-import-map tiny "$(du -sb D | cut -f1)" "$bin/simp-import-map" --simp-dir D --out W2
peak simp-eval tiny "$(sz Q/groundtruth.tum)" "$bin/simp-eval" traj --gt Q/groundtruth.tum --est Q/groundtruth.tum
io="$src/tests/data/detector_io"
for f in "$io"/*.json; do
  peak simp-import-omni3d "$(basename "$f")" "$(sz "$f")" "$bin/simp-import-omni3d" --predictions "$f" \
       --poses "$io/poses.tum" --rig "$io/rig.ini" --out x.rawlog
done
for f in "$io"/*.csv; do
  peak simp-import-ros-detections "$(basename "$f")" "$(sz "$f")" "$bin/simp-import-ros-detections" --csv "$f" \
       --poses "$io/poses.tum" --rig "$io/rig.ini" --out x.rawlog
done
rm -f rss.tmp
