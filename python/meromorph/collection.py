"""Map a whole collection of meshes, on this machine or a Dask cluster.

    python3 -m meromorph.collection IN OUT [--scheduler ADDRESS] [--workers N]
            [--time-limit S] [--memory-limit MB] [--retry-failed] [--no-descriptors]
            [param options]

maps every mesh under IN (a folder, searched for .ply .obj .off .stl; or a text file listing one
path per line) with `meromorph param` and the given options (for example --area-correct, --uv
stereographic), and writes under OUT:

- meshes/NAME.uv.ply, NAME.sphere.ply, NAME.report.json: each mesh's outputs, all or none, moved
  into place when complete (NAME: the path under IN without its extension);
- rows/NAME.json: the mesh's row, written (atomically) only after its outputs;
- table.csv and table.jsonl (and table.parquet with pyarrow): one row per mesh: file, vertices,
  genus, degree, branch points, angle error, folded faces, modulus or Riemann matrix, shape
  descriptor, seconds, peak memory, status and error.

A rerun skips every mesh that has a row (--retry-failed: all but those that failed). A mesh that
fails gets its row with the error, and the others go on. Each mesh is mapped in a process of its
own (the command-line tool), so a mesh over its time or memory limit is stopped and reported as
such, and a worker that dies has its tasks retried elsewhere by Dask without duplicates: outputs
and rows are replaced whole, never appended.

Default: a distributed.LocalCluster of --workers processes (one thread each; the tool then runs
on one thread) on this machine; --scheduler tcp://HOST:8786 uses a running Dask cluster whose
workers have this package. From Python: `run(paths, out, client=...)`.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import uuid
from pathlib import Path
from typing import Iterable, List, Optional, Sequence, Tuple

MESH_EXTENSIONS = (".ply", ".obj", ".off", ".stl")
COLUMNS = ["file", "name", "status", "error", "vertices", "faces", "genus", "degree",
           "branch_points", "angle_error_mean", "angle_error_away_from_branch_points",
           "folded_faces", "valid", "modulus", "riemann_matrix", "spharm", "seconds",
           "peak_memory_mb"]


def tool_path() -> str:
    """The command-line tool shipped in this package (bin/meromorph), else `meromorph` on PATH."""
    here = Path(__file__).resolve().parent / "bin" / "meromorph"
    if here.is_file():
        return str(here)
    found = shutil.which("meromorph")
    if not found:
        raise FileNotFoundError("the meromorph command-line tool is neither in the package "
                                "(meromorph/bin) nor on PATH")
    return found


def find_meshes(source: str) -> List[str]:
    """Every mesh file under a folder (sorted), or the paths a list file names (one per line,
    relative to the list's folder; # starts a comment)."""
    path = Path(source)
    if path.is_dir():
        return sorted(str(p) for p in path.rglob("*")
                      if p.is_file() and p.suffix.lower() in MESH_EXTENSIONS)
    if path.is_file():
        listed = []
        for line in path.read_text().splitlines():
            line = line.split("#", 1)[0].strip()
            if line:
                listed.append(str((path.parent / line) if not os.path.isabs(line) else Path(line)))
        return listed
    raise FileNotFoundError(f"{source}: no such folder or list file")


def mesh_name(path: str, root: Optional[str]) -> str:
    """The name of a mesh's outputs: its path under `root` without the extension (else the file's
    stem)."""
    p = Path(path)
    if root and Path(root).is_dir():
        try:
            p = p.resolve().relative_to(Path(root).resolve())
        except ValueError:
            p = Path(p.name)
    else:
        p = Path(p.name)
    return str(p.with_suffix(""))


def _write_atomically(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix="." + path.name + ".")
    try:
        with os.fdopen(handle, "w") as stream:
            stream.write(text)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def _resident_mb(pid: int) -> float:
    try:
        with open(f"/proc/{pid}/status") as status:
            for line in status:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) / 1024
    except (OSError, ValueError, IndexError):
        pass
    return 0.0


def _run_tool(command: List[str], time_limit: Optional[float],
              memory_limit: Optional[float]) -> Tuple[Optional[str], int, str, float]:
    """Runs the tool in a process of its own, watched every 50 ms: (the limit it was stopped at,
    "time" or "memory", else None; its exit code; its standard error; seconds). The memory watched
    is the tool's resident memory (a limit on its address space or data would stop it in
    OpenBLAS's start, which reserves buffers it never touches)."""
    environment = dict(os.environ, OMP_NUM_THREADS=os.environ.get("OMP_NUM_THREADS", "1"))
    stopped = []
    with tempfile.TemporaryFile() as errors:
        start = time.perf_counter()
        child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=errors,
                                 env=environment)
        finished = threading.Event()

        def watch():
            while not finished.wait(0.05):
                if time_limit and time.perf_counter() - start > time_limit:
                    stopped.append("time")
                elif memory_limit and _resident_mb(child.pid) > memory_limit:
                    stopped.append("memory")
                else:
                    continue
                child.kill()  # (not yet waited for: the pid is still the child's)
                return

        watcher = threading.Thread(target=watch, daemon=True)
        watcher.start()
        try:
            code = child.wait()
        finally:
            finished.set()
            watcher.join()
        seconds = time.perf_counter() - start
        errors.seek(0)
        message = errors.read().decode("utf-8", "replace").strip()
    return (stopped[0] if stopped else None), code, message, seconds


def _descriptor(genus: int, report: dict, uv_file: Path, sphere_file: Path) -> dict:
    from . import descriptors, read
    if genus == 0:
        vertices, triangles = read(str(uv_file))
        sphere, _ = read(str(sphere_file))
        return descriptors.describe(0, report, vertices, triangles, sphere[:len(vertices)])
    return descriptors.describe(genus, report)


def map_one(path: str, name: str, out: str, options: Sequence[str] = (),
            time_limit: Optional[float] = None, memory_limit: Optional[float] = None,
            tool: Optional[str] = None, describe: bool = True) -> dict:
    """Maps one mesh with the command-line tool in a process of its own, writes its outputs and
    then its row (rows/NAME.json), and returns the row. Never raises for a mesh that fails.
    `describe`: the shape descriptor too (for genus 0 it reads the written files back)."""
    out_dir = Path(out)
    base = out_dir / "meshes" / name
    base.parent.mkdir(parents=True, exist_ok=True)
    uv_file = base.with_name(base.name + ".uv.ply")
    sphere_file = base.with_name(base.name + ".sphere.ply")
    report_file = base.with_name(base.name + ".report.json")
    row = {column: None for column in COLUMNS}
    row.update(file=path, name=name)
    command = [tool or tool_path(), "param", path, "-o", str(uv_file), "--sphere",
               str(sphere_file), "--report", str(report_file), "--quiet", *options]
    try:
        stopped, status, message, seconds = _run_tool(command, time_limit, memory_limit)
    except OSError as error:
        row.update(status="error", error=f"cannot run the tool: {error}")
        _write_atomically(out_dir / "rows" / (name + ".json"), json.dumps(row) + "\n")
        return row
    row["seconds"] = round(seconds, 4)
    if stopped == "time":
        row.update(status="time limit", error=f"stopped after {time_limit} s")
    elif stopped == "memory":
        row.update(status="memory limit", error=f"stopped above {memory_limit} MB resident")
    elif status == 0:
        row["status"] = "ok"
    elif status < 0:
        row.update(status="killed", error=f"killed by signal {-status}")
    else:
        row.update(status={3: "refused", 2: "bad arguments", 4: "write failed"}.get(
            status, "failed"), error=message.replace("meromorph: error: ", "") or
            f"exit code {status}")
    if report_file.is_file() and row["status"] == "ok":
        report = json.loads(report_file.read_text())
        distortion = report.get("distortion", {})
        overall = distortion.get("overall", {})
        away = distortion.get("away_from_branch_points", {})
        row.update(vertices=report.get("vertices"), faces=report.get("faces"),
                   genus=report.get("genus"), degree=report.get("degree"),
                   branch_points=len(report.get("branch_points", [])), valid=report.get("valid"),
                   angle_error_mean=overall.get("angle_error_mean_degrees"),
                   angle_error_away_from_branch_points=away.get("angle_error_mean_degrees"),
                   folded_faces=overall.get("folded_faces"),
                   peak_memory_mb=report.get("peak_memory_mb"))
        descriptor = _descriptor(int(row["genus"]), report, uv_file, sphere_file) if describe \
            else {}
        row["modulus"] = descriptor.get("modulus")
        row["riemann_matrix"] = descriptor.get("riemann_matrix")
        row["spharm"] = descriptor.get("spharm")
    _write_atomically(out_dir / "rows" / (name + ".json"), json.dumps(row) + "\n")
    return row


def read_row(out: str, name: str) -> Optional[dict]:
    try:
        return json.loads((Path(out) / "rows" / (name + ".json")).read_text())
    except (OSError, ValueError):
        return None


def write_table(out: str, rows: List[dict]) -> None:
    """table.csv, table.jsonl (and table.parquet when pyarrow is installed), each replaced whole."""
    out_dir = Path(out)
    rows = sorted(rows, key=lambda row: row["name"])
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=COLUMNS, extrasaction="ignore")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: (json.dumps(v) if isinstance(v, (list, dict)) else v)
                         for k, v in row.items()})
    _write_atomically(out_dir / "table.csv", text.getvalue())
    _write_atomically(out_dir / "table.jsonl", "".join(json.dumps(r) + "\n" for r in rows))
    try:
        import pyarrow
        import pyarrow.parquet
    except ImportError:
        return
    columns = {c: [json.dumps(r.get(c)) if isinstance(r.get(c), (list, dict)) else r.get(c)
                   for r in rows] for c in COLUMNS}
    temporary = out_dir / ".table.parquet.part"
    pyarrow.parquet.write_table(pyarrow.table(columns), temporary)
    os.replace(temporary, out_dir / "table.parquet")


def _bar(done: int, total: int, started: float, stream=sys.stderr) -> None:
    if not stream.isatty() and done not in (0, total):
        return  # a log file gets the first and last line only
    width = 30
    filled = int(width * done / max(total, 1))
    elapsed = time.perf_counter() - started
    stream.write(f"\r\x1b[K" if stream.isatty() else "")
    stream.write(f"meromorph: [{'#' * filled}{'.' * (width - filled)}] {done}/{total} meshes, "
                 f"{elapsed:.0f} s" + ("" if stream.isatty() else "\n"))
    stream.flush()


def run(paths: Iterable[str], out: str, client=None, options: Sequence[str] = (),
        root: Optional[str] = None, time_limit: Optional[float] = None,
        memory_limit: Optional[float] = None, retry_failed: bool = False,
        workers: int = 2, progress: bool = False, describe: bool = True) -> List[dict]:
    """Maps every mesh of `paths` on `client` (a distributed.Client; default: a LocalCluster of
    `workers` processes made and closed here), writes outputs, rows and the table under `out`, and
    returns the rows (one per mesh, sorted by name). `options`: `meromorph param` options;
    `describe`: the shape descriptors (modulus, Riemann matrix, spherical-harmonic energies)."""
    from distributed import Client, LocalCluster, as_completed

    paths = list(paths)
    names = [mesh_name(p, root) for p in paths]
    if len(set(names)) != len(names):
        seen = set()
        twice = sorted({n for n in names if n in seen or seen.add(n)})
        raise ValueError(f"two meshes would write the same outputs: {', '.join(twice[:5])}")
    Path(out).mkdir(parents=True, exist_ok=True)
    rows = {}
    todo = []
    for path, name in zip(paths, names):
        row = read_row(out, name)
        if row is not None and not (retry_failed and row.get("status") != "ok"):
            rows[name] = row
        else:
            todo.append((path, name))

    own_cluster = None
    if client is None and todo:
        own_cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                   dashboard_address=None)
        client = Client(own_cluster)
    try:
        started = time.perf_counter()
        if todo:
            # Each worker finds its own tool (the package's copy on that machine). Keys are this
            # run's own, so a finished or failed task of an earlier run is never taken for it.
            token = uuid.uuid4().hex[:8]
            futures = {client.submit(map_one, path, name, str(Path(out).resolve()),
                                     list(options), time_limit, memory_limit, None, describe,
                                     key=f"meromorph-{name}-{token}", pure=False, retries=2): (path, name)
                       for path, name in todo}
            done = len(rows)
            if progress:
                _bar(done, len(paths), started)
            for future in as_completed(list(futures)):
                try:
                    row = future.result()
                except Exception as error:  # the task itself failed (a worker died too often)
                    path, name = futures[future]
                    row = {column: None for column in COLUMNS}
                    row.update(file=path, name=name, status="worker lost",
                               error=f"{type(error).__name__}: {error}")
                    _write_atomically(Path(out) / "rows" / (name + ".json"),
                                      json.dumps(row) + "\n")
                rows[row["name"]] = row
                done += 1
                if progress:
                    _bar(done, len(paths), started)
            if progress and sys.stderr.isatty():
                sys.stderr.write("\n")
    finally:
        if own_cluster is not None:
            client.close()
            own_cluster.close()
    ordered = [rows[name] for name in names]
    write_table(out, ordered)
    return sorted(ordered, key=lambda row: row["name"])


def main(argv: Optional[Sequence[str]] = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python3 -m meromorph.collection",
        description="Map every mesh under IN (a folder, or a file listing paths) and write each "
                    "one's outputs and a table under OUT. Options it does not know go to "
                    "`meromorph param` (for example --area-correct, --uv stereographic).")
    parser.add_argument("input", metavar="IN")
    parser.add_argument("output", metavar="OUT")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler "
                        "(default: a cluster on this machine)")
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1,
                        help="worker processes of the local cluster (default: the cores)")
    parser.add_argument("--time-limit", type=float, help="seconds per mesh")
    parser.add_argument("--memory-limit", type=float, help="megabytes per mesh")
    parser.add_argument("--retry-failed", action="store_true",
                        help="map again the meshes whose row has an error")
    parser.add_argument("--no-descriptors", action="store_true",
                        help="leave the shape descriptors out of the table")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    arguments, param_options = parser.parse_known_args(argv)
    try:
        paths = find_meshes(arguments.input)
    except FileNotFoundError as error:
        print(f"meromorph: error: {error}", file=sys.stderr)
        return 2
    if not paths:
        print(f"meromorph: error: {arguments.input}: no .ply, .obj, .off or .stl file",
              file=sys.stderr)
        return 2
    client = None
    if arguments.scheduler:
        from distributed import Client
        client = Client(arguments.scheduler)
    root = arguments.input if Path(arguments.input).is_dir() else None
    try:
        rows = run(paths, arguments.output, client=client, options=param_options, root=root,
                   time_limit=arguments.time_limit, memory_limit=arguments.memory_limit,
                   retry_failed=arguments.retry_failed, workers=arguments.workers,
                   describe=not arguments.no_descriptors,
                   progress=not arguments.quiet)
    finally:
        if client is not None:
            client.close()
    failed = [row for row in rows if row["status"] != "ok"]
    print(f"meromorph: {len(rows)} meshes, {len(rows) - len(failed)} mapped, {len(failed)} not; "
          f"table: {Path(arguments.output) / 'table.csv'}")
    return 0 if not failed else 3


if __name__ == "__main__":
    sys.exit(main())
