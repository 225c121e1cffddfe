#!/usr/bin/env python3
"""Regenerates docs/results.md from `drm bench` runs on the benchmark corpus.

Usage: tools/bench/make_results.py [--drm build/bin/drm] [--meshes ../shared/meshes] [--out docs/results.md]
       tools/bench/make_results.py --scale-only     # only rewrite the plots and "Scale" sections

Every figure in the output comes from the runs this script makes; the
paper's and the method notes' figures are quoted from their tables. The
"Scale" section comes from docs/data/scale.csv and docs/data/batch.csv,
recorded by tools/bench/measure_scale.py (minutes of runs, so not redone
here); the plots are drawn by tools/bench/make_plots.py.
"""
import argparse
import csv
import datetime
import math
import os
import subprocess
import sys
import tempfile

PAPER_MODELS = ["bunny", "fandisk", "feline", "horse", "horse-lres", "nefertiti", "venus", "venus-lres"]
# Table 4 (DR) and the best other coder listed there; drm aims at the smaller of the two.
PAPER_DR = {"bunny": 0.59, "fandisk": 0.65, "feline": 1.95, "horse": 0.70, "horse-lres": 0.44,
            "nefertiti": 1.66, "venus": 1.79, "venus-lres": 2.30}
BEST_OTHER = {"bunny": ("Nopt", 1.07), "fandisk": ("FL", 0.74), "feline": ("FL", 1.23), "horse": ("Nopt", 1.33),
              "horse-lres": ("FL", 0.96), "nefertiti": ("Nopt", 2.37), "venus": ("FL", 1.73), "venus-lres": ("AA", 1.95)}
# ../shared/docs/method-notes.md: a faithful reproduction (best of two prototypes).
FAITHFUL_NOTES = {"bunny": 0.88, "fandisk": 1.02, "feline": 1.83, "horse": 1.19, "horse-lres": 0.88,
                  "nefertiti": 2.62, "venus": 2.47, "venus-lres": 3.23}
# Table 5, DR Geom (MMG06 point coder), bits per vertex at 12 bits.
PAPER_GEOMETRY = {"bunny": 11.68, "fandisk": 12.79, "horse": 11.09, "armadillo": 11.84, "rabbit": 9.86}

LEVER_SETS = [
    ("none (the paper's method)", "none"),
    ("filter", "filter"),
    ("gap", "gap"),
    ("context", "context"),
    ("angle", "angle"),
    ("front", "front"),
    ("boundary", "boundary"),
    ("all but filter", "gap,context,angle,front,boundary"),
    ("all but gap", "filter,context,angle,front,boundary"),
    ("all but context", "filter,gap,angle,front,boundary"),
    ("all but angle", "filter,gap,context,front,boundary"),
    ("all but front", "filter,gap,context,angle,boundary"),
    ("all but boundary", "filter,gap,context,angle,front"),
    ("all", "all"),
]


def bench(drm, files, *options):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "bench.csv")
        subprocess.run([drm, "bench", *files, "--csv", out, *options],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(out) as f:
            return {os.path.splitext(row["mesh"])[0]: row for row in csv.DictReader(f)}


def read_rows(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


PLOTS_HEADING = "## Against the codecs people use (plots)"


def time_trend(data_dir):
    """A sentence: median µs per triangle on the corpus against the largest subdivided mesh, drm and Draco."""
    corpus = read_rows(os.path.join(data_dir, "peers.csv"))
    big = read_rows(os.path.join(data_dir, "peers-big.csv"))
    if not corpus or not big:
        return ""
    largest = max((r for r in big if r["status"] == "ok"), key=lambda r: int(r["triangles"]))
    parts = []
    for codec in ("drm", "draco cl10"):
        cells = []
        for column, verb in (("encode_s", "encode"), ("decode_s", "decode")):
            per = sorted(float(r[column]) / int(r["triangles"]) * 1e6 for r in corpus
                         if r["codec"] == codec and r["status"] == "ok" and int(r["triangles"]) >= 1000)
            if not per:
                return ""
            median = per[len(per) // 2]
            at = next(float(r[column]) / int(r["triangles"]) * 1e6 for r in big
                      if r["codec"] == codec and r["mesh"] == largest["mesh"])
            cells.append(f"{verb} {median:.2f} -> {at:.2f} µs ({at / median:.2f}x)")
        parts.append(f"{codec}: " + ", ".join(cells))
    return (f"Time per triangle, median over the corpus meshes of 1K triangles and more, then on "
            f"{largest['mesh']} ({int(largest['triangles']):,} triangles): " + "; ".join(parts) + ".")


def plots_section(data_dir="docs/data"):
    trend = time_trend(data_dir)
    return [PLOTS_HEADING, "",
            "From `docs/peers.md`'s run (`drm-peer-bench ../shared/meshes --csv docs/data/peers.csv`) and, for the "
            "two largest sizes, igea subdivided (`tools/bench/measure_scale.py`); drawn by "
            "`python3 tools/bench/make_plots.py`.", "",
            "![connectivity bits per vertex per mesh: drm, the paper, Draco, meshoptimizer, OpenCTM]"
            "(images/peers-connectivity.png)", "",
            "![encode and decode time per triangle against mesh size, drm and Draco](images/time-per-triangle.png)",
            ""] + ([trend, ""] if trend else [])


def replace_section(text, lines, before=None):
    """text with the section headed lines[0] replaced by lines; a missing one goes before the
    heading `before` if given and present, else at the end."""
    heading = "\n" + lines[0] + "\n"
    section = "\n".join(lines) + "\n"
    start = text.find(heading)
    if start >= 0:
        end = text.find("\n## ", start + 1)
        return text[:start + 1] + section + (text[end + 1:] if end >= 0 else "")
    at = text.find("\n" + before + "\n") if before else -1
    if at >= 0:
        return text[:at + 1] + section + "\n" + text[at + 1:]
    return text.rstrip("\n") + "\n\n" + section


def scale_section(data_dir):
    """The "Scale" section, from measure_scale.py's CSV files."""
    rows = read_rows(os.path.join(data_dir, "scale.csv"))
    batch = read_rows(os.path.join(data_dir, "batch.csv"))
    L = []
    w = L.append
    w("## Scale")
    w("")
    if not rows:
        w("No measurements recorded yet: run `python3 tools/bench/measure_scale.py` (see below).")
        w("")
        return L
    floor = next((int(r["encode_peak_kb"]) for r in rows if r["source"] == "process floor"), 0)
    data = sorted((r for r in rows if r["source"] != "process floor"), key=lambda r: int(r["triangles"]))
    mib = lambda kb: f"{int(kb) / 1024:.0f}" if int(kb) >= 10 * 1024 else f"{int(kb) / 1024:.1f}"
    above = lambda r, col: (int(r[col]) - floor) * 1024 / int(r["vertices"])
    w("`drm encode IN OUT.drm` and `drm decode OUT.drm OUT.ply` run as separate processes, as a user runs them "
      "(reading and writing the files included), on corpus meshes of several sizes and on igea.ply subdivided "
      "1-to-4 at edge midpoints once and twice (`tools/bench/make_big_mesh.py`; made in a temporary folder, not "
      "kept). Wall time is the shortest of the runs; peak memory is the process's maximum resident set size "
      "(`ru_maxrss` from `wait4`), the smallest of the runs. \"B/V\" is peak bytes per vertex; \"above floor\" "
      f"subtracts the {floor / 1024:.1f} MiB that `drm --version` alone takes (code and shared libraries), which "
      "dominates the small meshes. The subdivided meshes are more regular than scans (flat midpoints), so their "
      "rates are not representative; they test time and memory.")
    w("")
    w("| mesh | V | T | .drm bytes | encode s | decode s | encode µs/T | decode µs/T | encode peak MiB | "
      "decode peak MiB | encode B/V | decode B/V | encode B/V above floor | decode B/V above floor | runs |")
    w("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in data:
        name = r["mesh"] + (" (subdivided)" if r["source"] != "corpus" else "")
        w(f"| {name} | {r['vertices']} | {r['triangles']} | {r['drm_bytes']} | {r['encode_s']} | {r['decode_s']} | "
          f"{float(r['encode_us_per_tri']):.2f} | {float(r['decode_us_per_tri']):.2f} | {mib(r['encode_peak_kb'])} | "
          f"{mib(r['decode_peak_kb'])} | {float(r['encode_peak_b_per_vertex']):.0f} | "
          f"{float(r['decode_peak_b_per_vertex']):.0f} | {above(r, 'encode_peak_kb'):.0f} | "
          f"{above(r, 'decode_peak_kb'):.0f} | {r['runs']} |")
    w("")
    big = data[-1]
    source = next((r for r in data if r["source"] == "corpus" and big["mesh"].startswith(r["mesh"] + "-")), None)
    V, T = int(big["vertices"]), int(big["triangles"])
    w(f"The largest mesh, {big['mesh']} ({T:,} triangles, {V:,} vertices, {int(big['input_bytes']) / 1e6:.0f} MB of "
      f"binary PLY): encoded in {float(big['encode_s']):.1f} s with a peak of {int(big['encode_peak_kb']) / 1024:.0f} "
      f"MiB ({float(big['encode_peak_b_per_vertex']):.0f} bytes per vertex), decoded in {float(big['decode_s']):.1f} s "
      f"with a peak of {int(big['decode_peak_kb']) / 1024:.0f} MiB ({float(big['decode_peak_b_per_vertex']):.0f} bytes "
      f"per vertex); the .drm file is {int(big['drm_bytes']):,} bytes.")
    if source:
        k = int(big["triangles"]) / int(source["triangles"])
        ratio = lambda col: float(big[col]) / float(source[col])
        w(f"Against {source['mesh']} itself ({int(source['triangles']):,} triangles, {k:.0f} times fewer), time per "
          f"triangle is {ratio('encode_us_per_tri'):.2f} times as much to encode and {ratio('decode_us_per_tri'):.2f} "
          f"times to decode, and peak memory per vertex {ratio('encode_peak_b_per_vertex'):.2f} and "
          f"{ratio('decode_peak_b_per_vertex'):.2f} times (1 would be exactly linear).")
    w("")
    w("![drm encode and decode: peak memory per vertex and time per triangle against mesh size]"
      "(images/scale-memory.png)")
    w("")
    if batch:
        w("Many files at once, on the whole corpus folder (`drm encode DIR -o OUT -j N`; wall and CPU time of the "
          "process, the run with the shortest wall time of 2). \"cores busy\" is CPU time over wall time: how much "
          "parallel work the machine actually gave the process, which on this shared machine depends on what else "
          "runs.")
        w("")
        w("| files | -j | wall s | CPU s | cores busy | peak MiB | speed-up over -j 1 |")
        w("|---:|---:|---:|---:|---:|---:|---:|")
        one = next((float(b["wall_s"]) for b in batch if b["jobs"] == "1"), None)
        for b in batch:
            speed = f"{one / float(b['wall_s']):.2f}" if one else "-"
            cpu = number_or_none(b.get("cpu_s"))
            w(f"| {b['files']} | {b['jobs']} | {float(b['wall_s']):.2f} | {fmt(cpu, 2)} | "
              f"{fmt(cpu / float(b['wall_s']) if cpu else None, 2)} | {int(b['peak_kb']) / 1024:.0f} | {speed} |")
        w("")
    w("Absolute times move with the codec's own optimization and with the load of this shared 2-core machine; "
      "compare figures of one run, as ratios:")
    w("")
    w("```sh")
    w("bash scripts/make-bench-docs.sh --lock /tmp/drm-build.lock        # all of the below, and docs/peers.md")
    w("# or step by step:")
    w("python3 tools/bench/measure_scale.py --lock /tmp/drm-build.lock   # docs/data/{scale,batch,peers-big}.csv, ~15 min")
    w("python3 tools/bench/make_plots.py                                  # docs/images/*.png")
    w("python3 tools/bench/make_results.py --scale-only                   # this section")
    w("```")
    w("")
    return L


def number_or_none(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def fmt(x, digits=3):
    return "-" if x is None or x == "" else f"{float(x):.{digits}f}"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--drm", default="build/bin/drm")
    parser.add_argument("--meshes", default="../shared/meshes")
    parser.add_argument("--out", default="docs/results.md")
    parser.add_argument("--data", default="docs/data", help="measure_scale.py's CSV files")
    parser.add_argument("--scale-only", action="store_true",
                        help="only (re)write the plots and Scale sections of --out (no benches run)")
    args = parser.parse_args()
    if args.scale_only:
        with open(args.out) as f:
            text = f.read()
        text = replace_section(text, plots_section(args.data), before="## The paper's eight models: connectivity")
        text = replace_section(text, scale_section(args.data))
        with open(args.out, "w") as f:
            f.write(text)
        print(f"rewrote the plots and Scale sections of {args.out}", file=sys.stderr)
        return
    meshes = sorted(os.path.join(args.meshes, f) for f in os.listdir(args.meshes) if f.endswith(".ply"))
    paper_files = [os.path.join(args.meshes, m + ".ply") for m in PAPER_MODELS]

    print("corpus, default options ...", file=sys.stderr)
    corpus = bench(args.drm, meshes)
    # Connectivity is compared with the paper's at the paper's setting: ranks
    # on the 12-bit grid, so with the tree coder. The default may code the
    # vertex set with refine instead, which ranks on its coarser grid: more
    # connectivity bits, fewer geometry bits, a smaller file (horse-lres).
    print("corpus, tree geometry (ranks on the full grid) ...", file=sys.stderr)
    full_grid = bench(args.drm, meshes, "--geometry", "tree")
    print("corpus, the paper's method (no levers) ...", file=sys.stderr)
    plain = bench(args.drm, meshes, "--levers", "none", "--geometry", "tree")
    ablation = {}
    for label, levers in LEVER_SETS:
        print(f"ablation: {label} ...", file=sys.stderr)
        ablation[label] = bench(args.drm, paper_files, "--levers", levers, "--geometry", "tree")
    print("keep vertex order ...", file=sys.stderr)
    kept = bench(args.drm, paper_files, "--keep-vertex-order")
    print("corpus, refine geometry coder ...", file=sys.stderr)
    refine = bench(args.drm, meshes, "--geometry", "refine")
    raw = bench(args.drm, paper_files, "--geometry", "raw")

    L = []
    w = L.append
    w("# Results")
    w("")
    w(f"Generated by `tools/bench/make_results.py` on {datetime.date.today()} from `drm bench` runs "
      f"({subprocess.run([args.drm, '--version'], capture_output=True, text=True).stdout.strip()}) on the "
      f"{len(meshes)} meshes of `../shared/meshes`, 12 bits per axis, on this project's 2-core machine. "
      "Connectivity bits per vertex count the rank stream alone, as the paper does (its ~30-byte header "
      "is left out), or in a file of the topological coder (`connectivity_coder` topological in "
      "the data) its symbols; totals are whole files. Times are codec calls only, one run each: the machine is "
      "noisy, so compare ratios within a table, not across runs.")
    w("")
    w("Reproduce: `bash scripts/build.sh && python3 tools/bench/make_results.py`. "
      "The comparison with Draco, meshoptimizer and OpenCTM, measured in one run, is in `docs/peers.md` "
      "(`build/bin/drm-peer-bench`). Time and memory at scale, up to 4.3 million triangles: the Scale section "
      "at the end.")
    w("")
    L.extend(plots_section(args.data))

    w("## The paper's eight models: connectivity")
    w("")
    w("| model | V | paper DR (Table 4) | best other (Table 4) | faithful reproduction (method notes) | drm, paper's method | drm, levers | goal met | drm, default file |")
    w("|---|---:|---:|---:|---:|---:|---:|---|---:|")
    traded = []
    for m in PAPER_MODELS:
        row, base, default = full_grid.get(m), plain.get(m), corpus.get(m)
        goal = min(PAPER_DR[m], BEST_OTHER[m][1])
        ours = float(row["connectivity_bpv"]) if row else None
        met = "yes" if ours is not None and ours < goal else "no"
        w(f"| {m} | {row['vertices'] if row else '-'} | {PAPER_DR[m]:.2f} | {BEST_OTHER[m][1]:.2f} ({BEST_OTHER[m][0]}) | "
          f"{FAITHFUL_NOTES[m]:.2f} | {fmt(base and base['connectivity_bpv'])} | **{fmt(ours)}** | {met} (goal < {goal:.2f}) | "
          f"{fmt(default and default['connectivity_bpv'])} |")
        if row and default and default["connectivity_bpv"] != row["connectivity_bpv"]:
            coder = default["geometry_coder"] + (f" with {default['refine_bits']} low bits"
                                                  if default["geometry_coder"] == "refine" else "")
            traded.append(f"{m} ({coder}: {fmt(default['connectivity_bpv'])} bits per vertex of connectivity, "
                          f"{fmt(default['geometry_bpv'], 2)} of geometry, {fmt(default['total_bpv'], 2)} in all, against "
                          f"{fmt(row['connectivity_bpv'])}, {fmt(row['geometry_bpv'], 2)} and {fmt(row['total_bpv'], 2)} "
                          f"with the tree)")
    w("")
    w("As in the paper, connectivity is coded over the vertices at 12 bits: the columns \"paper's method\" and "
      "\"levers\" code the vertex set with the tree coder (`--geometry tree`), so that ranks are taken on the "
      "full grid. \"drm, paper's method\" is `--levers none`: the traversal, predictors and coder of the paper "
      "(midpoint predictor chosen by the paper's counters, size correction, no curvature correction, "
      "order-1 context on ranks 1 and 2). \"levers\" adds the levers below (the default). \"default file\" is "
      "the connectivity of `drm encode` with no option, whose vertex coder may be refine: it ranks on a "
      "coarser grid, so that its connectivity costs more and the file less"
      + (": " + "; ".join(traded) + "." if traded else " (none of these models takes it)."))
    w("")

    w("## Lever ablation (connectivity bpv, paper models)")
    w("")
    w("Each set of levers with the tree coder (`--geometry tree`), ranks on the 12-bit grid as above.")
    w("")
    w("| levers | " + " | ".join(PAPER_MODELS) + " | mean | encode µs/tri | decode µs/tri |")
    w("|---|" + "---:|" * (len(PAPER_MODELS) + 3))
    for label, _ in LEVER_SETS:
        rows = ablation[label]
        values = [float(rows[m]["connectivity_bpv"]) for m in PAPER_MODELS if m in rows]
        tris = sum(int(rows[m]["triangles"]) for m in PAPER_MODELS if m in rows)
        enc = sum(float(rows[m]["encode_s"]) for m in PAPER_MODELS if m in rows) / tris * 1e6
        dec = sum(float(rows[m]["decode_s"]) for m in PAPER_MODELS if m in rows) / tris * 1e6
        w(f"| {label} | " + " | ".join(fmt(rows[m]["connectivity_bpv"]) if m in rows else "-" for m in PAPER_MODELS) +
          f" | {sum(values) / len(values):.3f} | {enc:.2f} | {dec:.2f} |")
    w("")
    w("Levers (each a header flag, `docs/format.md`): **filter**, the topological candidate filter; "
      "**gap**, gap closing under 60 degrees ranked first; **context**, coder contexts from the ratio "
      "of the two nearest candidate distances (six buckets from 4096 faces, three below) and, with gap "
      "closing, whether the gap vertex is also the nearest; **angle**, the four nearest candidates "
      "ordered by the angle they subtend over the edge (those behind the edge last), used or not per "
      "edge by which order won the recent disagreements, with disagreement as a context; **front**, "
      "the edge's front neighbours ranked right after rank 1 while the recent apexes say that "
      "order is cheaper; **boundary**, whether the edge is a boundary edge coded as a flag of "
      "its own, in contexts of whether the size step found a vertex ahead and how many of the edge's fans "
      "end on a coded boundary (of the paper's models only bunny and nefertiti have borders). Contexts are "
      "seeded from a context-free parent table. Below 4096 faces the default also tries `none` and "
      "keeps the smaller file (only the tiniest regular meshes, such as the 288-vertex torus, choose it).")
    w("")

    w("## Every corpus mesh (default options)")
    w("")
    w("| mesh | V | T | comp | bnd | conn bpv | paper's method | ratio | rank 1 | rank 2 | geom bpv | total bpv | enc s | dec s | lossless |")
    w("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    worse = []

    def refined(row):  # the default file ranks on refine's coarse grid
        return f" (refine, {row['refine_bits']} low bits)" if row.get("geometry_coder") == "refine" else ""

    for m in sorted(corpus):
        r, p, t = corpus[m], plain.get(m), full_grid.get(m)
        if r["lossless"] != "ok":
            w(f"| {m} | {r['vertices'] or '-'} | {r['triangles'] or '-'} | | | | | | | | | | | | {r['lossless']} |")
            continue
        ratio = (float(t["connectivity_bpv"]) / float(p["connectivity_bpv"])
                 if t and p and float(p["connectivity_bpv"]) > 0 else None)
        if ratio is not None and ratio > 1.01:
            worse.append(m)
        w(f"| {m} | {r['vertices']} | {r['triangles']} | {r['components']} | {r['boundary_edges']} | "
          f"{fmt(r['connectivity_bpv'])}{refined(r)} | {fmt(p and p['connectivity_bpv'])} | {fmt(ratio, 2)} | {r['rank1_share']} | "
          f"{r['rank2_share']} | {fmt(r['geometry_bpv'], 2)} | {fmt(r['total_bpv'], 2)} | {r['encode_s']} | {r['decode_s']} | ok |")
    ok = sum(1 for r in corpus.values() if r["lossless"] == "ok")
    w("")
    w(f"{ok} of {len(corpus)} meshes round-trip losslessly (same quantized vertices, same oriented triangles). "
      "Meshes that are not manifold, consistently oriented surfaces are cut for the traversal and "
      "restored exactly from the repairs section (next table). \"paper's method\" is `--levers none "
      "--geometry tree`, and \"ratio\" the default levers' connectivity over it, both with ranks on the full "
      "grid (`--geometry tree`); \"conn bpv\" is the default file's, which ranks on a coarser grid where its "
      "vertex coder is refine (marked). "
      + (f"Meshes more than 1% worse than the paper's method: {', '.join(worse)}." if worse else
         "No mesh is more than 1% worse than the paper's method."))
    w("")

    w("## What the repairs cost")
    w("")
    w("Meshes the traversal cannot take as they are (MANIFEST.md: non-manifold edges or vertices, "
      "doubled faces, faces repeating a vertex, inconsistent orientation). The encoder cuts them into "
      "a manifold, consistently oriented mesh (vertex copies at non-manifold edges and vertices, faces "
      "turned over) and sets aside faces over the same vertices as an earlier face (coded as a "
      "reference to it) and faces repeating a vertex index (stored whole); the repairs section "
      "(`docs/format.md`) undoes all of it. A clean mesh has no repairs section. The connectivity "
      "column includes what the cut adds to the rank stream (more boundaries and components).")
    w("")
    w("| mesh | V | T | vertex copies | turned | repeated | loose | repair bytes | repair bpv | conn bpv | total bpv | repair share of file |")
    w("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for m in sorted(corpus):
        r = corpus[m]
        if r["lossless"] != "ok" or not int(r.get("repair_bytes") or 0):
            continue
        rb = int(r["repair_bytes"])
        bpv = 8 * rb / int(r["vertices"])
        share = bpv / float(r["total_bpv"]) if float(r["total_bpv"]) else 0
        w(f"| {m} | {r['vertices']} | {r['triangles']} | {r['vertex_copies']} | {r['turned_faces']} | "
          f"{r['repeated_faces']} | {r['loose_faces']} | {rb} | {bpv:.3f} | {fmt(r['connectivity_bpv'])} | "
          f"{fmt(r['total_bpv'], 2)} | {100 * share:.1f} % |")
    w("")

    w("## Geometry against the paper's point coder (Table 5)")
    w("")
    w("Bits per vertex of the geometry section at 12 bits. The default (`--geometry auto`) is the tree coder, or "
      "refine where that makes the file at least 3 % smaller, or smaller at all under 8,192 vertices (armadillo here); `--geometry refine` tries k = 1..5 "
      "and falls back to the tree where it does not win (next section).")
    w("")
    w("| model | paper DR Geom (MMG06) | drm default | drm refine | raw grid | default below the paper |")
    w("|---|---:|---:|---:|---:|---|")
    for m in ["bunny", "fandisk", "horse"]:
        r, f = corpus.get(m), refine.get(m)
        below = "yes" if r and float(r["geometry_bpv"]) < PAPER_GEOMETRY[m] else "no"
        w(f"| {m} | {PAPER_GEOMETRY[m]:.2f} | {fmt(r and r['geometry_bpv'], 2)} | {fmt(f and f['geometry_bpv'], 2)} | "
          f"{fmt(raw.get(m, {}).get('geometry_bpv'), 2)} | {below} |")
    r, f = corpus.get("armadillo-43k"), refine.get("armadillo-43k")
    w(f"| armadillo (43K of the paper's 173K vertices) | {PAPER_GEOMETRY['armadillo']:.2f} | "
      f"{fmt(r and r['geometry_bpv'], 2)} | {fmt(f and f['geometry_bpv'], 2)} | - | not the same model |")
    w("")
    above = [m for m in ["bunny", "fandisk", "horse"]
             if not corpus.get(m) or float(corpus[m]["geometry_bpv"]) >= PAPER_GEOMETRY[m]]
    w(f"Above MMG06: {', '.join(above)}." if above else
      "All three are below MMG06 since the encoder grows its tree cheapest vertex first, not as the minimum spanning "
      "tree alone (Draco's geometry, which predicts across the mesh's edges, takes about 11.3 on fandisk, "
      "method notes).")
    w("")
    peers = {}
    for row in read_rows(os.path.join(args.data, "peers.csv")):
        if row["codec"] == "draco cl10" and row["status"] == "ok":
            peers[os.path.splitext(row["mesh"])[0]] = float(row["total_bpv"])
    w("## Geometry coders, every corpus mesh")
    w("")
    w("The default (`--geometry auto`: the tree coder, or refine with 4 or 2 low bits where that is at least 3 % smaller, or smaller at all under 8,192 vertices) against `--geometry refine`, which codes a coarser grid with the tree, ranks the connectivity on "
      "it, and then codes the k low bits of each vertex predicted across the decoded triangles; the encoder tries "
      "k = 1..5 and keeps the smallest file, the tree's own when no k wins (k = 0 below). Draco cl10's whole file "
      "(`docs/data/peers.csv`, from `drm-peer-bench`, same 12-bit grid) for reference. Bits per vertex; `docs/format.md` "
      "specifies both coders, `docs/design.md` says why refine ranks the connectivity on the coarse grid.")
    w("")
    w("| mesh | V | default geom | default total | refine geom | refine conn | refine total | k | refine / default | Draco cl10 total | best drm / Draco |")
    w("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    wins, ratios, below_draco = 0, [], 0
    for m in sorted(corpus):
        a, b = corpus[m], refine.get(m)
        if not b or a["lossless"] != "ok" or b["lossless"] != "ok":
            w(f"| {m} | {a['vertices']} | - | - | - | - | - | - | - | - | - |")
            continue
        ratio = float(b["total_bpv"]) / float(a["total_bpv"])
        ratios.append(ratio)
        wins += 1 if ratio < 0.9995 else 0
        draco = peers.get(m)
        best = min(float(a["total_bpv"]), float(b["total_bpv"]))
        vs = f"{best / draco:.2f}" if draco else "-"
        below_draco += 1 if draco and best < draco else 0
        w(f"| {m} | {a['vertices']} | {fmt(a['geometry_bpv'], 2)} | {fmt(a['total_bpv'], 2)} | {fmt(b['geometry_bpv'], 2)} | "
          f"{fmt(b['connectivity_bpv'], 2)} | {fmt(b['total_bpv'], 2)} | {b.get('refine_bits', '-')} | {ratio:.3f} | "
          f"{fmt(draco, 2) if draco else '-'} | {vs} |")
    w("")
    if ratios:
        gm = math.exp(sum(math.log(x) for x in ratios) / len(ratios))
        w(f"`--geometry refine` writes a smaller file than the default on {wins} of {len(ratios)} meshes (never a "
          f"larger one; geometric mean of refine / default {gm:.3f}, best {min(ratios):.3f}). The smaller of the two drm files is "
          f"below Draco cl10's on {below_draco} of {len(peers)} meshes.")
        w("")

    w("## What keeping the input vertex order costs")
    w("")
    w("| model | V | total bpv | with --keep-vertex-order | cost bpv |")
    w("|---|---:|---:|---:|---:|")
    for m in PAPER_MODELS:
        a, b = corpus.get(m), kept.get(m)
        if a and b and b["lossless"] == "ok":
            w(f"| {m} | {a['vertices']} | {fmt(a['total_bpv'], 2)} | {fmt(b['total_bpv'], 2)} | "
              f"{float(b['total_bpv']) - float(a['total_bpv']):.2f} |")
    w("")
    L.extend(scale_section(args.data))
    os.makedirs(os.path.dirname(args.out) or ".", exist_ok=True)
    with open(args.out, "w") as f:
        f.write("\n".join(L) + "\n")
    print(f"wrote {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
