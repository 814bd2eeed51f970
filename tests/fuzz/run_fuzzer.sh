#!/usr/bin/env bash
# Fuzzes the config loader or the model-file reader with libFuzzer, then minimises the corpus into
# tests/fuzz/corpus (config) or tests/fuzz/model_corpus (model).
# usage: tests/fuzz/run_fuzzer.sh [SECONDS (default 600)] [BUILD_DIR (default build-fuzz)] [config|model]
# Needs clang and libclang-rt (Debian: clang, libclang-rt-14-dev). The build instruments lrchain,
# lrchain_sim, the derivation and toml++ with -fsanitize=fuzzer-no-link,address,undefined,float-cast-overflow
# (GiNaC and CLN are the system's, not instrumented).
# Findings (crashing inputs) are left in BUILD_DIR/fuzz-work-TARGET/artifacts; the log in fuzz.log.
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
seconds=${1:-600}
build=${2:-$src/build-fuzz}
target=${3:-config}
case $target in
  config) fuzzer_name=lrchain-config-fuzz corpus=$src/tests/fuzz/corpus dict=$src/tests/fuzz/config.dict
          seeds=("$src"/examples/*.toml) ;;
  model)  fuzzer_name=lrchain-model-fuzz corpus=$src/tests/fuzz/model_corpus dict=$src/tests/fuzz/model.dict
          seeds=("$src"/models/*.toml) ;;
  *) echo "run_fuzzer.sh: target must be config or model (got '$target')" >&2; exit 2 ;;
esac
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S "$src" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLRCHAIN_FUZZ=ON -DLRCHAIN_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" --target "$fuzzer_name" -j2
fuzzer=$build/tests/fuzz/$fuzzer_name
work=$build/fuzz-work-$target
rm -rf "$work/artifacts" "$work/merged"  # the working corpus carries over between runs
mkdir -p "$work/corpus" "$work/artifacts" "$work/merged" "$corpus"
cp "${seeds[@]}" "$work/corpus/"
cd "$work"  # libFuzzer's -merge writes crash files into the current directory
if compgen -G "$corpus/*" >/dev/null; then cp "$corpus"/* "$work/corpus/"; fi
# Inputs up to 4 KiB (the seeds are ~1 KiB); the dictionary holds the keys and tokens of the format.
# An input that takes over 10 s is a finding too (e.g. an expression that expands without bound).
# Leaks inside CLN and GiNaC are not ours (tests/sanitizer/lsan.supp says which).
export LSAN_OPTIONS="suppressions=$src/tests/sanitizer/lsan.supp:print_suppressions=0"
status=0
"$fuzzer" -max_total_time="$seconds" -max_len=4096 -timeout=10 -dict="$dict" \
  -artifact_prefix="$work/artifacts/" -print_final_stats=1 "$work/corpus" >"$work/fuzz.log" 2>&1 || status=$?
grep -v '^#' "$work/fuzz.log" | tail -30
# Minimised on edge coverage (-use_counters=0) to keep the committed corpus to a few hundred files;
# regression-* files (earlier findings) are kept whatever they cover.
"$fuzzer" -merge=1 -use_counters=0 "$work/merged" "$work/corpus" >"$work/merge.log" 2>&1
find "$corpus" -type f ! -name 'regression-*' -delete
cp "$work"/merged/* "$corpus/"
echo "corpus: $(ls "$corpus" | wc -l) files; findings: $(ls "$work/artifacts" | wc -l); fuzzer exit $status"
exit "$status"
