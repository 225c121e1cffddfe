"""python3 -m drm.batch on a Dask cluster of a scheduler and two workers on
127.0.0.1 (Debian's dask-scheduler and dask-worker): the files are those
`drm encode` writes, the manifest records each, failures are listed with
exit code 1, and a second run skips what is done."""
import json
import os
import shutil
import subprocess
import sys
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.environ.get("DRM_TEST_DATA", os.path.join(HERE, "..", "data"))
DRM_TOOL = os.environ.get("DRM_TOOL", "drm")
MESHES = sorted(os.path.join(DATA, n) for n in os.listdir(DATA) if n.endswith(".ply"))


def read(path):
    with open(path, "rb") as f:
        return f.read()


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """The address of a scheduler with two single-thread workers."""
    if not shutil.which("dask-scheduler"):
        pytest.fail("dask-scheduler is missing: bash scripts/setup.sh installs python3-distributed")
    folder = tmp_path_factory.mktemp("cluster")
    scheduler_file = folder / "scheduler.json"
    env = dict(os.environ, DASK_DISTRIBUTED__WORKER__DAEMON="False")
    logs = open(folder / "cluster.log", "w")
    processes = [subprocess.Popen(["dask-scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                                   "--scheduler-file", str(scheduler_file)], stdout=logs, stderr=logs, env=env)]
    deadline = time.monotonic() + 60
    while not scheduler_file.exists() and time.monotonic() < deadline:
        time.sleep(0.2)
    for _ in range(2):
        processes.append(subprocess.Popen(["dask-worker", "--scheduler-file", str(scheduler_file), "--nthreads", "1",
                                           "--nworkers", "1", "--host", "127.0.0.1", "--no-dashboard"],
                                          stdout=logs, stderr=logs, env=env))
    try:
        address = json.loads(scheduler_file.read_text())["address"]
        from dask.distributed import Client

        with Client(address, timeout="60s") as client:
            client.wait_for_workers(2, timeout=60)
        yield address
    finally:
        for p in processes[::-1]:
            p.terminate()
        for p in processes:
            try:
                p.wait(timeout=20)
            except subprocess.TimeoutExpired:
                p.kill()
        logs.close()


def batch(*args):
    return subprocess.run([sys.executable, "-m", "drm.batch", *args], capture_output=True, text=True, timeout=600)


def manifest_of(folder):
    with open(os.path.join(folder, "drm-manifest.jsonl")) as f:
        return [json.loads(line) for line in f]


def test_a_cluster_of_two_workers_writes_the_files_drm_encode_writes(cluster, tmp_path):
    inputs = tmp_path / "inputs"
    inputs.mkdir()
    for path in MESHES:
        shutil.copy(path, inputs)
    (inputs / "broken.ply").write_text("ply\nformat ascii 1.0\nelement vertex 3\nend_header\n0 0 0\n")
    out = tmp_path / "out"
    run = batch(str(inputs), "-o", str(out), "--scheduler", cluster)
    assert run.returncode == 1, run.stdout + run.stderr
    assert "broken.ply" in run.stderr and "FAILED broken.ply" in run.stdout

    records = manifest_of(out)
    assert len(records) == len(MESHES) + 1
    failed = [r for r in records if r["error"]]
    assert [os.path.basename(r["input"]) for r in failed] == ["broken.ply"]
    assert not (out / "broken.drm").exists()
    workers = {r["worker"] for r in records}
    assert len(workers) == 2, workers  # both workers took files
    for record in records:
        if record["error"]:
            continue
        name = os.path.splitext(os.path.basename(record["input"]))[0]
        subprocess.run([DRM_TOOL, "encode", record["input"], str(tmp_path / "tool.drm")], check=True,
                       stdout=subprocess.DEVNULL)
        assert read(out / (name + ".drm")) == read(tmp_path / "tool.drm"), name
        assert record["output_bytes"] == os.path.getsize(out / (name + ".drm"))
        assert record["input_bytes"] == os.path.getsize(record["input"])
        assert record["bpv"] > 0 and record["seconds"] >= 0

    # A second run encodes only what failed; with the broken file gone,
    # nothing is left to do. A changed input is encoded again.
    again = batch(str(inputs), "-o", str(out), "--scheduler", cluster)
    assert again.returncode == 1 and f"{len(MESHES)} done before" in again.stdout
    (inputs / "broken.ply").unlink()
    third = batch(str(inputs), "-o", str(out), "--scheduler", cluster)
    assert third.returncode == 0, third.stdout + third.stderr
    assert f"{len(MESHES)} done before" in third.stdout and "0 to encode" in third.stdout
    os.utime(inputs / os.path.basename(MESHES[0]), ns=(1, 1))
    fourth = batch(str(inputs), "-o", str(out), "--scheduler", cluster)
    assert fourth.returncode == 0 and "1 to encode" in fourth.stdout, fourth.stdout


def test_a_local_cluster_and_the_refusals(tmp_path):
    out = tmp_path / "out"
    run = batch(MESHES[0], MESHES[1], "-o", str(out), "--workers", "2")
    assert run.returncode == 0, run.stdout + run.stderr
    assert len(manifest_of(out)) == 2
    assert batch(MESHES[0], "-o", str(out), "--bits", "40").returncode != 0  # refused before any work
    same_name = tmp_path / "again"
    same_name.mkdir()
    shutil.copy(MESHES[0], same_name)
    clash = batch(MESHES[0], str(same_name / os.path.basename(MESHES[0])), "-o", str(tmp_path / "x"))
    assert clash.returncode != 0 and "both be written" in clash.stderr
    assert not (tmp_path / "x" / "drm-manifest.jsonl").exists()


def test_a_second_run_with_other_options_encodes_again_and_damaged_lines_are_passed_over(tmp_path):
    out = tmp_path / "out"
    first = batch(MESHES[0], "-o", str(out), "--workers", "1")
    assert first.returncode == 0, first.stdout + first.stderr
    name = os.path.splitext(os.path.basename(MESHES[0]))[0]
    other = batch(MESHES[0], "-o", str(out), "--workers", "1", "--bits", "14")
    assert other.returncode == 0 and "1 to encode" in other.stdout, other.stdout
    subprocess.run([DRM_TOOL, "encode", MESHES[0], str(tmp_path / "t.drm"), "--bits", "14"], check=True,
                   stdout=subprocess.DEVNULL)
    assert read(out / (name + ".drm")) == read(tmp_path / "t.drm")
    manifest = out / "drm-manifest.jsonl"
    with open(manifest, "ab") as f:  # damaged lines, the last one cut short
        f.write(b'[1, 2]\n42\n{"input": ["a"], "output": 1}\n\xff\xfe\n{"input": "/x", "output": "/y", "error": nu')
    again = batch(MESHES[0], "-o", str(out), "--workers", "1", "--bits", "14")
    assert again.returncode == 0 and "1 done before" in again.stdout, again.stdout + again.stderr
    touched = batch(MESHES[0], MESHES[0], "-o", str(out), "--workers", "1")  # 12 bits again; listed twice
    assert touched.returncode == 0 and "1 file," in touched.stdout and "1 to encode" in touched.stdout, touched.stdout
    last = manifest.read_bytes().splitlines()[-1]
    assert json.loads(last)["settings"]["options"].get("bits") is None
