#!/usr/bin/env bash
# Builds a stub of libhwy's TimerResolution() and prints its path, for LD_PRELOAD under valgrind:
# Debian's valgrind 3.19 cannot decode the rdtscp that libhwy (via OpenCV's codecs) runs at load.
set -euo pipefail
dir="${TMPDIR:-/tmp}/fieldsight-hwy-shim"
mkdir -p "$dir"
cat > "$dir/shim.cpp" <<'CPP'
namespace hwy { namespace platform { double TimerResolution() { return 1e-9; } } }
CPP
echo 'HWY_0 { global: _ZN3hwy8platform15TimerResolutionEv; };' > "$dir/shim.map"
g++ -shared -fPIC -O2 -Wl,--version-script="$dir/shim.map" "$dir/shim.cpp" -o "$dir/libhwyshim.so"
echo "$dir/libhwyshim.so"
