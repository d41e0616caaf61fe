"""meromorph.collection on a Dask LocalCluster: every mesh mapped once, its row after its
outputs, failures as rows, nothing lost or doubled when a worker is killed, reruns do no work."""

import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest
from distributed import Client, LocalCluster

from meromorph import collection
from conftest import make, read_ply_vertices, tool


def generated_collection(folder: Path, count: int, resolution: int = 24) -> list:
    """`count` meshes of genus 0, 1 and 2, rigidly moved by different seeds."""
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for k in range(count):
        genus = k % 3
        seed = str(k + 1)
        if genus == 1:
            path = make("torus", folder / f"torus{k:02d}.off", "--rigid-motion", "--seed", seed,
                        "--resolution", str(resolution))
        else:
            path = make("genus", folder / f"genus{genus}_{k:02d}.ply", "-g", str(genus),
                        "--resolution", str(resolution), "--rigid-motion", "--seed", seed)
        paths.append(str(path))
    return paths


def judge(out: Path, row: dict) -> None:
    """The row against the files written: the sphere's points on the unit sphere (genus 0) or
    on it layer by layer, the report's degree and genus, Riemann-Hurwitz from its branch points."""
    base = out / "meshes" / row["name"]
    report = json.loads(Path(str(base) + ".report.json").read_text())
    surface = read_ply_vertices(Path(str(base) + ".uv.ply"))
    sphere = read_ply_vertices(Path(str(base) + ".sphere.ply"))
    assert len(surface["x"]) == row["vertices"] == report["vertices"]
    radius = np.sqrt(sphere["x"] ** 2 + sphere["y"] ** 2 + sphere["z"] ** 2)
    assert np.allclose(radius, 1, atol=1e-5)
    assert row["genus"] == report["genus"] and row["degree"] == report["degree"]
    ramification = sum(b["local_degree"] - 1 for b in report["branch_points"])
    assert 2 * row["genus"] - 2 == -2 * row["degree"] + ramification
    assert row["folded_faces"] == 0 and row["valid"] is True
    if row["genus"] == 0:
        assert len(row["spharm"]) == 17
    elif row["genus"] == 1:
        tau = complex(*row["modulus"])
        assert abs(tau.real) <= 0.5 + 1e-12 and abs(tau) >= 1 - 1e-12
    else:
        assert np.array(row["riemann_matrix"]).shape == (row["genus"], row["genus"], 2)


@pytest.fixture(scope="module")
def client():
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=None)
    with Client(cluster) as dask_client:
        yield dask_client
    cluster.close()


def test_two_workers_map_twenty_meshes_and_a_rerun_does_no_work(tmp_path, client):
    paths = generated_collection(tmp_path / "in", 20)
    (tmp_path / "in" / "broken.off").write_text("OFF\n3 1 0\n0 0 0\n")
    paths.append(str(tmp_path / "in" / "broken.off"))
    out = tmp_path / "out"
    rows = collection.run(paths, str(out), client=client, root=str(tmp_path / "in"))
    assert len(rows) == 21 and len({r["name"] for r in rows}) == 21
    broken = [r for r in rows if r["name"] == "broken"][0]
    assert broken["status"] == "refused" and "broken.off" in broken["error"]
    for row in rows:
        if row["name"] != "broken":
            assert row["status"] == "ok", row
            judge(out, row)
    table = (out / "table.csv").read_text().splitlines()
    assert len(table) == 22 and table[0].startswith("file,name,status")
    assert len((out / "table.jsonl").read_text().splitlines()) == 21
    stamps = {p: p.stat().st_mtime_ns for p in out.rglob("*") if p.is_file() and "table" not in p.name}
    again = collection.run(paths, str(out), client=client, root=str(tmp_path / "in"))
    assert again == rows
    assert {p: p.stat().st_mtime_ns for p in stamps} == stamps  # nothing mapped or written again
    # --retry-failed maps the failed one only.
    collection.run(paths, str(out), client=client, root=str(tmp_path / "in"), retry_failed=True)
    changed = [p for p in stamps if p.stat().st_mtime_ns != stamps[p]]
    assert changed == [out / "rows" / "broken.json"]


def test_a_killed_worker_loses_nothing_and_duplicates_nothing(tmp_path):
    paths = generated_collection(tmp_path / "in", 12, resolution=40)
    out = tmp_path / "out"
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=None)
    killed = []
    with Client(cluster) as dask_client:
        pids = list(dask_client.run(os.getpid).values())

        def kill_one_when_work_started():
            deadline = time.time() + 60
            while time.time() < deadline:
                if len(list((out / "rows").glob("*.json"))) >= 2 if (out / "rows").exists() \
                        else False:
                    os.kill(pids[0], signal.SIGKILL)
                    killed.append(pids[0])
                    return
                time.sleep(0.01)

        killer = threading.Thread(target=kill_one_when_work_started)
        killer.start()
        rows = collection.run(paths, str(out), client=dask_client, root=str(tmp_path / "in"))
        killer.join()
        survivors = list(dask_client.run(os.getpid).values())
    cluster.close()
    assert killed and killed[0] not in survivors  # the worker was really killed mid-run
    assert len(rows) == 12 and len({r["name"] for r in rows}) == 12
    for row in rows:
        assert row["status"] == "ok", row
        judge(out, row)
    # No half-written or temporary file anywhere, one set of outputs per mesh.
    leftovers = [p for p in out.rglob("*") if p.name.startswith(".")]
    assert leftovers == []
    outputs = sorted(p.name for p in (out / "meshes").rglob("*") if p.is_file())
    assert len(outputs) == 36


def test_the_command_runs_a_list_with_limits_on_a_running_scheduler(tmp_path, client):
    paths = generated_collection(tmp_path / "in", 3)
    big = make("torus", tmp_path / "in" / "big.off", "--resolution", "400")
    listing = tmp_path / "meshes.txt"
    listing.write_text("# the collection\n" + "\n".join(
        os.path.relpath(p, tmp_path) for p in paths + [str(big)]) + "\n")
    # On the running cluster of the fixture, through its scheduler's address.
    command = [sys.executable, "-m", "meromorph.collection", str(listing), str(tmp_path / "out"),
               "--scheduler", client.scheduler.address, "--quiet"]
    result = subprocess.run(command + ["--time-limit", "60", "--memory-limit", "80"],
                            capture_output=True, text=True)
    assert result.returncode == 3, result.stderr
    assert "4 meshes, 3 mapped, 1 not" in result.stdout
    rows = [json.loads(line) for line in (tmp_path / "out" / "table.jsonl").read_text().splitlines()]
    statuses = {row["name"]: row["status"] for row in rows}
    assert statuses["big"] == "memory limit"
    assert sorted(v for k, v in statuses.items() if k != "big") == ["ok"] * 3
    assert all(row["peak_memory_mb"] < 80 for row in rows if row["status"] == "ok")
    # Again, the failed one only, now with a time limit that stops it.
    result = subprocess.run(command + ["--retry-failed", "--time-limit", "0.3"],
                            capture_output=True, text=True)
    assert result.returncode == 3 and "4 meshes, 3 mapped, 1 not" in result.stdout
    rows = [json.loads(line) for line in (tmp_path / "out" / "table.jsonl").read_text().splitlines()]
    assert {row["name"]: row["status"] for row in rows}["big"] == "time limit"
    assert not (tmp_path / "out" / "meshes" / "big.uv.ply").exists()
