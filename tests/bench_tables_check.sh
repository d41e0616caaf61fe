#!/bin/bash
# docs/benchmarks.md holds the bench's tables (bench/bench_meshes.cpp): the main table has three
# rows (three sizes) for each of its five meshes, each with a vertex count, a ratio and a peak
# memory; the exponent table one row for each of genus 0, 1, 2, 5 and 10.
# Usage: bench_tables_check.sh docs/benchmarks.md
set -euo pipefail
readme="$1"
main=$(awk '/^\| mesh \| vertices \| genus \| read \| prepare/ {on = 1; getline; next}
            on && /^\| / {print; next} on {exit}' "$readme")
exponents=$(awk '/^\| genus \| read \| prepare/ {on = 1; getline; next}
                 on && /^\| / {print; next} on {exit}' "$readme")
failed=0
for mesh in "maxplanck" "kitten" "eight" "genus 5 (generated)" "genus 10 (generated)"; do
  rows=$(echo "$main" | awk -F'|' -v m="$mesh" '{name = $2; sub(/^ /, "", name);
    sub(/ x[0-9]+ $/, "", name); if (name == m && $3 ~ /^ [0-9]+ $/ && $20 ~ /^ [0-9.]+ $/ &&
    $23 ~ / MB $/) n++} END {print n + 0}')
  if [ "$rows" != 3 ]; then
    echo "docs/benchmarks.md: the benchmark table: $rows rows for $mesh, not 3"; failed=1
  fi
done
total=$(echo "$main" | grep -c '^| ' || true)
if [ "$total" != 15 ]; then echo "docs/benchmarks.md: the benchmark table: $total rows, not 15"; failed=1; fi
genera=$(echo "$exponents" | awk -F'|' '{gsub(/ /, "", $2); printf "%s ", $2}')
if [ "$genera" != "0 1 2 5 10 " ]; then
  echo "docs/benchmarks.md: the exponent table: rows for genus '$genera', not '0 1 2 5 10 '"; failed=1
fi
exit $failed
