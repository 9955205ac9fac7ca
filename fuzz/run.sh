#!/usr/bin/env bash
# Runs the libFuzzer harnesses of the fuzz preset, each for a bounded time, and fails if any found an
# input that crashes, leaks, hangs or runs out of memory. fuzz/README.md explains the rest.
#
#   fuzz/run.sh [HARNESS...]      (default: every harness; `make fuzz` builds the preset and calls this)
#
# Environment:
#   FUZZ_SECONDS   seconds per harness (default 60)
#   FUZZ_BUILD     the fuzz preset's build folder (default build/fuzz)
#   FUZZ_ARGS      more libFuzzer flags for every harness (e.g. -jobs=2 -workers=2, -seed=1)
#
# Each harness runs on its own copy of the seed corpus, build/fuzz/runs/corpus/<harness>/, which
# starts as fuzz/corpus/<harness>/ and keeps what the fuzzer adds (so later runs go on from there);
# the repository's corpus is never written. Reproducers go to build/fuzz/runs/artifacts/<harness>/,
# logs to build/fuzz/runs/logs/<harness>.log.
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD:-$root/build/fuzz}
seconds=${FUZZ_SECONDS:-60}
runs=$build/runs

all_harnesses=(scene_yaml scene_json scene_edit pbrt gltf obj ply mtl checkpoint
               image_png image_jpeg image_bmp image_tga image_pnm image_hdr image_pfm image_exr)
if [ $# -gt 0 ]; then
    harnesses=("$@")
else
    harnesses=("${all_harnesses[@]}")
fi

# The largest input the fuzzer makes: room for the biggest seed and some growth, small enough that
# each execution stays fast.
max_len_of() {
    case "$1" in
        scene_yaml | scene_json | pbrt | gltf) echo 32768 ;;
        scene_edit) echo 4096 ;;
        obj | ply | mtl | checkpoint) echo 16384 ;;
        *) echo 65536 ;;
    esac
}

# Sanitizer reports: symbolized stacks, and UBSan's stack too (the build already makes UB fatal).
export ASAN_OPTIONS=${ASAN_OPTIONS:-symbolize=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

mkdir -p "$runs/logs"
failed=()
summary=()
start_all=$(date +%s)
for harness in "${harnesses[@]}"; do
    binary=$build/fuzz/fuzz_$harness
    if [ ! -x "$binary" ]; then
        echo "fuzz: $binary is missing (build it with: cmake --preset fuzz && cmake --build --preset fuzz)" >&2
        exit 2
    fi
    corpus=$runs/corpus/$harness
    artifacts=$runs/artifacts/$harness
    log=$runs/logs/$harness.log
    mkdir -p "$corpus" "$artifacts"
    cp -rn "$root/fuzz/corpus/$harness/." "$corpus/"
    before=$(ls "$artifacts")
    dict=()
    if [ -f "$root/fuzz/dict/$harness.dict" ]; then
        dict=("-dict=$root/fuzz/dict/$harness.dict")
    fi

    echo "fuzz: $harness for ${seconds}s ..." >&2
    started=$(date +%s)
    # The outer timeout only guards against libFuzzer itself getting stuck; -timeout catches slow inputs.
    # shellcheck disable=SC2086  # FUZZ_ARGS is a list of flags
    (cd "$runs" && timeout --kill-after=30 $((seconds + 300)) "$binary" "$corpus" \
        -max_total_time="$seconds" -max_len="$(max_len_of "$harness")" -rss_limit_mb=2048 -timeout=10 \
        -print_final_stats=1 -artifact_prefix="$artifacts/" "${dict[@]}" ${FUZZ_ARGS:-}) >"$log" 2>&1
    status=$?
    elapsed=$(($(date +%s) - started))

    executions=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | awk '{s += $2} END {print s + 0}')
    corpus_size=$(find "$corpus" -type f | wc -l)
    new_artifacts=$(comm -13 <(echo "$before" | sort) <(ls "$artifacts" | sort) | sed "s|^|$artifacts/|")
    if [ "$status" -ne 0 ] || [ -n "$new_artifacts" ]; then
        failed+=("$harness")
        summary+=("$(printf '%-11s %12s executions %5ss  %5s inputs  FAILED (exit %s)' "$harness" "$executions" \
            "$elapsed" "$corpus_size" "$status")")
        echo "fuzz: $harness FAILED (exit $status); log: $log" >&2
        # The report: the sanitizer's or libFuzzer's error line, the top of the stack, the summary.
        grep -E '^==[0-9]+==ERROR|^ERROR: libFuzzer|runtime error|fuzz check failed|^SUMMARY|^    #[0-9] ' "$log" |
            grep -v -E 'in (fuzzer::|__sanitizer|__asan|__ubsan|__interceptor|abort|raise|__pthread_kill)' |
            head -n 14 | sed 's/^/    /' >&2
        if [ -n "$new_artifacts" ]; then
            echo "fuzz: reproducer(s), replay with $binary FILE:" >&2
            echo "$new_artifacts" | sed 's/^/    /' >&2
        fi
    else
        summary+=("$(printf '%-11s %12s executions %5ss  %5s inputs  ok' "$harness" "$executions" "$elapsed" \
            "$corpus_size")")
    fi
done

echo "fuzz: ${seconds}s per harness, $(($(date +%s) - start_all))s in all" >&2
printf '    %s\n' "${summary[@]}" >&2
if [ ${#failed[@]} -gt 0 ]; then
    echo "fuzz: findings in ${failed[*]}: copy each reproducer to fuzz/regressions/<harness>/ (fuzz/README.md)" >&2
    exit 1
fi
