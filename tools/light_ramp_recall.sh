#!/usr/bin/env bash
# Recall of ball / goalpost / field line on B-Human's 2009 frames (46 annotated) under a synthetic
# white-balance and gain ramp (as synth --drift: at the last frame R, G, B times
# (1 - D/2) x (1 + D, 1, 1 - D)), the log's own table kept static and with --adapt. Needs
# build/app/fieldsight and build/tests/light_ramp (cmake --build build --target light_ramp), and
# ../shared/reference_data. Writes /tmp/light_ramp_*.
set -euo pipefail
cd "$(dirname "$0")/.."
F=${FIELDSIGHT:-build/app/fieldsight}
T=tests/data/real/bhuman2009/annotations.json
log=/tmp/light_ramp_bhuman
[ -d $log ] || $F import ../shared/reference_data/bhuman2009_log_coltable --out $log \
    --params tests/data/real/bhuman2009/params.json >/dev/null
recall() {
    awk '$1=="ball"{b=$6} $1=="goalpost"{g=$6} $1=="field" && $2=="line"{l=$7}
         END{print b" / "g" / "l}'
}
echo "drift  static (ball / goalpost / field line)  --adapt"
for D in 0 0.1 0.2 0.3; do
    read -r R G B < <(awk -v d=$D 'BEGIN{l=1-d/2; print l*(1+d), l, l*(1-d)}')
    out=/tmp/light_ramp_$D
    rm -rf $out
    build/tests/light_ramp $log $out $R $G $B
    echo "$D    $($F eval $out --truth $T --threads 2 2>/dev/null | recall)    $($F eval $out --truth $T --threads 2 --adapt 2>/dev/null | recall)"
done
