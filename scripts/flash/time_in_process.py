# python3 time_in_process.py ADDON_DIR MESH.off [REPEATS]: the least time of a genus-0 map made
# in a running process, as the Blender add-on makes it: its own ctypes binding
# (ADDON_DIR/library.py, with the libmeromorph.so beside it) called REPEATS times (default 3, as
# FLASH is timed) on the mesh, read before the clock starts. Prints "first_ms T" (the first call,
# which loads the library) and "least_ms T"; exits 1 if a map is not a valid degree-1 map.
import os
import sys
import time

import numpy as np


def read_off(path):
    with open(path) as file:
        words = [line.split("#")[0].split() for line in file]
    words = [w for w in words if w]
    if words[0][0] != "OFF":
        raise SystemExit("%s: not an OFF file" % path)
    header = words[0][1:] if len(words[0]) > 1 else words[1]
    first = 1 if len(words[0]) > 1 else 2
    vertices, faces = int(header[0]), int(header[1])
    positions = np.array(words[first:first + vertices], dtype=np.float64)[:, :3]
    polygons = words[first + vertices:first + vertices + faces]
    if any(p[0] != "3" for p in polygons):
        raise SystemExit("%s: only triangles are timed here" % path)
    triangles = np.array([p[1:4] for p in polygons], dtype=np.int32)
    return positions, triangles


def main():
    addon, mesh = sys.argv[1], sys.argv[2]
    repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    sys.path.insert(0, os.path.abspath(addon))
    import library  # the add-on's binding (blender_addon/meromorph_blender/library.py)

    positions, triangles = read_off(mesh)
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        out = library.parameterize(positions, triangles)
        times.append(1000 * (time.perf_counter() - start))
        if out["genus"] != 0 or out["degree"] != 1 or not out["valid"]:
            print("%s: not a valid genus-0 map (genus %d, degree %d)"
                  % (mesh, out["genus"], out["degree"]), file=sys.stderr)
            return 1
    print("first_ms %.1f\nleast_ms %.1f" % (times[0], min(times)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
