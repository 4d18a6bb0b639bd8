#!/usr/bin/env bash
# One libFuzzer campaign on one target, its finds merged (minimized) into the kept corpus
# tests/fuzz/corpus/TARGET/ (docs/testing.md, "Fuzzing").
#   tests/fuzz/campaign.sh LIBFUZZER_BUILD SEED_BUILD TARGET SECONDS
# LIBFUZZER_BUILD is a tree configured with -DBP_LIBFUZZER=ON; SEED_BUILD an ordinary tree
# whose drivers write the seeds (`--emit`): the target's examples and built documents, or
# the protocol and API drivers' generated inputs. TARGET is codec, api, or a fuzz_files
# target (`fuzz_files --help` lists them). One fuzzer process, at the lowest priority:
# the machines this runs on are shared. Prints one line of results (tab-separated):
#   target seconds execs cov ft corpus_files corpus_bytes artifacts
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
lf="$(cd "$1" && pwd)"; seedbuild="$(cd "$2" && pwd)"; target="$3"; secs="$4"
work="${BP_FUZZ_WORK:-/tmp/bp-fuzz}/$target"
corpus="$here/tests/fuzz/corpus/$target"
rm -rf "$work"; mkdir -p "$work/new" "$work/seeds" "$work/min" "$corpus"
extra=()
case "$target" in
  codec) bin="$lf/tests/fuzz/fuzz_codec"; "$seedbuild/tests/fuzz/fuzz_codec" --emit "$work/seeds" --iterations 200; extra=(-max_len=4096) ;;
  api)   bin="$lf/tests/fuzz/fuzz_api"; "$seedbuild/tests/fuzz/fuzz_api" --emit "$work/seeds" --iterations 200; extra=(-max_len=8192) ;;
  *)     bin="$lf/tests/fuzz/fuzz_files"; export BP_FUZZ_TARGET="$target"
         "$seedbuild/tests/fuzz/fuzz_files" --target "$target" --emit "$work"
         mv "$work/$target"/* "$work/seeds/" 2>/dev/null || true ;;
esac
cd "$work"
# -jobs=1 runs the fuzzer as one child whose log is fuzz-0.log.
nice -n 19 "$bin" -jobs=1 -workers=1 -max_total_time="$secs" -timeout=20 -rss_limit_mb=2048 \
  -print_final_stats=1 -artifact_prefix="$work/" "${extra[@]}" "$work/new" "$corpus" "$work/seeds" >/dev/null 2>&1 || true
log="$work/fuzz-0.log"
execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
last=$(grep -E '^#[0-9]+' "$log" | tail -1)
cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last"); ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
artifacts=$(ls "$work" | grep -cE '^(crash|leak|timeout|oom|slow-unit)-' || true)
# The kept corpus: the smallest set of inputs that keeps the coverage of all three.
nice -n 19 "$bin" -merge=1 -timeout=20 -rss_limit_mb=2048 "${extra[@]}" "$work/min" "$corpus" "$work/new" "$work/seeds" >"$work/merge.log" 2>&1 || true
# A kept corpus stays small (under 300 files a target, CI replays it): past that, minimize
# for edges alone (-use_counters=0) instead of edges and their hit-count buckets.
if [ "$(ls "$work/min" | wc -l)" -gt 300 ]; then
  mkdir -p "$work/min-edges"
  nice -n 19 "$bin" -merge=1 -use_counters=0 -timeout=20 -rss_limit_mb=2048 "${extra[@]}" "$work/min-edges" "$work/min" >>"$work/merge.log" 2>&1 || true
  [ -n "$(ls -A "$work/min-edges")" ] && { rm -rf "$work/min"; mv "$work/min-edges" "$work/min"; }
fi
# Inputs that once failed (regress-*, named by a test) keep their names whatever the merge.
if [ -n "$(ls -A "$work/min")" ]; then
  mkdir -p "$work/keep"; cp "$corpus"/regress-* "$work/keep/" 2>/dev/null || true
  rm -f "$corpus"/*; cp "$work/min"/* "$work/keep"/* "$corpus/" 2>/dev/null || cp "$work/min"/* "$corpus/"
fi
files=$(ls "$corpus" | wc -l); bytes=$(du -sb "$corpus" | cut -f1)
printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$target" "$secs" "${execs:-?}" "${cov:-?}" "${ft:-?}" "$files" "$bytes" "$artifacts"
