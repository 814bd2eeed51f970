#!/usr/bin/env bash
# Fuzzes the config loader with libFuzzer, then minimises the corpus into tests/fuzz/corpus.
# usage: tests/fuzz/run_fuzzer.sh [SECONDS (default 600)] [BUILD_DIR (default build-fuzz)]
# Needs clang and libclang-rt (Debian: clang, libclang-rt-14-dev). The build instruments lrchain,
# lrchain_sim and toml++ with -fsanitize=fuzzer-no-link,address,undefined,float-cast-overflow.
# Findings (crashing inputs) are left in BUILD_DIR/fuzz-work/artifacts; the log in fuzz.log.
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
seconds=${1:-600}
build=${2:-$src/build-fuzz}
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S "$src" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLRCHAIN_FUZZ=ON -DLRCHAIN_BUILD_DERIVATION=OFF -DLRCHAIN_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" --target lrchain-config-fuzz -j2
fuzzer=$build/tests/fuzz/lrchain-config-fuzz
work=$build/fuzz-work
rm -rf "$work/artifacts" "$work/merged"  # the working corpus carries over between runs
mkdir -p "$work/corpus" "$work/artifacts" "$work/merged"
cp "$src"/examples/*.toml "$work/corpus/"
if compgen -G "$src/tests/fuzz/corpus/*" >/dev/null; then cp "$src"/tests/fuzz/corpus/* "$work/corpus/"; fi
# Inputs up to 4 KiB (the examples are ~1 KiB); the dictionary holds the schema's keys and TOML tokens.
status=0
"$fuzzer" -max_total_time="$seconds" -max_len=4096 -dict="$src/tests/fuzz/config.dict" \
  -artifact_prefix="$work/artifacts/" -print_final_stats=1 "$work/corpus" >"$work/fuzz.log" 2>&1 || status=$?
grep -v '^#' "$work/fuzz.log" | tail -30
# Minimised on edge coverage (-use_counters=0) to keep the committed corpus to a few hundred files;
# regression-* files (earlier findings) are kept whatever they cover.
"$fuzzer" -merge=1 -use_counters=0 "$work/merged" "$work/corpus" >"$work/merge.log" 2>&1
find "$src/tests/fuzz/corpus" -type f ! -name 'regression-*' -delete
cp "$work"/merged/* "$src/tests/fuzz/corpus/"
echo "corpus: $(ls "$src/tests/fuzz/corpus" | wc -l) files; findings: $(ls "$work/artifacts" | wc -l); fuzzer exit $status"
exit "$status"
