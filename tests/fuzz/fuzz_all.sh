#!/usr/bin/env bash
# Fuzzes every reader longer than CTest does: each target of BUILD (default build-asan, made by
# .ci/sanitize) whose name matches the extended regular expression PATTERN (default: all; "!RE":
# all but those matching RE) runs RUNS executions (default 1000000), JOBS targets at a time
# (default 2), from its seed corpus (new inputs go to BUILD/tests/fuzz/work/, never into the
# repository). FUZZ_FLAGS adds libFuzzer options (-max_total_time=1800 bounds a slow target by
# time). Prints executions and seconds per target; a crash stops that target and its input is kept
# in BUILD/tests/fuzz/crashes/. tests/fuzz/fuzz_long.sh runs them all.
#   [JOBS=n] [FUZZ_FLAGS=...] tests/fuzz/fuzz_all.sh [BUILD] [RUNS] [PATTERN]
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build-asan}
runs=${2:-1000000}
pattern=${3:-.}
dir="$build/tests/fuzz"
ls "$dir"/fuzz_* > /dev/null 2>&1 || { echo "no fuzz targets in $dir: run .ci/sanitize first"; exit 2; }
mkdir -p "$dir/logs" "$dir/crashes"

fuzz_one() {
    local target=$1 name=${1#fuzz_} start end
    mkdir -p "$dir/work/$name"
    start=$(date +%s)
    # shellcheck disable=SC2086 # FUZZ_FLAGS: words on purpose
    if "$dir/$target" -runs="$runs" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        ${FUZZ_FLAGS:-} -artifact_prefix="$dir/crashes/$name-" "$dir/work/$name" "tests/fuzz/corpus/$name" \
        > "$dir/logs/$name.log" 2>&1; then result=ok; else result=CRASH; fi
    end=$(date +%s)
    printf '%-20s %12s %8s  %s\n' "$name" \
        "$(sed -n 's/^stat::number_of_executed_units: //p' "$dir/logs/$name.log")" \
        "$((end - start))" "$result"
}
export -f fuzz_one
export dir runs

printf '%-20s %12s %8s  %s\n' target executions seconds result
if [ "${pattern#!}" != "$pattern" ]; then
    select=(grep -vE -- "${pattern#!}")
else
    select=(grep -E -- "$pattern")
fi
targets=$(ls "$dir" | grep '^fuzz_' | grep -v '\.' | "${select[@]}")
echo "$targets" | xargs -P "${JOBS:-2}" -I{} bash -c 'fuzz_one {}' | sort
for t in $targets; do
    ! grep -al "ERROR: AddressSanitizer\|runtime error\|deadly signal\|ERROR: libFuzzer" \
        "$dir/logs/${t#fuzz_}.log" || exit 1
done
