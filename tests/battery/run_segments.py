#!/usr/bin/env python3
"""Where one localization run leaves the bounds (doc/results-localization.md, how failures are read).
Reads RUN/steps.csv and SEQ/groundtruth.tum; from the first `localized` step on (where estimate.tum
starts), lists each stretch whose reported estimate is outside 0.3 m / pi/4 rad: its times, length,
largest error, the states and detections per step in it, and its largest one-step move of the
estimate against the truth's, with that step's detections and whether it updated (a move near the
stretch's error is a jump: the reported cluster changed, e.g. a minority of the set won an update; a
small one, a slide over several updates). Ends with the time outside in all (from the first
`localized` step; simp-eval traj counts it from the converging estimate on and compares it with
max_outside_s). Standard library only.
Usage: run_segments.py RUN SEQ"""
import csv, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from analyze_runs import err, interp, read_tum  # noqa: E402

MAX_TRANS_M, MAX_ROT_RAD = 0.3, math.pi / 4


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    run, seq = sys.argv[1], sys.argv[2]
    gt = read_tum(os.path.join(seq, 'groundtruth.tum'))
    rows = list(csv.DictReader(open(os.path.join(run, 'steps.csv'))))
    t_start = gt[0][0]  # times are printed from the sequence's start
    segments, current, started, prev = [], None, False, None
    total = 0.0
    for i, r in enumerate(rows):
        t = float(r['time_s'])
        started = started or r['state'] == 'localized'
        g = interp(gt, t)
        if not started or g is None:
            continue
        x, y, phi = float(r['est_x_m']), float(r['est_y_m']), float(r['est_phi_rad'])
        e_xy, e_phi = err(gt, t, x, y, phi)
        # The estimate's move over the step less the truth's: what the filter did, not the robot.
        move = 0.0
        if prev is not None:
            move = math.hypot((x - prev[0]) - (g[0] - prev[2]), (y - prev[1]) - (g[1] - prev[3]))
        prev = (x, y, g[0], g[1])
        # Each estimate holds until the next one (simp-eval traj's zero-order hold).
        hold = float(rows[i + 1]['time_s']) - t if i + 1 < len(rows) else 0.0
        if e_xy > MAX_TRANS_M or e_phi > MAX_ROT_RAD:
            total += hold
            if current is None:
                current = {'t0': t, 'held': 0.0, 'max_m': 0.0, 'states': {}, 'detections': 0, 'steps': 0,
                           'jump': (0.0, t, 0, 0)}
            c = current
            c['t1'], c['held'] = t, c['held'] + hold
            c['max_m'] = max(c['max_m'], e_xy)
            c['states'][r['state']] = c['states'].get(r['state'], 0) + 1
            c['detections'] += int(r['detections'] or 0)
            c['steps'] += 1
            if c['steps'] == 1 or move > c['jump'][0]:
                c['jump'] = (move, t, int(r['detections'] or 0), int(r['updated'] or 0))
        elif current is not None:
            segments.append(current)
            current = None
    if current is not None:
        segments.append(current)
    print('| from s | to s | outside s | max error m | states (steps) | detections per step | largest move m (at s, K, updated) |')
    print('|---:|---:|---:|---:|---|---:|---|')
    for c in segments:
        states = ', '.join(f'{k} {v}' for k, v in sorted(c['states'].items()))
        move, at, k, upd = c['jump']
        print(f"| {c['t0'] - t_start:.1f} | {c['t1'] - t_start:.1f} | {c['held']:.1f} | {c['max_m']:.2f} | {states} | "
              f"{c['detections'] / c['steps']:.1f} | {move:.2f} ({at - t_start:.1f}, {k}, {upd}) |")
    print(f'\ntime outside the bounds: {total:.1f} s in {len(segments)} stretches')


if __name__ == '__main__':
    main()
