#!/usr/bin/env bash
# Runs every libFuzzer target of a -DSIMP_FUZZ=ON build folder, one after the other, for SECONDS
# each (doc/fuzzing.md "Long runs"). Fork mode keeps a run going past a finding (each one is saved
# under OUT/<target>/crash-*|oom-*|timeout-*|leak-*); /usr/bin/time -v records the peak RSS of the
# worker processes. Usage: tests/fuzz/run_fuzzers.sh BUILD_DIR OUT [SECONDS] [target...]
set -euo pipefail
build="$(cd "$1" && pwd)"; out="$2"; secs="${3:-600}"; shift 2; [ $# -gt 0 ] && shift
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_rawlog fuzz_object_map_bin fuzz_world_json fuzz_floorplan
                                   fuzz_ini_lists fuzz_tum fuzz_detections)
src="$(cd "$(dirname "$0")/../.." && pwd)"
mkdir -p "$out"
# Third-party leaks only (libfyaml's parser state on invalid YAML, reached by fuzz_floorplan), the
# same justified list as the sanitizer stage: without it every such report stops the worker, which
# cut fuzz_floorplan's 600 s run to 2259 executions (doc/fuzzing.md). Fork-mode workers inherit it.
export LSAN_OPTIONS="suppressions=$src/tests/sanitizers/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
[ -d "$out/seeds" ] || "$build/bin/make_seeds" "$out/seeds" "$src" > "$out/make_seeds.log"
for t in "${targets[@]}"; do
  dir="${t#fuzz_}"
  mkdir -p "$out/$t/corpus"
  cp -n "$out/seeds/$dir"/* "$out/$t/corpus/" 2>/dev/null || true
  # rss_limit 1024 MB: an ASan process of these targets sits at 60-250 MB (quarantine included), so
  # 1 GB only trips on inputs that really grow memory; -timeout 10 s: no input of <= max_len bytes
  # may take that long. -detect_leaks=1 is libFuzzer's default, kept explicit.
  echo "[fuzz] $t for $secs s ($(date -u +%T), load $(cut -d' ' -f1-3 /proc/loadavg), LSAN_OPTIONS=$LSAN_OPTIONS)"
  (cd "$out/$t" && /usr/bin/time -v "$build/bin/$t" corpus -max_total_time="$secs" -rss_limit_mb=1024 \
      -timeout=10 -detect_leaks=1 -fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 \
      -artifact_prefix=./ > run.log 2>&1) || echo "[fuzz] $t exited $?"
  grep -E '^#[0-9]+: cov' "$out/$t/run.log" | tail -n 1
  grep -E 'Maximum resident' "$out/$t/run.log"
  ls "$out/$t" | grep -E '^(crash|oom|timeout|leak|slow-unit)-' || echo "[fuzz] $t: no finding saved"
done
