#!/usr/bin/env python3
"""Whole files with attributes, drm against Draco, in one run.

For every mesh of a folder (default ../shared/meshes-attributes): drm's file
(default options: every attribute kept, 12-bit positions, 10-bit normals,
12-bit texture coordinates) with its sections from `drm info --json`, and
Draco's (`draco_encoder -qp 12 -qt 12 -qn 10 -cl 10`, all attributes it
reads); decode time of both, best of --runs whole processes (PLY out on both
sides). Prints Markdown tables; --csv writes the figures.

Draco does not read every attribute drm keeps: its PLY reader drops texture
coordinates (s, t), its OBJ reader vertex colours (`v x y z r g b`), and it
keeps no material names, texture file names or qualities. What it kept is
asked of Draco itself (normals and texture coordinates: `--skip NORMAL`,
`--skip TEX_COORD` give a smaller file; colours: its decoded PLY has `red`).
Where Draco dropped something, drm encodes the mesh again keeping only what
Draco kept (`--attributes LIST`), so that one column compares the same data.
An ASCII PLY whose texture coordinates Draco drops is also written as an OBJ
(v, vt, vn per vertex, in a temporary folder) and both codecs encode that,
to compare the texture coordinates themselves.

usage: attributes_vs_draco.py [--drm build/bin/drm] [--dir DIR] [--runs 3] [--csv F]
"""
import argparse, csv, json, os, subprocess, sys, tempfile, time

DRACO_OPTIONS = ["-qp", "12", "-qt", "12", "-qn", "10", "-cl", "10"]
# drm's attribute sections by the Draco attribute that would carry them
# (sections missing here, such as qualities, materials, texture names and
# metadata, Draco never keeps).
DRACO_KIND = {"normals": "NORMAL", "corner-normals": "NORMAL", "texcoords": "TEX_COORD",
              "corner-texcoords": "TEX_COORD", "colors": "COLOR"}


def run(cmd):
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def best_time(cmd, runs):
    best = None
    for _ in range(runs):
        t = time.perf_counter()
        run(cmd)
        dt = time.perf_counter() - t
        best = dt if best is None else min(best, dt)
    return best


def draco_size(src, out, extra=()):
    run(["draco_encoder", "-i", src, "-o", out] + DRACO_OPTIONS + list(extra))
    return os.path.getsize(out)


def draco_kept(src, tmp, full_bytes, decoded_ply):
    """The attribute kinds Draco's file of src holds."""
    kept = set()
    probe = os.path.join(tmp, "probe.drc")
    for kind in ("NORMAL", "TEX_COORD"):
        if draco_size(src, probe, ["--skip", kind]) < full_bytes:
            kept.add(kind)
    with open(decoded_ply, "rb") as f:
        header = f.read(4096).split(b"end_header")[0]
    if b" red" in header:
        kept.add("COLOR")
    return kept


def drm_sections(drm, drm_file):
    info = json.loads(subprocess.run([drm, "info", drm_file, "--json"], check=True, capture_output=True, text=True).stdout)
    return [(s["name"], s["bytes"]) for s in info.get("attributes", [])]  # a name may repeat (materials)


def ascii_ply_as_obj(src, dst):
    """Writes an ASCII PLY with x y z, s t (and nx ny nz) per vertex as an OBJ
    with one v, vt (and vn) per vertex; False where the file is not such a
    PLY (binary, no s t, colours an OBJ cannot carry for Draco)."""
    with open(src, "rb") as f:
        data = f.read()
    if not data.startswith(b"ply\nformat ascii 1.0\n"):
        return False
    lines = data.decode("ascii", "replace").split("\n")
    props, counts, element, i = [], {}, None, 0
    while lines[i] != "end_header":
        w = lines[i].split()
        if w[:1] == ["element"]:
            element = w[1]
            counts[element] = int(w[2])
        elif w[:1] == ["property"] and element == "vertex":
            props.append(w[-1])
        i += 1
    at = {p: k for k, p in enumerate(props)}
    if not {"x", "y", "z", "s", "t"} <= at.keys() or "red" in at:
        return False
    normals = {"nx", "ny", "nz"} <= at.keys()
    body = lines[i + 1:]
    nv = counts["vertex"]
    with open(dst, "w") as o:
        for v in body[:nv]:
            a = v.split()
            o.write("v %s %s %s\nvt %s %s\n" % (a[at["x"]], a[at["y"]], a[at["z"]], a[at["s"]], a[at["t"]]))
            if normals:
                o.write("vn %s %s %s\n" % (a[at["nx"]], a[at["ny"]], a[at["nz"]]))
        for face in body[nv:nv + counts.get("face", 0)]:
            ids = [int(x) + 1 for x in face.split()[1:]]
            o.write("f " + " ".join(("%d/%d/%d" if normals else "%d/%d") % ((x,) * (3 if normals else 2)) for x in ids) + "\n")
    return True


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.normpath(os.path.join(here, "..", ".."))
    ap = argparse.ArgumentParser()
    ap.add_argument("--drm", default=os.path.join(root, "build", "bin", "drm"))
    ap.add_argument("--dir", default=os.path.join(root, "..", "shared", "meshes-attributes"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--csv")
    a = ap.parse_args()
    rows, through_obj = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for name in sorted(os.listdir(a.dir)):
            if not name.endswith((".ply", ".obj")):
                continue
            src = os.path.join(a.dir, name)
            stem = os.path.splitext(name)[0]
            drm_file, drc_file = os.path.join(tmp, stem + ".drm"), os.path.join(tmp, stem + ".drc")
            drm_ply, drc_ply = os.path.join(tmp, stem + "-drm.ply"), os.path.join(tmp, stem + "-drc.ply")
            run([a.drm, "encode", src, drm_file])
            draco_bytes = draco_size(src, drc_file)
            sections = drm_sections(a.drm, drm_file)
            t_drm = best_time([a.drm, "decode", drm_file, drm_ply], a.runs)
            t_drc = best_time(["draco_decoder", "-i", drc_file, "-o", drc_ply], a.runs)
            kept = draco_kept(src, tmp, draco_bytes, drc_ply)
            names = sorted({s for s, _ in sections})
            same = [s for s in names if DRACO_KIND.get(s) in kept]
            dropped = [s for s in names if s not in same]
            same_bytes = os.path.getsize(drm_file)
            if dropped:
                same_file = os.path.join(tmp, stem + "-same.drm")
                run([a.drm, "encode", src, same_file, "--attributes", ",".join(same) if same else "none"])
                same_bytes = os.path.getsize(same_file)
            rows.append({"mesh": name, "drm_bytes": os.path.getsize(drm_file), "draco_bytes": draco_bytes,
                         "drm_attribute_bytes": sum(b for _, b in sections),
                         "sections": ", ".join("%s %d" % kv for kv in sections),
                         "draco_drops": " ".join(dropped), "drm_same_attributes_bytes": same_bytes,
                         "drm_decode_s": t_drm, "draco_decode_s": t_drc})
            obj = os.path.join(tmp, stem + "-as.obj")
            if name.endswith(".ply") and "TEX_COORD" not in kept and ascii_ply_as_obj(src, obj):
                obj_drm = os.path.join(tmp, stem + "-as.drm")
                run([a.drm, "encode", obj, obj_drm])
                obj_sections = drm_sections(a.drm, obj_drm)
                full = draco_size(obj, os.path.join(tmp, "as.drc"))
                no_uv = draco_size(obj, os.path.join(tmp, "as.drc"), ["--skip", "TEX_COORD"])
                through_obj.append({"mesh": name, "drm_bytes": os.path.getsize(obj_drm), "draco_bytes": full,
                                    "drm_uv_bytes": sum(b for s, b in obj_sections if DRACO_KIND.get(s) == "TEX_COORD"),
                                    "draco_uv_bytes": full - no_uv})
    print("| mesh | drm bytes | Draco bytes | drm / Draco | Draco drops | drm, Draco's attributes only | that / Draco "
          "| drm attribute sections (bytes) | decode drm / Draco |")
    print("|---|---:|---:|---:|---|---:|---:|---|---:|")
    for r in rows:
        print("| %s | %d | %d | %.3f | %s | %d | %.3f | %s | %.2f |" % (
            r["mesh"], r["drm_bytes"], r["draco_bytes"], r["drm_bytes"] / r["draco_bytes"], r["draco_drops"] or "-",
            r["drm_same_attributes_bytes"], r["drm_same_attributes_bytes"] / r["draco_bytes"], r["sections"],
            r["drm_decode_s"] / r["draco_decode_s"]))
    smaller = sum(1 for r in rows if r["drm_bytes"] <= r["draco_bytes"])
    same = sum(1 for r in rows if r["drm_same_attributes_bytes"] <= r["draco_bytes"])
    print("\ndrm's file is no larger than Draco's on %d of %d meshes; keeping only what Draco keeps, on %d of %d."
          % (smaller, len(rows), same, len(rows)))
    if through_obj:
        print("\nPLY texture coordinates Draco drops, both codecs given the same mesh as an OBJ (v, vt, vn per vertex):\n")
        print("| mesh | drm bytes | Draco bytes | drm / Draco | drm texture coordinates | Draco's | drm / Draco |")
        print("|---|---:|---:|---:|---:|---:|---:|")
        for r in through_obj:
            print("| %s | %d | %d | %.3f | %d | %d | %.3f |" % (r["mesh"], r["drm_bytes"], r["draco_bytes"],
                  r["drm_bytes"] / r["draco_bytes"], r["drm_uv_bytes"], r["draco_uv_bytes"],
                  r["drm_uv_bytes"] / r["draco_uv_bytes"]))
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    sys.exit(main())
