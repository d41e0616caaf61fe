#!/usr/bin/env bash
# Runs every libFuzzer target for a set time and prints a table of executions and findings.
# Usage: scripts/fuzz.sh BUILD_FUZZ_DIR [SECONDS]   (the `fuzz` build target calls it)
# Seeds: the test meshes of each format and the committed corpus tests/fuzz_corpus/ (seeds/ and
# regressions/, every input that ever crashed). A finding is written to BUILD_FUZZ_DIR/findings/;
# copy it into tests/fuzz_corpus/regressions/ once fixed, so the test suite keeps it.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="$1"
seconds="${2:-60}"
corpus="$here/tests/fuzz_corpus"
mkdir -p "$bin/findings"
status=0
printf '| target | seconds | executions | executions/s | findings |\n|---|---|---|---|---|\n'
for target in fuzz_read_ply fuzz_read_off fuzz_read_obj fuzz_read_stl fuzz_c_abi \
  fuzz_c_abi_remesh fuzz_job_forms fuzz_job_remesh; do
  work="$bin/corpus/$target"
  mkdir -p "$work"
  seeds=()
  case "$target" in
  fuzz_read_*)
    format="${target#fuzz_read_}"
    for f in "$here"/tests/data/*."$format" "$corpus"/seeds/*."$format" "$corpus"/regressions/*."$format"; do
      [ -f "$f" ] && [ "$(stat -c %s "$f")" -lt 20000 ] && cp -n "$f" "$work/" 2>/dev/null
    done
    ;;
  fuzz_c_abi | fuzz_c_abi_remesh)
    for f in "$corpus"/seeds/*.abi; do [ -f "$f" ] && cp -n "$f" "$work/"; done
    ;;
  fuzz_job_*)
    # Two leading bytes (options, scale: 30 = 10^0) before each OFF seed.
    for f in "$corpus"/seeds/*.off "$corpus"/regressions/*.off; do
      [ -f "$f" ] && [ "$(stat -c %s "$f")" -lt 20000 ] &&
        { printf '\x00\x1e'; cat "$f"; } >"$work/$(basename "$f")"
    done
    ;;
  esac
  log="$bin/$target.log"
  ASAN_OPTIONS=detect_leaks=1 "$bin/$target" -max_total_time="$seconds" -max_len=16384 \
    -print_final_stats=1 -artifact_prefix="$bin/findings/$target-" -close_fd_mask=3 \
    "$work" >"$log" 2>&1
  code=$?
  runs=$(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}')
  runs=${runs:-0}
  findings=$(ls "$bin/findings" 2>/dev/null | grep -c "^$target-")
  [ "$code" -ne 0 ] && status=1
  printf '| %s | %s | %s | %s | %s |\n' "$target" "$seconds" "$runs" "$((runs / seconds))" "$findings"
done
[ "$status" -eq 0 ] || echo "fuzz: findings in $bin/findings (logs: $bin/*.log)" >&2
exit "$status"
