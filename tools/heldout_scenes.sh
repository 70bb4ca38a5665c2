#!/usr/bin/env bash
# Generated scenes to tune obstacle defaults on, and scenes held out of the tuning (issue 34).
#
#   tools/heldout_scenes.sh [--fieldsight BIN] [--dir DIR] [--set tuning|heldout|all]
#                           [-- EVAL_ARGS...]
#
# Generates each scene once into DIR (default /tmp/fieldsight_scenes) with `fieldsight synth`,
# then prints `fieldsight eval` per scene as one line: ball, goalpost and obstacle TP/FP/FN.
# EVAL_ARGS go to every eval (e.g. -- --set obstacles.robot_width=1.2); --fieldsight may name an
# older build, to score these same scenes with the defaults of another commit.
#
# The TUNING set is what a rule may be tuned on and looked at while tuning. The HELD-OUT set
# (other seeds, other camera heights, other scenarios) is only scored: before and after a change,
# never while choosing it.
set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
bin="$here/build/app/fieldsight"
dir=/tmp/fieldsight_scenes
which=all
eval_args=()
while [ $# -gt 0 ]; do
    case "$1" in
    --fieldsight) bin=$2; shift 2 ;;
    --dir) dir=$2; shift 2 ;;
    --set) which=$2; shift 2 ;;
    --) shift; eval_args=("$@"); break ;;
    *) echo "usage: $0 [--fieldsight BIN] [--dir DIR] [--set tuning|heldout|all] [-- EVAL_ARGS...]" >&2
       exit 2 ;;
    esac
done
# The generator of this checkout makes the scenes (an older --fieldsight may not know crowded).
synth="$here/build/app/fieldsight"

frames=40
# name scenario seed camera-height
tuning=(
    "tune_crowded_s1 crowded 1 0.45"
    "tune_crowded_s2 crowded 2 0.45"
    "tune_crowded_s3 crowded 3 0.45"
    "tune_lab1_s8_h40 lab1 8 0.40"
    "tune_rc2013_s5 rc2013 5 0.45"
)
heldout=(
    "held_crowded_s101_h45 crowded 101 0.45"
    "held_crowded_s102_h38 crowded 102 0.38"
    "held_crowded_s103_h52 crowded 103 0.52"
    "held_crowded_s104_h33 crowded 104 0.33"
    "held_rc2013_s105 rc2013 105 0.45"
    "held_rc2012_s106 rc2012 106 0.45"
    "held_difficult_s107 difficult 107 0.45"
    "held_lab1_s108_h40 lab1 108 0.40"
)

scenes=()
case "$which" in
tuning) scenes=("${tuning[@]}") ;;
heldout) scenes=("${heldout[@]}") ;;
all) scenes=("${tuning[@]}" "${heldout[@]}") ;;
*) echo "$0: --set is tuning, heldout or all" >&2; exit 2 ;;
esac

mkdir -p "$dir"
printf '%-24s %-12s %-12s %-12s\n' scene "ball" "goalpost" "obstacle"
for entry in "${scenes[@]}"; do
    read -r name scenario seed height <<<"$entry"
    out="$dir/$name"
    if [ ! -f "$out/annotations.json" ]; then
        "$synth" synth --scenario "$scenario" --seed "$seed" --camera-height "$height" \
            --frames "$frames" --out "$out" >/dev/null
    fi
    "$bin" eval "$out" ${eval_args[@]+"${eval_args[@]}"} 2>/dev/null | awk -v name="$name" '
        $1 == "ball" { b = $2 "/" $3 "/" $4 }
        $1 == "goalpost" { g = $2 "/" $3 "/" $4 }
        $1 == "obstacle" { o = $2 "/" $3 "/" $4 }
        END { printf "%-24s %-12s %-12s %-12s\n", name, b, g, o }'
done | awk '
    { print }
    $1 != "scene" {
        set = substr($1, 1, 4)
        for (c = 2; c <= 4; ++c) {
            split($c, v, "/")
            for (k = 1; k <= 3; ++k) sum[set, c, k] += v[k]
        }
        sets[set] = 1
    }
    END {
        for (set in sets) {
            line = sprintf("%-24s", "total " set)
            for (c = 2; c <= 4; ++c) {
                tp = sum[set, c, 1]; fp = sum[set, c, 2]; fn = sum[set, c, 3]
                p = tp + fp > 0 ? tp / (tp + fp) : 1
                r = tp + fn > 0 ? tp / (tp + fn) : 1
                line = line sprintf(" %d/%d/%d %.2f/%.2f", tp, fp, fn, p, r)
            }
            print line
        }
    }'
