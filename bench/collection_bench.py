"""Meshes per minute of meromorph.collection on Dask (1 and 2 workers) against the command-line
tool called serially, on one collection of generated and shared meshes of 2k-50k vertices.

    python3 bench/collection_bench.py TOOL SHARED_MESHES [--count 200] [--work FOLDER]

Prints a table (Markdown). The Dask path's overhead is the 1-worker time over the serial time.
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def build_collection(tool: str, shared: Path, folder: Path, count: int) -> list:
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    def vertex_count(path):
        from meromorph import read
        return len(read(str(path))[0])

    # The closed shared meshes of 2k vertices and more (the open ones are face, eight.open, ...).
    shared_meshes = sorted(p for p in shared.glob("*.off")
                           if "open" not in p.name and "hole" not in p.name
                           and p.name != "face.off" and vertex_count(p) >= 2000)
    k = 0
    while len(paths) < count:
        kind = k % 4
        seed = str(k + 1)
        if kind == 0 and shared_meshes:
            source = shared_meshes[(k // 4) % len(shared_meshes)]
            path = folder / f"{k:03d}_{source.stem}.off"
            if not path.exists():
                path.symlink_to(source.resolve())
        else:
            resolution = str(40 + 14 * ((k // 4) % 5))  # 3k to 42k vertices
            path = folder / f"{k:03d}_g{kind - 1}_r{resolution}.ply"
            if not path.exists():
                subprocess.run([tool, "make", "genus", "-g", str(kind - 1), "--resolution",
                                resolution, "--rigid-motion", "--seed", seed, "-o", str(path)],
                               check=True, stdout=subprocess.DEVNULL)
        paths.append(str(path))
        k += 1
    return paths


def serial(tool: str, paths: list, out: Path) -> float:
    out.mkdir(parents=True, exist_ok=True)
    environment = dict(os.environ, OMP_NUM_THREADS="1")
    start = time.perf_counter()
    for k, path in enumerate(paths):
        base = out / f"{k:03d}"
        subprocess.run([tool, "param", path, "-o", f"{base}.uv.ply", "--sphere",
                        f"{base}.sphere.ply", "--report", f"{base}.report.json", "--quiet"],
                       env=environment, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def on_dask(paths: list, out: Path, workers: int, root: Path, describe: bool = True) -> float:
    from distributed import Client, LocalCluster
    from meromorph import collection
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                           dashboard_address=None)
    with Client(cluster) as client:
        start = time.perf_counter()
        rows = collection.run(paths, str(out), client=client, root=str(root), describe=describe)
        seconds = time.perf_counter() - start
    cluster.close()
    failed = [r for r in rows if r["status"] != "ok"]
    if failed:
        print(f"({len(failed)} meshes not mapped: {failed[0]['name']}: {failed[0]['error']})",
              file=sys.stderr)
    return seconds


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("tool")
    parser.add_argument("shared")
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--work", default=None)
    arguments = parser.parse_args()
    work = Path(arguments.work or tempfile.mkdtemp(prefix="meromorph-bench-"))
    paths = build_collection(arguments.tool, Path(arguments.shared), work / "in",
                             arguments.count)
    rows = []
    base = serial(arguments.tool, paths, work / "serial")
    rows.append(("CLI, serially (one thread)", base))
    for workers, describe in ((1, False), (1, True), (2, True)):
        seconds = on_dask(paths, work / f"dask{workers}{describe}", workers, work / "in", describe)
        rows.append((f"meromorph.collection, {workers} worker{'s' if workers > 1 else ''}"
                     + (", with the shape descriptors" if describe else ", no descriptors"),
                     seconds))
    print(f"\n{len(paths)} meshes (2k-50k vertices: generated genus 0-2 and the shared meshes)\n")
    print("| run | seconds | meshes per minute | time over the serial CLI |")
    print("|---|---|---|---|")
    for name, seconds in rows:
        print(f"| {name} | {seconds:.1f} | {60 * len(paths) / seconds:.1f} | "
              f"{seconds / base:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
