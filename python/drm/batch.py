"""Encode many mesh files on a Dask cluster, or on the cores of this machine.

    python3 -m drm.batch INPUTS... -o DIR [--scheduler ADDRESS | --workers N]
                         [--manifest FILE] [encoding options of `drm encode`]

Every input (a PLY, OBJ, OFF or STL file, or a folder: its mesh files in
name order, not recursive) becomes DIR/NAME.drm, the same bytes `drm encode
INPUT DIR/NAME.drm` writes. Each file is one task; a worker reads the input
and writes the output itself, so inputs and DIR must be paths every worker
sees (a shared file system) under the same names.

The manifest (DIR/drm-manifest.jsonl unless --manifest says otherwise) gets
one JSON line as each file finishes: input, output, input and output
bytes, bits per vertex, seconds, the worker, and the error if it failed. A
second run skips every input the manifest records as done, with the same
drm version and options, whose input and output are as they were then, so
an interrupted run resumes. Failures are
listed at the end and the exit code is 1.

Without --scheduler, a local cluster of --workers processes (default: the
number of cores) runs on this machine. With --scheduler, the workers of
that cluster run the tasks: start it with Debian's python3-distributed
(`dask-scheduler` on one machine, `dask-worker tcp://HOST:8786` on each
other, or `dask-ssh HOST...`), each with the same drm installed.
"""
from __future__ import annotations

import argparse
import json
import os
import socket
import sys
import time
from typing import Any, Dict, Iterable, List, Optional, Tuple

MESH_EXTENSIONS = (".ply", ".obj", ".off", ".stl")
MANIFEST_NAME = "drm-manifest.jsonl"


def mesh_inputs(paths: Iterable[str]) -> List[str]:
    """The input files, absolute, in the order given; a folder's mesh files in
    name order."""
    files: List[str] = []
    for path in paths:
        if os.path.isdir(path):
            names = sorted(n for n in os.listdir(path) if n.lower().endswith(MESH_EXTENSIONS))
            files.extend(os.path.abspath(os.path.join(path, n)) for n in names
                         if os.path.isfile(os.path.join(path, n)))
        elif os.path.isfile(path):
            if not path.lower().endswith(MESH_EXTENSIONS):
                raise SystemExit(f"drm.batch: {path} is not a .ply, .obj, .off or .stl file")
            files.append(os.path.abspath(path))
        else:
            raise SystemExit(f"drm.batch: {path}: no such file or folder")
    unique: List[str] = []
    seen = set()
    for path in files:  # a file named twice (or through a link) is coded once
        real = os.path.realpath(path)
        if real not in seen:
            seen.add(real)
            unique.append(path)
    return unique


def output_paths(inputs: List[str], out_dir: str) -> List[str]:
    outputs: List[str] = []
    seen: Dict[str, str] = {}
    for path in inputs:
        stem = os.path.splitext(os.path.basename(path))[0]
        output = os.path.join(out_dir, stem + ".drm")
        if output in seen:
            raise SystemExit(f"drm.batch: two inputs would both be written to {output}: {seen[output]} and {path} "
                             "(nothing written)")
        seen[output] = path
        outputs.append(output)
    return outputs


def _signature(path: str) -> Optional[Tuple[int, int]]:
    try:
        st = os.stat(path)
    except OSError:
        return None
    return st.st_size, st.st_mtime_ns


def _worker_name() -> str:
    try:
        from distributed import get_worker

        return get_worker().address
    except (ImportError, ValueError):
        return socket.gethostname()


def encode_one(input: str, output: str, options: Dict[str, Any], version: str) -> Dict[str, Any]:
    """The task a worker runs: one file, as `drm encode` codes it. Never
    raises for a bad file: the error goes into the record."""
    import drm  # imported on the worker

    record: Dict[str, Any] = {"input": input, "output": output, "worker": _worker_name(),
                              "input_bytes": None, "output_bytes": None, "bpv": None, "seconds": None, "error": None}
    start = time.perf_counter()
    try:
        if drm.__version__ != version:
            raise RuntimeError(f"the worker runs drm {drm.__version__}, the client {version}: files could differ")
        record["input_bytes"] = os.path.getsize(input)
        result = drm.encode_file(input, output, **options)
        record["output_bytes"] = result["stats"]["total_bytes"]
        record["bpv"] = round(result["stats"]["total_bpv"], 4)
        record["vertices"] = result["stats"]["vertices"]
        record["faces"] = result["stats"]["faces"]
        record["notes"] = result["notes"]
    except Exception as e:  # a file that fails is reported, the others go on
        record["error"] = str(e) or type(e).__name__
    record["seconds"] = round(time.perf_counter() - start, 3)
    sig_in, sig_out = _signature(input), _signature(output)
    record["input_signature"] = list(sig_in) if sig_in else None
    record["output_signature"] = list(sig_out) if sig_out and record["error"] is None else None
    return record


def _pair(value: Any) -> Optional[Tuple[int, int]]:
    if isinstance(value, list) and len(value) == 2 and all(isinstance(x, int) for x in value):
        return value[0], value[1]
    return None


def done_before(manifest: str, settings: Dict[str, Any]) -> Dict[Tuple[str, str], Dict[str, Any]]:
    """The manifest's successful records, made with these settings (drm's
    version and the encoding options), whose files are unchanged since.
    A line that is not such a record (cut short by an interrupted run, or
    damaged) is passed over."""
    done: Dict[Tuple[str, str], Dict[str, Any]] = {}
    if not os.path.exists(manifest):
        return done
    with open(manifest, encoding="utf-8", errors="replace") as f:
        for line in f:
            try:
                record = json.loads(line)
            except ValueError:
                continue
            if not isinstance(record, dict) or not isinstance(record.get("input"), str) \
                    or not isinstance(record.get("output"), str):
                continue
            key = (record["input"], record["output"])
            signatures = _pair(record.get("input_signature")), _pair(record.get("output_signature"))
            if record.get("error") is None and record.get("settings") == settings and all(signatures) \
                    and _signature(key[0]) == signatures[0] and _signature(key[1]) == signatures[1]:
                done[key] = record
            else:
                done.pop(key, None)
    return done


def _ends_with_newline(path: str) -> bool:
    try:
        with open(path, "rb") as f:
            f.seek(0, os.SEEK_END)
            if f.tell() == 0:
                return True
            f.seek(-1, os.SEEK_END)
            return f.read(1) == b"\n"
    except FileNotFoundError:
        return True


def encoding_options(args: argparse.Namespace) -> Dict[str, Any]:
    """The options of `drm encode` given on the command line, in the package's
    names; none given: the defaults `drm encode` uses."""
    options: Dict[str, Any] = {}
    for name in ("bits", "refine_bits", "normal_bits", "uv_bits", "predictor", "geometry", "connectivity",
                 "levers", "weld"):
        value = getattr(args, name)
        if value is not None:
            options[name] = value
    if args.attributes is not None:
        options["keep"] = args.attributes
    if args.curvature is not None:
        options["curvature"] = args.curvature == "on"
    if args.start is not None:
        options["search_starts"] = args.start == "search"
    if args.keep_vertex_order:
        options["keep_vertex_order"] = True
    if args.verify:
        options["verify"] = True
    options["threads"] = 1  # one file per worker thread; never changes the bytes
    return options


def parse_arguments(argv: List[str]) -> argparse.Namespace:
    p = argparse.ArgumentParser(prog="python3 -m drm.batch", description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("inputs", nargs="+", help="mesh files and folders")
    p.add_argument("-o", "--output-dir", required=True, help="folder for the .drm files (created if missing)")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--scheduler", help="address of a Dask scheduler, e.g. tcp://10.0.0.1:8786")
    where.add_argument("--workers", type=int, help="processes of a local cluster (default: the cores)")
    p.add_argument("--manifest", help=f"the manifest file (default: DIR/{MANIFEST_NAME})")
    e = p.add_argument_group("encoding options", "as `drm encode`'s, with its defaults (`drm help encode`)")
    e.add_argument("--bits", type=int, help="quantization bits per axis")
    e.add_argument("--refine-bits", type=int, help="low bits the refine coder codes")
    e.add_argument("--normal-bits", type=int, help="normal quantization bits")
    e.add_argument("--uv-bits", type=int, help="texture coordinate quantization bits")
    e.add_argument("--predictor", help="auto, parallelogram or midpoint")
    e.add_argument("--geometry", help="auto, tree, refine, sorted or raw")
    e.add_argument("--connectivity", help="auto, ranks or topological")
    e.add_argument("--levers", help="all, none or a list")
    e.add_argument("--weld", choices=("auto", "on", "off"))
    e.add_argument("--attributes", help="all, none or a list of the attributes to keep")
    e.add_argument("--curvature", choices=("on", "off"))
    e.add_argument("--start", choices=("search", "smallest"))
    e.add_argument("--keep-vertex-order", action="store_true")
    e.add_argument("--verify", action="store_true", help="decode each file and compare before writing it")
    args = p.parse_args(argv)
    if args.workers is not None and args.workers < 1:
        p.error("--workers takes a number of processes, 1 or more")
    return args


def _client(args: argparse.Namespace):
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise SystemExit("drm.batch: needs Dask's distributed scheduler (Debian: python3-distributed; "
                         "pip: distributed)") from None

    if args.scheduler:
        return Client(args.scheduler, timeout="30s"), None
    workers = args.workers or os.cpu_count() or 1
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                           host="127.0.0.1")
    return Client(cluster), cluster


def main(argv: Optional[List[str]] = None) -> int:
    args = parse_arguments(sys.argv[1:] if argv is None else argv)
    import drm

    inputs = mesh_inputs(args.inputs)
    if not inputs:
        print("drm.batch: no .ply, .obj, .off or .stl file in the inputs", file=sys.stderr)
        return 1
    out_dir = os.path.abspath(args.output_dir)
    if os.path.exists(out_dir) and not os.path.isdir(out_dir):
        print(f"drm.batch: cannot write into {out_dir}: it is not a folder", file=sys.stderr)
        return 1
    outputs = output_paths(inputs, out_dir)
    input_set = {os.path.realpath(p) for p in inputs}
    for output in outputs:
        if os.path.realpath(output) in input_set:
            print(f"drm.batch: cannot write {output}: it is one of the inputs (nothing written)", file=sys.stderr)
            return 1
    options = encoding_options(args)
    try:  # a bad option fails here, once, not on every worker
        drm.encode([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], **options)
    except drm.Error as e:
        print(f"drm.batch: {e}", file=sys.stderr)
        return 2
    os.makedirs(out_dir, exist_ok=True)
    manifest = os.path.abspath(args.manifest or os.path.join(out_dir, MANIFEST_NAME))
    settings = {"drm": drm.__version__, "options": options}
    done = done_before(manifest, settings)
    todo = [(i, o) for i, o in zip(inputs, outputs) if (i, o) not in done]
    skipped = len(inputs) - len(todo)
    print(f"drm.batch: {len(inputs)} file{'' if len(inputs) == 1 else 's'}, {skipped} done before "
          f"(manifest {manifest}), {len(todo)} to encode", flush=True)

    failures: List[Dict[str, Any]] = []
    bytes_in = bytes_out = 0
    start = time.perf_counter()
    if todo:
        client, cluster = _client(args)
        from dask.distributed import as_completed

        try:
            workers = len(client.scheduler_info().get("workers", {}))
            print(f"drm.batch: {workers} workers at {client.scheduler.address}", flush=True)
            futures = {client.submit(encode_one, i, o, options, drm.__version__, pure=False, key=f"drm-encode-{n}"): (i, o)
                       for n, (i, o) in enumerate(todo)}
            cut_short = not _ends_with_newline(manifest)
            with open(manifest, "a", encoding="utf-8") as log:
                if cut_short:
                    log.write("\n")  # an interrupted run's last line stays apart from the next record
                for count, future in enumerate(as_completed(futures), 1):
                    try:
                        record = future.result()
                    except Exception as e:  # the worker died or the task could not run
                        i, o = futures[future]
                        record = {"input": i, "output": o, "error": f"task failed: {e}"}
                    record["settings"] = settings
                    log.write(json.dumps(record) + "\n")
                    log.flush()
                    os.fsync(log.fileno())
                    name = os.path.basename(record["input"])
                    if record.get("error"):
                        failures.append(record)
                        print(f"[{count}/{len(todo)}] FAILED {name}: {record['error']}", flush=True)
                    else:
                        bytes_in += record["input_bytes"]
                        bytes_out += record["output_bytes"]
                        print(f"[{count}/{len(todo)}] {name} -> {os.path.basename(record['output'])}: "
                              f"{record['output_bytes']} bytes, {record['bpv']:.3f} bits per vertex, "
                              f"{record['seconds']:.2f} s", flush=True)
        finally:
            client.close()
            if cluster is not None:
                cluster.close()
    seconds = time.perf_counter() - start
    encoded = len(todo) - len(failures)
    ratio = f", {bytes_in / bytes_out:.2f}:1" if bytes_out else ""
    print(f"drm.batch: {encoded} encoded, {skipped} skipped, {len(failures)} failed; "
          f"{bytes_in} bytes in, {bytes_out} out{ratio}; {seconds:.1f} s", flush=True)
    if failures:
        print("drm.batch: failed:", file=sys.stderr)
        for record in failures:
            print(f"  {record['input']}: {record['error']}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
