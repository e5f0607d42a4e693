#!/usr/bin/env bash
# Peak RSS of the rawlog and world readers against input size (issue #14 "~50 MB + O(N)";
# doc/fuzzing.md "Peak memory against input size"). Generates its inputs with the project's own
# tools into OUT and prints: input, bytes, peak RSS (KB), RSS - baseline (KB), ratio to the size,
# seconds, exit code. Usage: tests/fuzz/measure_reader_rss.sh BIN_DIR OUT [--big] (--big adds the
# 100 MB rawlog: ~90 s and 700 MB of RAM).
set -euo pipefail
bin="$(cd "$1" && pwd)"; out="$2"; big="${3:-}"
mkdir -p "$out"; cd "$out"
row() {  # name file-or-dir command...
  local name="$1" input="$2" m; shift 2
  /usr/bin/time -o rss.tmp -f '%M %e %x' "$@" > /dev/null 2>&1 || true
  m="$(tail -n 1 rss.tmp)"
  set -- $m
  local bytes; bytes="$(du -sb "$input" | cut -f1)"
  awk -v n="$name" -v b="$bytes" -v r="$1" -v base="$BASE" -v s="$2" -v x="$3" \
    'BEGIN { d = r - base; printf "%-28s %11d %8d %8d %7.2f %6.1f %d\n", n, b, r, d, (b > 0 ? d * 1024 / b : 0), s, x }'
}
base() { /usr/bin/time -f '%M' "$@" 2>&1 > /dev/null | tail -n 1; }
ex="$bin/simp-example-rawlog"; exd="$bin/simp-export-detections"; exm="$bin/simp-export-map"
"$ex" --out r1k.rawlog --frames 1 --cameras 1 --detections 5 > /dev/null
for n in 100 1000; do "$ex" --out r$n.rawlog --frames $n --cameras 1 --detections 85 > /dev/null; done
[ "$big" = "--big" ] && "$ex" --out r10000.rawlog --frames 10000 --cameras 1 --detections 85 > /dev/null
head -c 10218000 /dev/urandom > garbage10m.rawlog            # hostile: random bytes
head -c 10217000 r1000.rawlog > truncated10m.rawlog           # hostile: cut inside the last entry
python3 -c "import gzip; d=open('r1k.rawlog','rb').read(); gzip.open('bomb.rawlog.gz','wb',9).write(d*10000)"
for a in 50 2000 20000; do "$bin/simp-sim" world --builtin office --seed 1 --out w$a --size-m2 $a > /dev/null; done
rm -rf wraster && cp -r w50 wraster   # hostile: a 25 Mpx floor plan (the raster maximum) in 35 KB
python3 - <<'EOF'
import struct, zlib
w = h = 5000
raw = b''.join(b'\x00' + b'\xfe' * w for _ in range(h))
ch = lambda t, d: struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
open('wraster/floorplan.png', 'wb').write(b'\x89PNG\r\n\x1a\n' + ch(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 0, 0, 0, 0))
                                         + ch(b'IDAT', zlib.compress(raw, 9)) + ch(b'IEND', b''))
EOF
echo "input                              bytes  RSS(KB)  -base(KB) KB/KB   s  exit"
BASE="$(base "$exd" --help)"; echo "baseline simp-export-detections --help: $BASE KB"
for f in r1k r100 r1000 $([ "$big" = "--big" ] && echo r10000); do
  row "$f.rawlog" $f.rawlog "$exd" --rawlog $f.rawlog --out-csv /dev/null; done
row garbage10m.rawlog garbage10m.rawlog "$exd" --rawlog garbage10m.rawlog --out-csv /dev/null
row truncated10m.rawlog truncated10m.rawlog "$exd" --rawlog truncated10m.rawlog --out-csv /dev/null
row bomb.rawlog.gz bomb.rawlog.gz "$exd" --rawlog bomb.rawlog.gz --out-csv /dev/null
BASE="$(base "$exm" --help)"; echo "baseline simp-export-map --help: $BASE KB"
for w in w50 w2000 w20000 wraster; do row "$w (world dir)" $w "$exm" --world $w --gridmap "$out/x.gridmap"; done
