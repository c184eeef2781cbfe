#!/usr/bin/env bash
# run.sh HARNESS SECONDS WORKDIR [SEED_DIR...]: runs one libFuzzer harness for SECONDS.
# New inputs go to WORKDIR/corpus (kept between runs), crashes to WORKDIR/crashes/; seed folders
# that do not exist are skipped. Exits non-zero when the harness finds a crash, leak or timeout.
# FUZZ_RUNS=N stops after N executions (libFuzzer -runs) if that comes before SECONDS.
# FUZZ_TIMEOUT (default 60) is libFuzzer's per-input wall-clock timeout: raise it on a loaded
# machine, where a niced harness gets a few percent of a core.
set -euo pipefail
harness=$1 seconds=$2 work=$3
shift 3
mkdir -p "$work/corpus" "$work/crashes"
seeds=()
for d in "$@"; do [ -e "$d" ] && seeds+=("$d"); done
dict=$(dirname "$0")/json.dict
runs=()
[ -n "${FUZZ_RUNS:-}" ] && runs=(-runs="$FUZZ_RUNS")
exec "$harness" "${runs[@]}" -max_total_time="$seconds" -max_len=65536 -timeout="${FUZZ_TIMEOUT:-60}" -rss_limit_mb=4096 \
  -dict="$dict" -artifact_prefix="$work/crashes/" -print_final_stats=1 \
  "$work/corpus" "${seeds[@]}"
