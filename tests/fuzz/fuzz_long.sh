#!/usr/bin/env bash
# The long fuzz run of README's development notes, one command: a million executions of every
# reader. The readers of small files run in the sanitizer build of CI (build-asan, made by
# .ci/sanitize). The fixed-size colour tables (.lut, .nnmc and .nnmc.bz2: 2 MiB; .raw: 256 KiB,
# expanded to 2 MiB) cost 30-60 ms an execution there (fresh pages for each table under ASan, a coverage
# callback per cell), so they run in build-fuzz: UBSan and libFuzzer without ASan, coverage left
# out of their per-cell loops (table_loops.ignorelist), glibc told to keep freed tables mapped.
#   tests/fuzz/fuzz_long.sh [RUNS]
set -euo pipefail
cd "$(dirname "$0")/../.."
runs=${1:-1000000}
tables='^fuzz_lut(_nnmc|_nnmc_bz2|_raw)?$'

[ -x build-asan/tests/fuzz/fuzz_strm ] || .ci/sanitize
if [ ! -x build-fuzz/tests/fuzz/fuzz_lut ]; then
    CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DFIELDSIGHT_FUZZ=ON \
        -DCMAKE_BUILD_TYPE=Release \
        "-DCMAKE_CXX_FLAGS=-g -fsanitize=undefined -fno-sanitize-recover=undefined -fsanitize-coverage-ignorelist=$PWD/tests/fuzz/table_loops.ignorelist" \
        -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=undefined > /dev/null
fi
cmake --build build-fuzz --target fuzz_lut fuzz_lut_nnmc fuzz_lut_nnmc_bz2 fuzz_lut_raw > /dev/null

status=0
tests/fuzz/fuzz_all.sh build-asan "$runs" "!$tables" || status=1
MALLOC_MMAP_THRESHOLD_=67108864 MALLOC_TRIM_THRESHOLD_=1073741824 \
    tests/fuzz/fuzz_all.sh build-fuzz "$runs" "$tables" || status=1
exit $status
