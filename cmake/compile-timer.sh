#!/usr/bin/env bash
# Compiler launcher that logs each compile's CPU time: one line "user+sys<TAB>wall<TAB>output" per
# command appended to $LRCHAIN_COMPILE_LOG (default: compile-times.tsv in the working directory).
# Usage: cmake -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/cmake/compile-timer.sh ...; then
#        sort -rn build/compile-times.tsv | head   (the heaviest translation units first)
set -uo pipefail
log=${LRCHAIN_COMPILE_LOG:-$PWD/compile-times.tsv}
out=-
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
  [[ ${args[i]} == -o ]] && out=${args[i + 1]:-}
done
TIMEFORMAT='%U %S %R'
{ timing=$( { time "$@" 2>&3 1>&4; } 2>&1 ); } 3>&2 4>&1
status=$?
read -r user sys wall <<<"${timing##*$'\n'}"
awk -v u="$user" -v s="$sys" -v w="$wall" -v o="$out" 'BEGIN { printf "%.2f\t%s\t%s\n", u + s, w, o }' >>"$log"
exit "$status"
