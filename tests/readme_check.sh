#!/bin/bash
# The README cannot drift from the tool: its C and C++ examples are the files the tests build and
# run (docs/examples/), every option its synopsis names is in that subcommand's --help, its exit
# codes are the tool's, the documents it links exist, and it stays short (at most 350 lines).
# Usage: readme_check.sh README.md MEROMORPH_CLI
set -uo pipefail
readme="$1"
cli="$2"
root="$(dirname "$readme")"
failed=0
fail() { echo "README: $*"; failed=1; }

block() { awk -v lang="$1" '$0 == "```" lang {on = 1; next} on && $0 == "```" {exit} on' "$readme"; }
diff <(block c) "$root/docs/examples/map_a_torus.c" >/dev/null ||
  fail "the C example is not docs/examples/map_a_torus.c"
diff <(block cpp) "$root/docs/examples/map_a_torus.cpp" >/dev/null ||
  fail "the C++ example is not docs/examples/map_a_torus.cpp"

# The synopsis: lines from 'meromorph SUB' to the next line that is not indented further.
for sub in info param remesh forms match; do
  options=$(awk -v sub_="$sub" '$1 == "meromorph" && $2 == sub_ {on = 1; print; next}
             on && /^              / {print; next} {on = 0}' "$readme" | grep -o -- '--[a-z-]*' | sort -u)
  [ -n "$options" ] || fail "no synopsis of $sub"
  help=$("$cli" "$sub" --help 2>&1)
  for option in $options; do
    grep -q -- "$option" <<<"$help" || fail "$sub: $option is not in 'meromorph $sub --help'"
  done
done

# Exit codes: each row's code and first word are in the tool's own list (meromorph --help).
tool_codes=$("$cli" --help 2>&1 | tr '\n' ' ')
while IFS='|' read -r _ code meaning _; do
  code=$(echo "$code" | tr -d ' ')
  first=$(echo "$meaning" | awk '{print $1}' | tr -d ':,')
  grep -q -- "$code $first" <<<"$tool_codes" || fail "exit code $code ('$first') is not the tool's"
done < <(awk '/^\| code \| meaning \|/ {on = 1; getline; next} on && /^\| / {print; next} on {exit}' "$readme")

for link in $(grep -o '](docs/[^)]*)' "$readme" | tr -d '()]' | sort -u) LICENSE; do
  [ -e "$root/$link" ] || fail "links $link, which does not exist"
done
lines=$(wc -l <"$readme")
[ "$lines" -le 350 ] || fail "$lines lines, more than 350"
exit $failed
