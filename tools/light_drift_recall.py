#!/usr/bin/env python3
"""Recall of ball / goalpost / field line against light drift on a generated stream: the first
light's table kept static, the same table with --adapt, and tables made for each segment's own
light (synth --table-light at the segment's middle), per-frame misses from eval's JSON.

  tools/light_drift_recall.py SCENARIO SEED FRAMES DRIFTS [SEGMENTS] [WORKDIR]
  e.g. tools/light_drift_recall.py lab2 1 40 0,0.1,0.2,0.3 3 /tmp/ltm

FIELDSIGHT names the executable (default build/app/fieldsight). Streams are kept in WORKDIR and
reused on the next run."""
import json, subprocess, sys, os
F = os.environ.get('FIELDSIGHT', 'build/app/fieldsight')
scenario, seed, frames = sys.argv[1], sys.argv[2], int(sys.argv[3])
drifts = [float(d) for d in sys.argv[4].split(',')]
segments = int(sys.argv[5]) if len(sys.argv) > 5 else 3
work = sys.argv[6] if len(sys.argv) > 6 else '/tmp/light_drift'
root = f'{work}/{scenario}_{seed}_{frames}'
os.makedirs(root, exist_ok=True)
CLASSES = [('ball', 'balls'), ('goalpost', 'goalposts'), ('field_line', 'field_lines')]

def synth(out, drift, table_light=0.0):
    if os.path.exists(out + '/default.lut'):
        return
    cmd = [F, 'synth', '--scenario', scenario, '--seed', seed, '--frames', str(frames),
           '--out', out, '--strm', '--no-png', '--drift', str(drift)]
    if table_light:
        cmd += ['--table-light', str(table_light)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)

def evaluate(stream, lut, adapt):
    out = f'{stream}/eval_{os.path.basename(os.path.dirname(lut))}_{int(adapt)}.json'
    cmd = [F, 'eval', stream + '/image.strm', '--truth', stream + '/annotations.json', '--lut', lut,
           '--threads', '1', '--json', out] + (['--adapt'] if adapt else [])
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return json.load(open(out))

def per_frame(stream, report, keep):
    """(truth, missed) per class over frames whose index passes keep()."""
    truth = json.load(open(stream + '/annotations.json'))['frames']
    missed = {}
    for d in report['disagreements']:
        missed[(d['index'], d['class'])] = len(d['missed'])
    totals = {c: [0, 0] for c, _ in CLASSES}
    for name, f in truth.items():
        i = int(name.split('_')[1].split('.')[0])
        if not keep(i):
            continue
        for c, key in CLASSES:
            totals[c][0] += len(f.get(key, []))
            totals[c][1] += missed.get((i, c), 0)
    return totals

def recall(t):
    return 1.0 if t[0] == 0 else (t[0] - t[1]) / t[0]

print(f'# {scenario} seed {seed}, {frames} frames; recall ball / goalpost / field line')
print('drift  static                 adapt                  own-light tables       adapt/own (ball)')
for drift in drifts:
    stream = f'{root}/d{drift}'
    synth(stream, drift)
    lut = stream + '/default.lut'
    st = per_frame(stream, evaluate(stream, lut, False), lambda i: True)
    ad = per_frame(stream, evaluate(stream, lut, True), lambda i: True)
    own = {c: [0, 0] for c, _ in CLASSES}
    for s in range(segments):
        lo, hi = s * frames // segments, (s + 1) * frames // segments
        if drift == 0:
            rep, ref = stream, lut
        else:
            phase = ((lo + hi - 1) / 2) / (frames - 1)
            ref_dir = f'{root}/d{drift}_t{phase:.3f}'
            synth(ref_dir, drift, phase)
            ref = ref_dir + '/default.lut'
        t = per_frame(stream, evaluate(stream, ref, False), lambda i: lo <= i < hi)
        for c in own:
            own[c][0] += t[c][0]; own[c][1] += t[c][1]
    fmt = lambda t: ' / '.join(f'{recall(t[c]):.3f}' for c, _ in CLASSES)
    ratio = recall(ad['ball']) / max(1e-9, recall(own['ball']))
    print(f'{drift:<6} {fmt(st)}  {fmt(ad)}  {fmt(own)}  {ratio:.3f}', flush=True)
