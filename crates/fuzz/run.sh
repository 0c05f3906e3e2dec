#!/usr/bin/env bash
# Fuzz tapegate-core for a bounded time: crates/fuzz/run.sh [SECONDS_PER_TARGET] (default 60).
#
# Seeds the corpora (seed.sh), builds the targets with cargo fuzz and runs each one for the
# given time with libFuzzer (-rss_limit_mb=256 -timeout=5), one after the other. Prints per
# target the executions (libFuzzer's final stat::number_of_executed_units) and whether it
# crashed, and exits non-zero if any target crashed (1) or could not be built or run (2).
# A crashing input is left in crates/fuzz/artifacts/<target>/, the full log of each run in
# crates/fuzz/target/logs/<target>.log.
#
# The toolchain is the stable one: cargo fuzz passes nightly-only -Z flags for a sanitizer,
# which RUSTC_BOOTSTRAP=1 lets stable rustc accept. CARGO_CACHE_RUSTC_INFO=0 stops cargo from
# reusing a target-info probe it cached before RUSTC_BOOTSTRAP was set (the cache is not keyed
# on that variable, so one build without it would break every later one).
#
# Environment: FUZZ_TARGETS (default "tokenize check convert expr"); FUZZ_SANITIZER (default
# "none": the core is safe Rust, where libFuzzer's own panic, timeout and RSS checks are the
# ones that matter, and it runs faster uninstrumented; "address" for ASan); FUZZ_ARGS, extra
# libFuzzer flags.
set -uo pipefail

seconds=${1:-60}
case "$seconds" in '' | *[!0-9]*) echo "usage: $0 [SECONDS_PER_TARGET]" >&2; exit 2 ;; esac
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
targets=${FUZZ_TARGETS:-tokenize check convert expr}
sanitizer=${FUZZ_SANITIZER:-none}
export RUSTC_BOOTSTRAP=1 CARGO_CACHE_RUSTC_INFO=0

if ! cargo fuzz --version > /dev/null 2>&1; then
    echo "run.sh: cargo fuzz is not installed (cargo install cargo-fuzz)" >&2
    exit 2
fi
"$here/seed.sh" || exit 2
cargo fuzz build --fuzz-dir "$here" -s "$sanitizer" || exit 2

mkdir -p "$here/target/logs"
crashed=0
failed=0
total=0
summary=()
for t in $targets; do
    log=$here/target/logs/$t.log
    echo "run.sh: fuzzing $t for ${seconds}s (log: $log)"
    # shellcheck disable=SC2086  # FUZZ_ARGS is a list of flags
    cargo fuzz run --fuzz-dir "$here" -s "$sanitizer" "$t" -- \
        -max_total_time="$seconds" -rss_limit_mb=256 -timeout=5 -print_final_stats=1 \
        ${FUZZ_ARGS:-} > "$log" 2>&1
    rc=$?
    execs=$(grep -aoE 'stat::number_of_executed_units: *[0-9]+' "$log" | tail -n 1 | grep -oE '[0-9]+$')
    artifact=$(grep -aoE '(Test unit|artifact) written to [^ ]+' "$log" | tail -n 1 | awk '{print $NF}')
    if [ "$rc" -eq 0 ]; then
        state="no crash"
    elif [ -n "$artifact" ]; then
        state="CRASHED: $artifact"
        crashed=1
        grep -aE "panicked at|^==[0-9]+== ERROR|ERROR: libFuzzer|SUMMARY" "$log" | head -n 4 | sed 's/^/    /'
    else
        state="FAILED (exit $rc, see $log)"
        failed=1
        tail -n 5 "$log" | sed 's/^/    /'
    fi
    total=$((total + ${execs:-0}))
    summary+=("$(printf '%-9s %12s executions  %s' "$t" "${execs:-?}" "$state")")
done

echo
echo "run.sh: ${seconds}s per target, sanitizer $sanitizer"
printf '%s\n' "${summary[@]}"
printf '%-9s %12s executions\n' total "$total"
if [ "$crashed" -ne 0 ]; then exit 1; fi
if [ "$failed" -ne 0 ]; then exit 2; fi
exit 0
