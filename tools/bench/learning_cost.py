#!/usr/bin/env python3
"""What the vertex coder's adaptive models cost to learn, per mesh: an
upper bound on what better starting probabilities could save.

Usage: tools/bench/learning_cost.py MESH.ply... [--drm build/bin/drm] [--bits 12]

For each mesh, a second copy is placed beside it (shifted by its extent
along its longest axis) and the pair is coded at bits + 1, which keeps the
quantization step that of the single mesh at `bits` (to about 0.01 %). The
second copy is then coded with models trained on the first, so whatever it
saves is all that perfect priors could save. Geometry bytes come from
`drm info`; the tree coder is forced (`--geometry tree`) so that both
files code vertices the same way. Needs numpy (Debian: python3-numpy).
Results: docs/tuning.md, "What learning costs small meshes".
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_big_mesh import read_ply, write_ply  # noqa: E402


def geometry_bytes(drm, mesh, out, bits):
    subprocess.run([drm, "encode", mesh, out, "--geometry", "tree", "--bits", str(bits)],
                   check=True, stdout=subprocess.DEVNULL)
    info = subprocess.run([drm, "info", out], check=True, capture_output=True, text=True).stdout
    return int(re.search(r"^geometry bytes\s+(\d+)", info, re.M).group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("--drm", default="build/bin/drm")
    parser.add_argument("--bits", type=int, default=12)
    args = parser.parse_args()
    print("| mesh | vertices | geometry, one copy | two copies | second copy saves |")
    print("|---|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        for mesh in args.meshes:
            vertices, faces = read_ply(mesh)
            extent = vertices.max(axis=0) - vertices.min(axis=0)
            shift = np.zeros(3)
            shift[int(np.argmax(extent))] = extent.max()
            pair = os.path.join(tmp, "pair.ply")
            write_ply(pair, np.concatenate([vertices, vertices + shift]),
                      np.concatenate([faces, faces + len(vertices)]))
            one = geometry_bytes(args.drm, mesh, os.path.join(tmp, "one.drm"), args.bits)
            two = geometry_bytes(args.drm, pair, os.path.join(tmp, "two.drm"), args.bits + 1)
            saved = 100.0 * (2 * one - two) / one
            name = os.path.splitext(os.path.basename(mesh))[0]
            print(f"| {name} | {len(vertices):,} | {one:,} | {two:,} | {saved:.1f} % |")


if __name__ == "__main__":
    main()
