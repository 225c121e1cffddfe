#!/usr/bin/env python3
"""Encoding CPU of drm builds side by side, mesh by mesh, over a folder.

Usage: tools/bench/encode_cpu.py BEFORE AFTER [--runs 3] [--meshes DIR]
                                 [-- ENCODE OPTIONS...]

Runs `BINARY encode MESH OUT.drm [ENCODE OPTIONS]` for every mesh of DIR
(default: the corpus, shared/meshes beside the repository), the binaries
in turn (BEFORE AFTER BEFORE AFTER ...,
so that the machine's drift falls on both), and takes each run's CPU time,
user and system, of the finished process (the whole process: reading the
mesh and writing the file included). Prints each mesh's median for each
binary and their ratio, then the sums of the medians, by size (faces:
under 4,096, 4,096 to 20,000, 20,000 to 65,536, more) and in all.

CPU time, not wall time: the encoder's second thread overlaps its work,
and what is compared here is the work. For wall time against a peer, run
both in alternation under /usr/bin/time (docs/performance.md). Needs no
module beyond Python's own.
"""
import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile

CLASSES = [(4096, "under 4,096 faces"), (20000, "4,096 to 20,000"), (65536, "20,000 to 65,536"),
           (None, "65,536 and more")]


def face_count(path):
    """The face count a PLY header declares (0 if it declares none)."""
    with open(path, "rb") as f:
        for raw in f:
            line = raw.decode("ascii", "replace").split()
            if line[:2] == ["element", "face"]:
                return int(line[2])
            if line[:1] == ["end_header"]:
                break
    return 0


def cpu_seconds(command):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    run = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if run.returncode != 0:
        sys.exit("failed (exit %d): %s\n%s" % (run.returncode, " ".join(command), run.stderr.decode(errors="replace")))
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--runs", type=int, default=3)
    repository = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
    parser.add_argument("--meshes", default=os.path.join(os.path.dirname(repository), "shared", "meshes"))
    # What follows the first -- goes to `drm encode` as it is.
    argv = sys.argv[1:]
    options = argv[argv.index("--") + 1:] if "--" in argv else []
    args = parser.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    args.options = options
    meshes = sorted(os.path.join(args.meshes, m) for m in os.listdir(args.meshes) if m.endswith(".ply"))
    if not meshes:
        sys.exit("no .ply meshes in " + args.meshes)
    binaries = [args.before, args.after]
    sums = {label: [0.0, 0.0] for _, label in CLASSES}
    with tempfile.TemporaryDirectory() as out:
        target = os.path.join(out, "out.drm")
        for mesh in meshes:
            times = [[], []]
            for _ in range(args.runs):
                for i, binary in enumerate(binaries):
                    times[i].append(cpu_seconds([binary, "encode", mesh, target] + args.options))
            medians = [statistics.median(t) for t in times]
            faces = face_count(mesh)
            label = next(l for bound, l in CLASSES if bound is None or faces < bound)
            for i in range(2):
                sums[label][i] += medians[i]
            print("%-28s %8d faces  %7.3f %7.3f s  ratio %.2f" %
                  (os.path.basename(mesh), faces, medians[0], medians[1], medians[1] / medians[0]), flush=True)
    total = [sum(s[i] for s in sums.values()) for i in range(2)]
    for _, label in CLASSES:
        before, after = sums[label]
        if before > 0:
            print("%-20s %7.2f -> %7.2f s  ratio %.3f" % (label, before, after, after / before))
    print("%-20s %7.2f -> %7.2f s  ratio %.3f" % ("all", total[0], total[1], total[1] / total[0]))


if __name__ == "__main__":
    main()
