#!/usr/bin/env python3
"""Localization battery analysis (doc/results-localization.md): reads runs listed in a TSV
(run_dir, sequence_dir, group) and prints success / ATE / convergence as simp-eval traj computes them,
plus what the localization state is worth:
  - localized_ok: fraction of steps in state 'localized' whose error is <= 0.3 m and pi/4 rad;
  - kidnap: time from the kidnap (Q/kidnap.json) to the first 'lost' step and to the first
    'localized' step after it whose error is within the bounds.
  - with --runs, one row per run: success, convergence, ATE and the share of steps within the bounds.
Standard library only. Usage: analyze_runs.py runs.tsv [--json] [--runs]"""
import csv, json, math, os, subprocess, sys
from collections import defaultdict

def read_tum(path):
    out = []
    with open(path) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            t, x, y, z, qx, qy, qz, qw = map(float, line.split())
            out.append((t, x, y, 2.0 * math.atan2(qz, qw)))
    return out

def interp(gt, t):
    lo, hi = 0, len(gt) - 1
    if t < gt[0][0] or t > gt[-1][0]:
        return None
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if gt[mid][0] <= t: lo = mid
        else: hi = mid
    a, b = gt[lo], gt[hi]
    u = 0.0 if b[0] == a[0] else (t - a[0]) / (b[0] - a[0])
    dphi = math.atan2(math.sin(b[3] - a[3]), math.cos(b[3] - a[3]))
    return (a[1] + u * (b[1] - a[1]), a[2] + u * (b[2] - a[2]), a[3] + u * dphi)

def err(gt, t, x, y, phi):
    g = interp(gt, t)
    if g is None: return None
    d = math.atan2(math.sin(phi - g[2]), math.cos(phi - g[2]))
    return math.hypot(x - g[0], y - g[1]), abs(d)

def main():
    rows = list(csv.reader(open(sys.argv[1]), delimiter='\t'))
    evalbin = os.environ.get('SIMP_EVAL', 'build/bin/simp-eval')
    groups = defaultdict(list)
    loc = defaultdict(lambda: [0, 0])   # group -> [localized steps, within the bounds]
    kid = defaultdict(list)             # config -> [(lost_s, relocalized_s)]
    for run, seq, group in rows:
        gt = read_tum(os.path.join(seq, 'groundtruth.tum'))
        r = subprocess.run([evalbin, 'traj', '--gt', os.path.join(seq, 'groundtruth.tum'), '--est',
                            os.path.join(run, 'estimate.tum'), '--json'], capture_output=True, text=True)
        m = json.loads(r.stdout.strip().splitlines()[-1]) if r.returncode == 0 else {'success': False, 'error': r.stderr.strip()}
        steps = list(csv.DictReader(open(os.path.join(run, 'steps.csv'))))
        kidnap_t = None
        kj = os.path.join(seq, 'kidnap.json')
        if os.path.exists(kj):
            kidnap_t = json.load(open(kj))['t_s']
        t0 = float(steps[0]['time_s'])
        lost_at = reloc_at = None
        n_err = n_within = 0
        for s in steps:
            t = float(s['time_s'])
            e = err(gt, t, float(s['est_x_m']), float(s['est_y_m']), float(s['est_phi_rad']))
            if e is None: continue
            within = e[0] <= 0.3 and e[1] <= math.pi / 4
            n_err += 1
            n_within += within
            if s['state'] == 'localized':
                loc[group][0] += 1
                loc[group][1] += within
            if kidnap_t is not None and t >= kidnap_t:
                if lost_at is None and s['state'] in ('lost', 'global'):
                    lost_at = t - kidnap_t
                if lost_at is not None and reloc_at is None and s['state'] == 'localized' and within:
                    reloc_at = t - kidnap_t
        m['localized_steps'] = sum(1 for s in steps if s['state'] == 'localized')
        m['kidnap_lost_s'] = lost_at
        m['kidnap_relocalized_s'] = reloc_at
        m['run'] = run
        m['within_share'] = n_within / max(1, n_err)
        groups[group].append(m)
        if kidnap_t is not None:
            kid[group.split('/')[0]].append((lost_at, reloc_at))
    out = {}
    if '--runs' in sys.argv:
        print('| run | success | conv s | ATE m | ATE rad | steps within bounds | kidnap: lost s | localized again s |')
        print('|---|---|---:|---:|---:|---:|---:|---:|')
        for g, ms in sorted(groups.items()):
            for m in ms:
                num = lambda k, fmt: fmt % m[k] if m.get(k) is not None else '-'
                conv = num('convergence_time_s', '%.1f') if m.get('converged') else '-'
                print(f"| {os.path.basename(m['run'])} | {'yes' if m.get('success') else 'no'} | {conv} | "
                      f"{num('ate_trans_m', '%.3f')} | {num('ate_rot_rad', '%.3f')} | {100 * m['within_share']:.0f} % | "
                      f"{num('kidnap_lost_s', '%.1f')} | {num('kidnap_relocalized_s', '%.1f')} |")
        print()
    print('| group | runs | success | ATE m | ATE rad | median conv s | localized steps within bounds |')
    print('|---|---:|---:|---:|---:|---:|---:|')
    for g, ms in sorted(groups.items()):
        ok = [m for m in ms if m.get('success')]
        ate_t = sum(m['ate_trans_m'] for m in ok) / len(ok) if ok else float('nan')
        ate_r = sum(m['ate_rot_rad'] for m in ok) / len(ok) if ok else float('nan')
        conv = sorted(m['convergence_time_s'] for m in ms if m.get('converged'))
        med = conv[len(conv) // 2] if conv else float('nan')
        lt, lk = loc[g]
        print(f'| {g} | {len(ms)} | {len(ok)}/{len(ms)} ({100*len(ok)/len(ms):.0f} %) | {ate_t:.3f} | {ate_r:.3f} | {med:.1f} | {lk}/{lt} ({100.0*lk/max(1,lt):.1f} %) |')
        out[g] = {'runs': len(ms), 'success': len(ok), 'ate_trans_m': ate_t, 'ate_rot_rad': ate_r, 'median_convergence_s': med}
    print()
    for cfg, ks in sorted(kid.items()):
        lost5 = sum(1 for l, r in ks if l is not None and l <= 5)
        rel20 = sum(1 for l, r in ks if l is not None and l <= 5 and r is not None and r <= 20)
        print(f'kidnap {cfg}: lost within 5 s {lost5}/{len(ks)}, and localized again (within bounds) within 20 s {rel20}/{len(ks)}')
    fails = [m['run'] for ms in groups.values() for m in ms if not m.get('success')]
    if fails:
        print('failed runs: ' + ' '.join(fails))
    if '--json' in sys.argv:
        print(json.dumps(out))

if __name__ == "__main__":
    main()
