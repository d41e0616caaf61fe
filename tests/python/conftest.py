"""Shared by the Python tests: where the built package, the tool and the test meshes are, and an
own reader of the PLY files meromorph writes (so a written file is judged by code of the test's
own, not by the package's reader)."""

import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

REPOSITORY = Path(__file__).resolve().parents[2]
DATA = REPOSITORY / "tests" / "data"


def tool() -> str:
    return os.environ["MEROMORPH_TOOL"]


def make(kind: str, path: Path, *options: str) -> Path:
    subprocess.run([tool(), "make", kind, "-o", str(path), *options], check=True,
                   stdout=subprocess.DEVNULL)
    return path


_PLY_TYPES = {"char": "i1", "uchar": "u1", "short": "i2", "ushort": "u2", "int": "i4",
              "uint": "u4", "float": "f4", "double": "f8", "int8": "i1", "uint8": "u1",
              "int16": "i2", "uint16": "u2", "int32": "i4", "uint32": "u4", "float32": "f4",
              "float64": "f8"}


def read_ply_vertices(path: Path) -> dict:
    """The vertex element of a binary little-endian PLY, property by property (numpy arrays)."""
    data = Path(path).read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    assert "format binary_little_endian 1.0" in header, header[:3]
    count, fields, in_vertex = 0, [], False
    for line in header:
        words = line.split()
        if words[:1] == ["element"]:
            in_vertex = words[1] == "vertex"
            if in_vertex:
                count = int(words[2])
        elif words[:1] == ["property"] and in_vertex:
            assert words[1] != "list"
            fields.append((words[2], "<" + _PLY_TYPES[words[1]]))
    vertices = np.frombuffer(data, dtype=np.dtype(fields), count=count, offset=end)
    return {name: np.array(vertices[name]) for name, _ in fields}


@pytest.fixture(scope="session")
def tool_path() -> str:
    return tool()
