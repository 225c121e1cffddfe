#!/usr/bin/env python3
"""Draws the benchmark plots of docs/ from the recorded CSV files.

Usage (from the project's root): python3 tools/bench/make_plots.py

Reads (each written by a measuring tool; rerun that to refresh the data):
  docs/data/peers.csv       drm-peer-bench ../shared/meshes --csv docs/data/peers.csv
  docs/data/peers-big.csv   tools/bench/measure_scale.py (drm-peer-bench on subdivided meshes)
  docs/data/scale.csv       tools/bench/measure_scale.py (drm encode/decode processes)
Writes:
  docs/images/peers-connectivity.png  connectivity bits per vertex per mesh: drm, the
                                      paper's Table 4, Draco cl10/cl7, meshopt+zstd, OpenCTM
  docs/images/time-per-triangle.png   encode and decode microseconds per triangle against
                                      triangles, drm and Draco cl10
  docs/images/scale-memory.png        drm encode/decode processes: peak memory per vertex
                                      and wall time per triangle against triangles

Needs matplotlib (Debian: python3-matplotlib, installed by scripts/setup.sh).
"""
import argparse
import csv
import os
import sys

try:
    import matplotlib
except ImportError:  # a python3 without Debian's packages first on PATH (pyenv, venv)
    if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3", *sys.argv])
    sys.exit("make_plots.py: needs matplotlib (apt-get install python3-matplotlib)")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FuncFormatter  # noqa: E402

CONNECTIVITY_CODECS = [  # CSV codec name, label, marker, colour, size
    ("drm", "drm", "o", "#d62728", 46),
    ("draco cl10", "Draco cl10 (Edgebreaker)", "s", "#1f77b4", 34),
    ("draco cl7", "Draco cl7 (connectivity coded as cl10)", "x", "#0b3d66", 22),
    ("meshopt+zstd", "meshoptimizer + zstd", "^", "#2ca02c", 34),
    ("openctm mg2", "OpenCTM MG2", "v", "#9467bd", 34),
]
TIME_CODECS = [("drm", "drm", "o", "#d62728"), ("draco cl10", "Draco cl10", "s", "#1f77b4")]


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def plain_number(x, _pos=None):
    if x >= 1_000_000:
        return f"{x / 1_000_000:g}M"
    if x >= 1_000:
        return f"{x / 1_000:g}K"
    return f"{x:g}"


def connectivity_plot(rows, out):
    meshes = {}
    for r in rows:
        if r["status"] != "ok":
            continue
        m = meshes.setdefault(r["mesh"], {"paper": number(r["paper_dr_bpv"])})
        m[r["codec"]] = number(r["connectivity_bpv"])
    # Sorted by drm's rate; meshes drm does not encode at the bottom.
    names = sorted(meshes, key=lambda n: (meshes[n].get("drm") is None, meshes[n].get("drm") or 0))
    height = 0.24 * len(names) + 1.6
    fig, ax = plt.subplots(figsize=(9, height))
    ys = range(len(names))
    for codec, label, marker, colour, size in reversed(CONNECTIVITY_CODECS):
        xs = [(meshes[n].get(codec), y) for y, n in zip(ys, names) if meshes[n].get(codec)]
        ax.scatter([x for x, _ in xs], [y for _, y in xs], marker=marker, s=size, color=colour, label=label,
                   zorder={"drm": 4, "draco cl7": 3}.get(codec, 2), linewidths=1.2)
    paper = [(meshes[n]["paper"], y) for y, n in zip(ys, names) if meshes[n]["paper"]]
    ax.scatter([x for x, _ in paper], [y for _, y in paper], marker="*", s=130, color="#ff7f0e",
               edgecolors="black", linewidths=0.5, label="paper, Table 4 (DR)", zorder=5)
    ax.set_yticks(list(ys))
    ax.set_yticklabels([n[:-4] if n.endswith(".ply") else n for n in names], fontsize=8)
    ax.set_ylim(-0.8, len(names) - 0.2)
    ax.invert_yaxis()
    ax.set_xscale("log")
    ax.xaxis.set_major_formatter(FuncFormatter(lambda x, _p: f"{x:g}"))
    ax.set_xlabel("connectivity, bits per vertex (log scale; lower is better)")
    ax.set_title("Connectivity per mesh at 12 bits (drm-peer-bench, corpus sorted by drm's rate)", fontsize=10)
    ax.grid(True, axis="x", which="both", alpha=0.3)
    ax.grid(True, axis="y", alpha=0.15)
    handles, labels = ax.get_legend_handles_labels()
    order = [labels.index(l) for l in ["drm", "paper, Table 4 (DR)"] + [c[1] for c in CONNECTIVITY_CODECS[1:]]]
    ax.legend([handles[i] for i in order], [labels[i] for i in order], loc="lower left", fontsize=8,
              framealpha=0.95)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def time_plot(rows, big_rows, out):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6), sharey=True)
    for ax, column, title in ((axes[0], "encode_s", "encode"), (axes[1], "decode_s", "decode")):
        for source, filled in ((rows, True), (big_rows, False)):
            for codec, label, marker, colour in TIME_CODECS:
                pts = [(int(r["triangles"]), number(r[column]) / int(r["triangles"]) * 1e6)
                       for r in source if r["codec"] == codec and r["status"] == "ok" and number(r[column])]
                if not pts:
                    continue
                ax.scatter([p[0] for p in pts], [p[1] for p in pts], marker=marker, s=28 if filled else 70,
                           facecolors=colour if filled else "none", edgecolors=colour, linewidths=1.3,
                           label=label + (" (corpus)" if filled else " (igea subdivided)"))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.xaxis.set_major_formatter(FuncFormatter(plain_number))
        ax.yaxis.set_major_formatter(FuncFormatter(lambda y, _p: f"{y:g}"))
        ax.set_xlabel("triangles (log scale)")
        ax.set_title(f"{title} time per triangle")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("µs per triangle (log scale; flat = linear time)")
    axes[1].legend(fontsize=8, loc="upper right")
    fig.suptitle("Codec calls only, best of the runs, in one process (drm-peer-bench); machine shared", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def scale_plot(rows, out):
    floor = next((number(r["encode_peak_kb"]) for r in rows if r["source"] == "process floor"), None)
    data = [r for r in rows if r["source"] != "process floor"]
    if not data:
        return
    data.sort(key=lambda r: int(r["triangles"]))
    tris = [int(r["triangles"]) for r in data]
    verts = [int(r["vertices"]) for r in data]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4))
    ax = axes[0]
    for column, label, marker, colour in (("encode_peak_kb", "encode", "o", "#d62728"),
                                          ("decode_peak_kb", "decode", "s", "#1f77b4")):
        peak = [number(r[column]) * 1024 for r in data]
        ax.plot(tris, [p / v for p, v in zip(peak, verts)], marker=marker, color=colour, label=f"{label}: peak / V")
        if floor:
            ax.plot(tris, [(p - floor * 1024) / v for p, v in zip(peak, verts)], marker=marker, color=colour,
                    linestyle="--", markerfacecolor="none", label=f"{label}: (peak - process floor) / V")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.xaxis.set_major_formatter(FuncFormatter(plain_number))
    ax.yaxis.set_major_formatter(FuncFormatter(lambda y, _p: f"{y:g}"))
    ax.set_xlabel("triangles (log scale)")
    ax.set_ylabel("peak resident memory, bytes per vertex (log scale)")
    ax.set_title("peak memory per vertex")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax = axes[1]
    for column, label, marker, colour in (("encode_us_per_tri", "drm encode", "o", "#d62728"),
                                          ("decode_us_per_tri", "drm decode", "s", "#1f77b4")):
        ax.plot(tris, [number(r[column]) for r in data], marker=marker, color=colour, label=label)
    ax.set_xscale("log")
    ax.set_ylim(bottom=0)
    ax.xaxis.set_major_formatter(FuncFormatter(plain_number))
    ax.set_xlabel("triangles (log scale)")
    ax.set_ylabel("wall µs per triangle (whole process, file I/O included)")
    ax.set_title("time per triangle")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.suptitle("`drm encode` / `drm decode` processes (tools/bench/measure_scale.py; the largest two are "
                 "igea subdivided)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", default="docs/data")
    parser.add_argument("--images", default="docs/images")
    args = parser.parse_args()
    os.makedirs(args.images, exist_ok=True)
    peers = read_csv(os.path.join(args.data, "peers.csv"))
    big = read_csv(os.path.join(args.data, "peers-big.csv"))
    scale = read_csv(os.path.join(args.data, "scale.csv"))
    if peers:
        connectivity_plot(peers, os.path.join(args.images, "peers-connectivity.png"))
        time_plot(peers, big, os.path.join(args.images, "time-per-triangle.png"))
        print(f"wrote {args.images}/peers-connectivity.png, {args.images}/time-per-triangle.png", file=sys.stderr)
    else:
        print(f"no {args.data}/peers.csv: run drm-peer-bench with --csv first", file=sys.stderr)
    if scale:
        scale_plot(scale, os.path.join(args.images, "scale-memory.png"))
        print(f"wrote {args.images}/scale-memory.png", file=sys.stderr)


if __name__ == "__main__":
    main()
