#!/usr/bin/env python3
"""Time and peak memory of `drm encode` and `drm decode` from 1K to millions of triangles.

Usage (from the project's root, after a build):

    python3 tools/bench/measure_scale.py --lock /tmp/drm-build.lock

1. Makes big meshes by 1-to-4 midpoint subdivision of one corpus mesh
   (default igea.ply, 268,686 triangles: 1 level gives 1.07M, 2 levels 4.3M)
   with tools/bench/make_big_mesh.py, in a temporary folder removed at the end.
2. Picks corpus meshes of several sizes (closest to 1K, 3K, 10K, 30K, 100K
   and 270K triangles).
3. Runs `drm encode IN OUT.drm` and `drm decode OUT.drm OUT.ply` on each, as a
   user would (file reading and writing included), --runs times, and keeps the
   shortest wall time and the smallest peak resident set size (the child's
   ru_maxrss, from wait4). Also `drm --version`: the process's own floor.
4. Runs drm-peer-bench (in-process codec times, drm and Draco side by side) on
   the subdivided meshes, one run each.

5. Encodes the whole corpus folder with `drm encode DIR -o OUT -j N`, N = 1
   and the number of cores, best of 2 (--only selects steps).

Writes docs/data/scale.csv (one row per mesh), docs/data/batch.csv and
docs/data/peers-big.csv (drm-peer-bench's CSV); tools/bench/make_results.py turns the first into the
"Scale" section of docs/results.md, tools/bench/make_plots.py both into plots.

The machine may be shared: --lock FILE takes an exclusive flock on FILE around
every measured run (not around the whole script, so builds waiting on the same
lock get in between). Do not wrap the script itself in `flock` on the same file.
"""
import argparse
import contextlib
import csv
import fcntl
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TARGETS = [1_000, 3_000, 10_000, 30_000, 100_000, 270_000]
COLUMNS = ["mesh", "source", "vertices", "triangles", "input_bytes", "drm_bytes",
           "encode_s", "decode_s", "encode_us_per_tri", "decode_us_per_tri",
           "encode_peak_kb", "decode_peak_kb", "encode_peak_b_per_vertex", "decode_peak_b_per_vertex", "runs"]


@contextlib.contextmanager
def locked(path):
    if not path:
        yield
        return
    with open(path, "a") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


def run_with_rusage(command, lock):
    with locked(lock):
        start = time.perf_counter()
        child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        err = child.stderr.read()
        _, status, usage = os.wait4(child.pid, 0)
        wall = time.perf_counter() - start
        child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed ({child.returncode}): {err.decode().strip()}")
    return wall, usage.ru_maxrss, usage.ru_utime + usage.ru_stime  # ru_maxrss: KiB on Linux


def ply_counts(path):
    vertices = faces = None
    with open(path, "rb") as f:
        for raw in f:
            line = raw.decode("ascii", "replace").strip()
            if line.startswith("element vertex"):
                vertices = int(line.split()[2])
            elif line.startswith("element face"):
                faces = int(line.split()[2])
            elif line == "end_header":
                break
    return vertices, faces


def pick_corpus(meshes_dir, exclude):
    sized = []
    for name in sorted(os.listdir(meshes_dir)):
        if name.endswith(".ply") and name[:-4] not in exclude:
            v, f = ply_counts(os.path.join(meshes_dir, name))
            if v and f:
                sized.append((f, name))
    picked = []
    for target in TARGETS:
        best = min((s for s in sized if s[1] not in picked), key=lambda s: abs((s[0] / target) - 1))
        picked.append(best[1])
    return [os.path.join(meshes_dir, name) for name in picked]


def measure(drm, path, source, runs, lock, work):
    stem = os.path.splitext(os.path.basename(path))[0]
    encoded = os.path.join(work, stem + ".drm")
    decoded = os.path.join(work, stem + ".decoded.ply")
    enc_wall, enc_rss, dec_wall, dec_rss = [], [], [], []
    for _ in range(runs):
        w, r, _ = run_with_rusage([drm, "encode", path, encoded], lock)
        enc_wall.append(w)
        enc_rss.append(r)
        w, r, _ = run_with_rusage([drm, "decode", encoded, decoded], lock)
        dec_wall.append(w)
        dec_rss.append(r)
    info = subprocess.run([drm, "info", encoded, "--json"], capture_output=True, text=True, check=True).stdout
    v = int(re.search(r'"vertices":\s*(\d+)', info).group(1))
    f = int(re.search(r'"faces":\s*(\d+)', info).group(1))
    row = {
        "mesh": stem, "source": source, "vertices": v, "triangles": f,
        "input_bytes": os.path.getsize(path), "drm_bytes": os.path.getsize(encoded),
        "encode_s": f"{min(enc_wall):.3f}", "decode_s": f"{min(dec_wall):.3f}",
        "encode_us_per_tri": f"{min(enc_wall) / f * 1e6:.3f}", "decode_us_per_tri": f"{min(dec_wall) / f * 1e6:.3f}",
        "encode_peak_kb": min(enc_rss), "decode_peak_kb": min(dec_rss),
        "encode_peak_b_per_vertex": f"{min(enc_rss) * 1024 / v:.1f}",
        "decode_peak_b_per_vertex": f"{min(dec_rss) * 1024 / v:.1f}",
        "runs": runs,
    }
    for p in (encoded, decoded):
        os.remove(p)
    print(f"  {stem}: V {v}, T {f}: encode {row['encode_s']} s, {row['encode_peak_kb'] / 1024:.0f} MiB; "
          f"decode {row['decode_s']} s, {row['decode_peak_kb'] / 1024:.0f} MiB", file=sys.stderr)
    return row


def measure_meshes(args, big_source, big, work):
    rows = []
    base_wall, base_rss, _ = run_with_rusage([args.drm, "--version"], args.lock)
    print(f"drm --version: {base_rss / 1024:.1f} MiB peak", file=sys.stderr)
    corpus = pick_corpus(args.meshes, exclude={args.big})
    for path in corpus + [big_source]:
        rows.append(measure(args.drm, path, "corpus", args.runs, args.lock, work))
    for level, path in enumerate(big, start=1):
        rows.append(measure(args.drm, path, f"{args.big} subdivided {level}x (1-to-4)", args.big_runs,
                            args.lock, work))

    os.makedirs(os.path.dirname(args.out) or ".", exist_ok=True)
    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerow({"mesh": "(drm --version)", "source": "process floor", "vertices": "", "triangles": "",
                         "input_bytes": "", "drm_bytes": "", "encode_s": f"{base_wall:.3f}", "decode_s": "",
                         "encode_us_per_tri": "", "decode_us_per_tri": "", "encode_peak_kb": base_rss,
                         "decode_peak_kb": "", "encode_peak_b_per_vertex": "", "decode_peak_b_per_vertex": "",
                         "runs": 1})
        writer.writerows(rows)
    print(f"wrote {args.out}", file=sys.stderr)


def measure_batch(args, work):
    """The whole corpus folder with -j 1 and -j (cores): wall and CPU seconds, best of 2 by wall."""
    batch = []
    for jobs in sorted({1, os.cpu_count() or 1}):
        best = None
        for _ in range(2):
            out_dir = os.path.join(work, f"batch-j{jobs}")
            wall, rss, cpu = run_with_rusage([args.drm, "encode", args.meshes, "-o", out_dir, "-j", str(jobs)],
                                             args.lock)
            shutil.rmtree(out_dir, ignore_errors=True)
            best = (wall, rss, cpu) if best is None or wall < best[0] else best
        files = sum(1 for n in os.listdir(args.meshes) if n.lower().endswith((".ply", ".obj", ".off", ".stl")))
        batch.append({"files": files, "jobs": jobs, "wall_s": f"{best[0]:.3f}", "cpu_s": f"{best[2]:.3f}",
                      "peak_kb": best[1]})
        print(f"  drm encode {args.meshes} -o DIR -j {jobs}: {best[0]:.2f} s wall, {best[2]:.2f} s CPU",
              file=sys.stderr)
    with open(args.batch_out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["files", "jobs", "wall_s", "cpu_s", "peak_kb"])
        writer.writeheader()
        writer.writerows(batch)
    print(f"wrote {args.batch_out}", file=sys.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--drm", default="build/bin/drm")
    parser.add_argument("--peer-bench", default="build/bin/drm-peer-bench")
    parser.add_argument("--meshes", default="../shared/meshes")
    parser.add_argument("--big", default="igea", help="corpus mesh to subdivide (default igea)")
    parser.add_argument("--levels", type=int, default=2, help="largest subdivision level (default 2: 16x triangles)")
    parser.add_argument("--runs", type=int, default=3, help="runs per mesh, best kept (default 3)")
    parser.add_argument("--big-runs", type=int, default=2, help="runs per subdivided mesh (default 2)")
    parser.add_argument("--lock", help="flock this file around every measured run")
    parser.add_argument("--out", default="docs/data/scale.csv")
    parser.add_argument("--peers-out", default="docs/data/peers-big.csv")
    parser.add_argument("--batch-out", default="docs/data/batch.csv")
    parser.add_argument("--only", action="append", choices=["meshes", "batch", "peers"],
                        help="run only these steps (repeatable): meshes (scale.csv), batch (batch.csv), "
                             "peers (peers-big.csv); default all")
    args = parser.parse_args()
    steps = set(args.only or ["meshes", "batch", "peers"])

    work = tempfile.mkdtemp(prefix="drm-scale-")
    try:
        big_source = os.path.join(args.meshes, args.big + ".ply")
        big = []
        for level in (range(1, args.levels + 1) if steps & {"meshes", "peers"} else []):
            out = os.path.join(work, f"{args.big}-x{4 ** level}.ply")
            subprocess.run([sys.executable, os.path.join(HERE, "make_big_mesh.py"), big_source, out,
                            "--levels", str(level)], check=True)
            big.append(out)

        if "meshes" in steps:
            measure_meshes(args, big_source, big, work)
        if "batch" in steps:
            measure_batch(args, work)
        if "peers" in steps:
            print("drm-peer-bench on the subdivided meshes ...", file=sys.stderr)
            with locked(args.lock):
                subprocess.run([args.peer_bench, *big, "--runs", "1", "--csv", args.peers_out],
                               stdout=subprocess.DEVNULL, check=True)
            print(f"wrote {args.peers_out}", file=sys.stderr)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
