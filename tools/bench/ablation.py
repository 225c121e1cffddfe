#!/usr/bin/env python3
"""What each encoder change bought, per mesh class: encodes every corpus mesh
with several drm binaries (or option sets) and prints, per class, the
geometric mean of the whole file and of the geometry section in bits per
vertex, and how many meshes are no larger than Draco cl10's file.

Usage:
  tools/bench/ablation.py [--meshes DIR] [--draco docs/data/peers.csv]
                          [--markdown F] LABEL=BINARY[,OPTION...] ...
e.g. to compare two builds, and a build with and without an option:
  tools/bench/ablation.py before=/tmp/drm-410efde after=build/bin/drm \\
                          tree=build/bin/drm,--geometry,tree

Classes come from the "kind" column of the corpus MANIFEST.md: small (under
3000 vertices), CAD (kind names CAD or STL), scans (kind names scan), regular
(regular, subdivided, icosphere), other. A mesh is clean when drm codes it
without a repairs section (no "cut into manifold pieces" note). Draco's
sizes are those of docs/data/peers.csv (drm-peer-bench, same 12-bit grid).
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile


def classes(manifest):
    kinds = {}
    for line in open(manifest):
        cells = [c.strip() for c in line.split('|')]
        if len(cells) > 15 and cells[1].endswith('.ply'):
            vertices, kind = int(cells[3]), cells[-2]
            if vertices < 3000:
                kinds[cells[1]] = 'small'
            elif 'CAD' in kind or 'STL' in kind:
                kinds[cells[1]] = 'CAD'
            elif 'scan' in kind:
                kinds[cells[1]] = 'scans'
            elif any(k in kind for k in ('regular', 'subdivided', 'icosphere')):
                kinds[cells[1]] = 'regular'
            else:
                kinds[cells[1]] = 'other'
    return kinds


def encode(binary, options, mesh, out):
    p = subprocess.run([binary, 'encode', mesh, out] + options, capture_output=True, text=True)
    if p.returncode:
        return None
    info = json.loads(subprocess.run([binary, 'info', '--json', out], capture_output=True, text=True,
                                     check=True).stdout)
    info['clean'] = 'cut into manifold pieces' not in p.stderr
    return info


def geomean(xs):
    return math.exp(sum(map(math.log, xs)) / len(xs)) if xs else float('nan')


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--meshes', default='../shared/meshes')
    ap.add_argument('--draco', default='docs/data/peers.csv')
    ap.add_argument('--markdown')
    ap.add_argument('variants', nargs='+')
    args = ap.parse_args()
    variants = []
    for v in args.variants:
        label, _, rest = v.partition('=')
        parts = rest.split(',')
        variants.append((label, parts[0], parts[1:]))
    draco = {r['mesh']: int(r['total_bytes']) for r in csv.DictReader(open(args.draco))
             if r['codec'] == 'draco cl10' and r['status'] == 'ok'}
    kinds = classes(os.path.join(args.meshes, 'MANIFEST.md'))
    rows = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name in sorted(kinds):
            rows[name] = []
            for label, binary, options in variants:
                info = encode(binary, options, os.path.join(args.meshes, name), os.path.join(tmp, 'a.drm'))
                rows[name].append(info)
            print(name, ' '.join(f"{r['total_bytes'] if r else 'failed'}" for r in rows[name]), file=sys.stderr, flush=True)
    lines = []
    w = lines.append
    w('| class | meshes | ' + ' | '.join(f'{l}: total bpv | {l}: geometry bpv | {l}: vs Draco | {l}: <= Draco'
                                        for l, _, _ in variants) + ' |')
    w('|---|---:|' + '---:|' * (4 * len(variants)))
    groups = sorted(set(kinds.values())) + ['all', 'clean']
    for group in groups:
        names = [n for n in rows if all(rows[n]) and n in draco and
                 (group == 'all' or (group == 'clean' and rows[n][0]['clean']) or kinds[n] == group)]
        cells = []
        for i in range(len(variants)):
            total = geomean([rows[n][i]['total_bpv'] for n in names])
            geometry = geomean([max(rows[n][i]['geometry_bpv'], 1e-9) for n in names])
            ratio = geomean([rows[n][i]['total_bytes'] / draco[n] for n in names])
            smaller = sum(rows[n][i]['total_bytes'] <= draco[n] for n in names)
            cells += [f'{total:.2f}', f'{geometry:.2f}', f'{ratio:.3f}', f'{smaller}']
        w(f'| {group} | {len(names)} | ' + ' | '.join(cells) + ' |')
    w('')
    w('| mesh | class | ' + ' | '.join(f'{l} bytes' for l, _, _ in variants) + ' | Draco cl10 bytes |')
    w('|---|---|' + '---:|' * (len(variants) + 1))
    for n in rows:
        w(f'| {n} | {kinds[n]}{"" if rows[n][0] and rows[n][0]["clean"] else " (repaired)"} | ' +
          ' | '.join(str(r['total_bytes']) if r else 'failed' for r in rows[n]) + f' | {draco.get(n, "")} |')
    text = '\n'.join(lines) + '\n'
    print(text)
    if args.markdown:
        open(args.markdown, 'w').write(text)


if __name__ == '__main__':
    main()
