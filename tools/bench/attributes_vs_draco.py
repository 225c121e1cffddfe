#!/usr/bin/env python3
"""Whole files with attributes, drm against Draco, in one run.

For every mesh of a folder (default ../shared/meshes-attributes): drm's file
(default options: every attribute kept, 12-bit positions, 10-bit normals,
12-bit texture coordinates) with its sections from `drm info --json`, and
Draco's (`draco_encoder -qp 12 -qt 12 -qn 10 -cl 10`, all attributes kept);
decode time of both, best of --runs whole processes (PLY out on both sides).
Prints a Markdown table; --csv writes the figures.

usage: attributes_vs_draco.py [--drm build/bin/drm] [--dir DIR] [--runs 3] [--csv F]
"""
import argparse, csv, json, os, subprocess, sys, tempfile, time


def best_time(cmd, runs):
    best = None
    for _ in range(runs):
        t = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        dt = time.perf_counter() - t
        best = dt if best is None else min(best, dt)
    return best


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.normpath(os.path.join(here, "..", ".."))
    ap = argparse.ArgumentParser()
    ap.add_argument("--drm", default=os.path.join(root, "build", "bin", "drm"))
    ap.add_argument("--dir", default=os.path.join(root, "..", "shared", "meshes-attributes"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--csv")
    a = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name in sorted(os.listdir(a.dir)):
            if not name.endswith((".ply", ".obj")):
                continue
            src = os.path.join(a.dir, name)
            stem = os.path.splitext(name)[0]
            drm_file, drc_file = os.path.join(tmp, stem + ".drm"), os.path.join(tmp, stem + ".drc")
            subprocess.run([a.drm, "encode", src, drm_file], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            subprocess.run(["draco_encoder", "-i", src, "-o", drc_file, "-qp", "12", "-qt", "12", "-qn", "10", "-cl", "10"],
                           check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            info = json.loads(subprocess.run([a.drm, "info", drm_file, "--json"], check=True, capture_output=True, text=True).stdout)
            sections = ", ".join("%s %d" % (s["name"], s["bytes"]) for s in info.get("attributes", []))
            t_drm = best_time([a.drm, "decode", drm_file, os.path.join(tmp, stem + "-drm.ply")], a.runs)
            t_drc = best_time(["draco_decoder", "-i", drc_file, "-o", os.path.join(tmp, stem + "-drc.ply")], a.runs)
            rows.append({"mesh": name, "drm_bytes": os.path.getsize(drm_file), "draco_bytes": os.path.getsize(drc_file),
                         "drm_attribute_bytes": info.get("attribute_bytes", 0), "sections": sections,
                         "drm_decode_s": t_drm, "draco_decode_s": t_drc})
    print("| mesh | drm bytes | Draco bytes | drm / Draco | drm attribute sections (bytes) | decode drm / Draco |")
    print("|---|---:|---:|---:|---|---:|")
    for r in rows:
        print("| %s | %d | %d | %.3f | %s | %.2f |" % (r["mesh"], r["drm_bytes"], r["draco_bytes"],
              r["drm_bytes"] / r["draco_bytes"], r["sections"], r["drm_decode_s"] / r["draco_decode_s"]))
    smaller = sum(1 for r in rows if r["drm_bytes"] <= r["draco_bytes"])
    print("\ndrm's file is no larger than Draco's on %d of %d meshes." % (smaller, len(rows)))
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    sys.exit(main())
