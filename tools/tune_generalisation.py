#!/usr/bin/env python3
"""Does `fieldsight tune` generalise? For each generated scenario: the defaults, parameters tuned
on ANOTHER stream of the same scene (the bundled one, or seed 1 where none is bundled), and parameters tuned on the stream
itself, all scored on a held-out stream of that scene (a seed nobody tuned on).

    tools/tune_generalisation.py build/app/fieldsight OUTDIR [--seed 301] [--frames 30]
        [--scenarios lab1,lab2,difficult,rc2012,rc2013,crowded] [--budget 1500]

Prints one table (TP/FP/FN per class and the boundary's mean error) and writes OUTDIR/report.json.
The held-out streams are made once in OUTDIR and reused.
"""
import argparse
import json
import os
import subprocess
import sys

CLASSES = ["ball", "goalpost", "obstacle", "field_line"]


def run(args):
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(args), done.stderr))
    return done.stdout


def evaluate(exe, stream, out, params=None):
    args = [exe, "eval", stream, "--json", out]
    if params:
        args += ["--params", params]
    run(args)
    with open(out) as f:
        return json.load(f)


def cells(report):
    row = []
    for c in CLASSES:
        s = report["classes"][c]
        row.append("%d/%d/%d" % (s["tp"], s["fp"], s["fn"]))
    boundary = report["field_boundary"]["mean_error_px"]
    row.append("-" if boundary is None else "%.2f" % boundary)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("exe")
    parser.add_argument("outdir")
    parser.add_argument("--seed", type=int, default=301)
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--budget", type=int, default=1500)
    parser.add_argument("--scenarios", default="lab1,lab2,difficult,rc2012,rc2013,crowded")
    parser.add_argument("--samples", default=os.path.join(os.path.dirname(__file__), "..",
                                                          "sample_streams"))
    a = parser.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    results = {}
    header = ["scene", "params"] + CLASSES + ["boundary px"]
    lines = [header]
    for scene in a.scenarios.split(","):
        held = os.path.join(a.outdir, "%s_seed%d" % (scene, a.seed))
        if not os.path.exists(os.path.join(held, "annotations.json")):
            run([a.exe, "synth", "--scenario", scene, "--frames", str(a.frames), "--seed",
                 str(a.seed), "--out", held])
        other = os.path.join(a.samples, scene)
        if not os.path.isdir(other):  # no bundled stream of the scene (crowded): seed 1
            other = os.path.join(a.outdir, "%s_seed1" % scene)
            if not os.path.exists(os.path.join(other, "annotations.json")):
                run([a.exe, "synth", "--scenario", scene, "--frames", str(a.frames), "--seed",
                     "1", "--out", other])
        on_other = os.path.join(a.outdir, "%s_tuned_on_seed1.json" % scene)
        on_itself = os.path.join(a.outdir, "%s_tuned_on_itself.json" % scene)
        for params, stream in ((on_other, other), (on_itself, held)):
            if not os.path.exists(params):
                run([a.exe, "tune", stream, "--holdout", "0", "--budget", str(a.budget), "--out",
                     params])
        rows = {
            "defaults": evaluate(a.exe, held, os.path.join(a.outdir, scene + "_d.json")),
            "tuned on seed 1": evaluate(a.exe, held, os.path.join(a.outdir, scene + "_o.json"),
                                        on_other),
            "tuned on itself": evaluate(a.exe, held, os.path.join(a.outdir, scene + "_i.json"),
                                        on_itself),
        }
        results[scene] = {k: v["classes"] | {"boundary": v["field_boundary"]}
                          for k, v in rows.items()}
        for name, report in rows.items():
            lines.append([scene, name] + cells(report))
    widths = [max(len(r[i]) for r in lines) for i in range(len(header))]
    for r in lines:
        print("  ".join(c.ljust(w) for c, w in zip(r, widths)))
    with open(os.path.join(a.outdir, "report.json"), "w") as f:
        json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
