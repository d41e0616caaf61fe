"""The Python module against the command-line tool's written files, exact mathematics and bad
input."""

import json
import math
import subprocess
import threading
import time

import numpy as np
import pytest

import meromorph
from meromorph import descriptors
from conftest import DATA, make, read_ply_vertices, tool


@pytest.mark.parametrize("name", ["eight.off", "torus.off", "maxplanck.nf25k.off"])
def test_the_same_map_as_the_tool_writes(tmp_path, name):
    source = DATA / name
    subprocess.run([tool(), "param", str(source), "-o", str(tmp_path / "cli.ply"), "--sphere",
                    str(tmp_path / "cli.sphere.ply"), "--report", str(tmp_path / "cli.json"),
                    "--quiet"], check=True)
    m = meromorph.param(source)
    m.write(tmp_path / "py.ply", sphere=tmp_path / "py.sphere.ply", report=tmp_path / "py.json")
    cli = read_ply_vertices(tmp_path / "cli.ply")
    cli_sphere = read_ply_vertices(tmp_path / "cli.sphere.ply")
    written = read_ply_vertices(tmp_path / "py.ply")
    # The arrays in Python are what the tool writes (the file stores float32).
    assert len(m.uv) == len(cli["x"])
    assert np.allclose(m.uv[:, 0], cli["texture_u"], atol=1e-6)
    assert np.allclose(m.uv[:, 1], cli["texture_v"], atol=1e-6)
    assert np.allclose(m.layered, np.c_[cli_sphere["x"], cli_sphere["y"], cli_sphere["z"]],
                       atol=1e-6)
    assert np.array_equal(m.layer, cli_sphere["layer"])
    assert np.allclose(written["texture_u"], cli["texture_u"]) and np.allclose(
        written["texture_v"], cli["texture_v"])
    report = json.loads((tmp_path / "cli.json").read_text())
    assert m.genus == report["genus"] and m.degree == report["degree"]
    assert sorted(m.branch_vertices.tolist()) == sorted(b["vertex"] for b in report["branch_points"])
    # Riemann-Hurwitz from the arrays: 2g - 2 = d (0 - 2) + sum (e - 1).
    assert 2 * m.genus - 2 == -2 * m.degree + int(np.sum(m.branch_degrees - 1))
    assert np.allclose(np.linalg.norm(m.sphere, axis=1), 1, atol=1e-9)
    assert m.valid


def test_float32_and_int64_arrays_give_the_same_map():
    V, F = meromorph.read(DATA / "torus.off")
    a = meromorph.param(V, F)
    b = meromorph.param(V.astype(np.float32).astype(np.float64), F.astype(np.int64))
    c = meromorph.param(V.astype(np.float32), F)
    assert a.degree == b.degree == c.degree == 2
    assert np.allclose(b.sphere, c.sphere, atol=1e-9)


def test_bad_arrays_raise_and_name_the_problem():
    V, F = meromorph.read(DATA / "eight.off")
    cases = [
        ((V[:, :2], F), meromorph.ArgumentError, "shape"),
        ((V, F[:, :2]), meromorph.ArgumentError, "shape"),
        ((V, F.astype(float)), meromorph.ArgumentError, "integers"),
        ((V.astype(str), F), meromorph.ArgumentError, "numbers"),
        ((np.where(np.arange(len(V))[:, None] == 7, np.nan, V), F), meromorph.InputError,
         "vertices 7"),
        ((V, np.where(np.arange(len(F))[:, None] == 5, 10**6, F)), meromorph.InputError,
         "face 5"),
        ((V, np.where(np.arange(len(F))[:, None] == 9, -1, F)), meromorph.InputError, "face 9"),
        ((V, F.astype(np.int64) + 2**40), meromorph.ArgumentError, "32 bits"),
        ((np.zeros((0, 3)), np.zeros((0, 3), int)), meromorph.InputError, "no vertices"),
    ]
    for (positions, triangles), kind, words in cases:
        with pytest.raises(kind) as caught:
            meromorph.param(positions, triangles)
        assert words in str(caught.value), (words, str(caught.value))
    with pytest.raises(meromorph.ArgumentError, match="uv"):
        meromorph.param(V, F, uv="polar")
    with pytest.raises(meromorph.ArgumentError, match="origin_vertex"):
        meromorph.param(V, F, origin=10**7)
    with pytest.raises(meromorph.ArgumentError, match="one size"):
        meromorph.remesh(V, F, vertices=100, edge_length=0.1)
    # Refusals carry the remedy in this package's words.
    with pytest.raises(meromorph.InputError) as caught:
        meromorph.param(DATA / "eight.open.off", strict=True)
    assert "close_holes=True" in str(caught.value) and caught.value.remedies


def test_files_are_read_and_never_written_over(tmp_path):
    with pytest.raises(meromorph.ArgumentError, match="no_such"):
        meromorph.read(tmp_path / "no_such.ply")
    (tmp_path / "broken.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(meromorph.InputError, match="broken.off"):
        meromorph.read(tmp_path / "broken.off")
    source = tmp_path / "eight.off"
    source.write_bytes((DATA / "eight.off").read_bytes())
    before = source.read_bytes()
    m = meromorph.param(source)
    with pytest.raises(meromorph.ArgumentError, match="never writes over its input"):
        m.write(source)
    with pytest.raises(meromorph.ArgumentError):
        m.write(tmp_path / "out.ply", sphere=source)
    assert source.read_bytes() == before
    assert not (tmp_path / "out.ply").exists()  # all or none
    with pytest.raises(meromorph.WriteError):
        m.write(tmp_path / "no_folder" / "out.ply")


def test_progress_is_reported_and_can_cancel():
    V, F = meromorph.read(DATA / "kitten.nf20k.off")
    seen = []
    meromorph.param(V, F, progress=lambda fraction, stage: seen.append((fraction, stage)))
    assert seen and seen[-1][0] == pytest.approx(1.0)
    assert all(0 <= f <= 1 for f, _ in seen)
    with pytest.raises(meromorph.Cancelled):
        meromorph.param(V, F, progress=lambda fraction, stage: False)

    def fails(fraction, stage):
        raise KeyError("from the callback")

    with pytest.raises(KeyError, match="from the callback"):
        meromorph.param(V, F, progress=fails)
    assert meromorph.param(V, F).valid  # the interpreter and the library go on


def test_the_gil_is_released_while_the_library_works():
    V, F = meromorph.read(DATA / "kitten.nv40k.off")
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    ticker = threading.Thread(target=tick)
    ticker.start()
    start = time.perf_counter()
    meromorph.param(V, F)
    end = time.perf_counter()
    stop.set()
    ticker.join()
    during = [t for t in ticks if start < t < end]
    # A thread holding the GIL for the whole call would leave no tick inside it.
    assert len(during) > 0.1 * (end - start) / 0.0011, (len(during), end - start)
    # Two threads at once, each its own mesh, the same maps as one after the other.
    results = {}
    threads = [threading.Thread(target=lambda k=k: results.__setitem__(k, meromorph.param(
        DATA / ("eight.off" if k == 0 else "torus.off")))) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results[0].degree == 2 and results[1].degree == 2
    assert np.allclose(results[0].sphere, meromorph.param(DATA / "eight.off").sphere, atol=1e-12)


def test_forms_of_tori_give_their_exact_modulus(tmp_path):
    # Tori of revolution: modulus i sqrt(R^2 - r^2) / r; the error falls under refinement.
    errors = []
    for resolution in (16, 32):
        path = make("torus", tmp_path / f"t{resolution}.off", "-R", "3", "-r", "1",
                    "--resolution", str(resolution))
        f = meromorph.forms(path)
        exact = 1j * math.sqrt(8)
        assert f.genus == 1
        errors.append(abs(descriptors.reduced_modulus(f.modulus) - exact))
    assert errors[1] < errors[0] / 3 and errors[1] < 0.01, errors  # second order
    # The same torus moved and rescaled: the same reduced modulus.
    V, F = meromorph.read(path)
    R = np.linalg.qr(np.random.default_rng(5).normal(size=(3, 3)))[0]
    R *= np.sign(np.linalg.det(R))
    moved = meromorph.forms(V @ R.T * 0.01 + 7.0, F)
    assert abs(descriptors.reduced_modulus(moved.modulus) -
               descriptors.reduced_modulus(f.modulus)) < 1e-8
    f = meromorph.forms(DATA / "eight.off")
    assert f.genus == 2 and f.riemann_matrix.shape == (2, 2)
    # Riemann's bilinear relations: Omega symmetric with a positive definite imaginary part.
    assert np.allclose(f.riemann_matrix, f.riemann_matrix.T, atol=1e-3)
    assert np.all(np.linalg.eigvalsh(f.riemann_matrix.imag) > 0)
    # The canonical basis is symplectic: P^T W P = J with integer entries.
    assert f.symplectic_basis.shape == (4, 4)
    assert round(abs(np.linalg.det(f.symplectic_basis))) == 1


def test_remesh_gives_a_closed_surface_of_the_same_genus():
    r = meromorph.remesh(DATA / "eight.off", vertices=1500)
    V, F = r.vertices, r.triangles
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    unique, counts = np.unique(edges, axis=0, return_counts=True)
    assert np.all(counts == 2)  # closed and manifold along every edge
    assert len(V) - len(unique) + len(F) == -2  # genus 2
    assert 1200 < len(V) < 1800
    assert np.count_nonzero(r.branch) > 0


def test_the_spherical_harmonics_are_orthonormal():
    # Gauss-Legendre in cos(theta) times the trapezoid rule in phi: exact for these degrees.
    x, wx = np.polynomial.legendre.leggauss(40)
    phi = np.linspace(0, 2 * np.pi, 80, endpoint=False)
    X, P = np.meshgrid(x, phi, indexing="ij")
    W = (wx[:, None] * np.full(80, 2 * np.pi / 80)[None, :]).ravel()
    Q = descriptors._normalized_legendre(16, X.ravel())
    Y = {(l, m): Q[l, m] * np.exp(1j * m * P.ravel()) for l in range(17) for m in range(l + 1)}
    for (l, m), a in Y.items():
        for (k, n), b in Y.items():
            if m == n and k >= l:
                assert abs(np.sum(W * a * np.conj(b)) - (l == k)) < 1e-10, (l, m, k, n)


def test_descriptors_are_invariant_and_close_after_remeshing():
    V, F = meromorph.read(DATA / "maxplanck.nf25k.off")
    m = meromorph.param(V, F)
    base = descriptors.spherical_harmonic_energies(m.vertices, m.triangles, m.sphere)
    rng = np.random.default_rng(3)
    R = np.linalg.qr(rng.normal(size=(3, 3)))[0]
    R *= np.sign(np.linalg.det(R))
    moved = meromorph.param(V @ R.T * 2.5 + np.array([1.0, -4.0, 2.0]), F)
    again = descriptors.spherical_harmonic_energies(moved.vertices, moved.triangles,
                                                    moved.sphere)
    assert np.allclose(base, again, rtol=1e-6, atol=1e-12 * base.sum())
    r = meromorph.remesh(V, F, vertices=8000)
    remeshed = meromorph.param(r.vertices, r.triangles)
    other = descriptors.spherical_harmonic_energies(remeshed.vertices, remeshed.triangles,
                                                    remeshed.sphere)
    assert np.abs(other[1:9] - base[1:9]).sum() < 0.05 * base[1:9].sum()
    # A different shape is farther away than the remesh.
    ball = meromorph.param(DATA / "sphere.off")
    round_one = descriptors.spherical_harmonic_energies(ball.vertices, ball.triangles,
                                                        ball.sphere)
    assert np.abs(round_one[1:9] - base[1:9]).sum() > 5 * np.abs(other[1:9] - base[1:9]).sum()
    # The modulus: the same torus rigidly moved or as its mirror basis, the same descriptor.
    assert descriptors.reduced_modulus(-1 / (0.2 + 1.5j)) == pytest.approx(0.2 + 1.5j)
    # 3.3 + 0.9i -> 0.3 + 0.9i (|tau| < 1) -> -1 / tau = -1/3 + i, in the fundamental domain.
    assert descriptors.reduced_modulus(3.3 + 0.9j) == pytest.approx(-1 / 3 + 1j)


def test_match_is_the_tools_and_carries_values_from_the_target(tmp_path):
    # Two triangulations of the kitten made apart, the second at ten times the size: the source's
    # vertices land where the same point of the kitten is, and the matched points are what
    # `meromorph match` writes.
    source, target = DATA / "kitten.nf20k.off", DATA / "kitten.nv40k.off"
    m = meromorph.match(source, target)
    V, _ = meromorph.read(source)
    W, G = meromorph.read(target)
    diagonal = np.linalg.norm(W.max(axis=0) - W.min(axis=0))
    assert m.report["genus"] == 1 and (m.target_face >= 0).all()
    assert np.allclose(m.weights.sum(axis=1), 1.0)
    assert np.linalg.norm(m.points - 10 * V, axis=1).mean() < 0.002 * diagonal
    # transfer() reads the target's values at the matched points: its positions are the points.
    assert np.allclose(m.transfer(W), m.points, atol=1e-9 * diagonal)
    assert m.transfer(W[:, 0]).shape == (len(V),)
    # Per source triangle corner from one target triangle: each corner's point, up to its distance
    # from that triangle's plane.
    F = meromorph.read(source)[1]
    corners = m.transfer_corners(W[G])  # (t, 3, 3): the target's corner positions
    assert corners.shape == (len(F), 3, 3) and (m.triangle_face >= 0).all()
    assert np.linalg.norm(corners - m.points[F], axis=2).max() < 0.01 * diagonal
    subprocess.run([tool(), "match", str(source), str(target), "-o", str(tmp_path / "m.ply"),
                    "--quiet"], check=True)
    cli = read_ply_vertices(tmp_path / "m.ply")
    assert np.array_equal(cli["target_face"], m.target_face)
    assert np.allclose(np.c_[cli["x"], cli["y"], cli["z"]], m.points, atol=1e-4 * diagonal)
    with pytest.raises(meromorph.ArgumentError):
        meromorph.match(source, target, landmarks=[1, 2, 3])
    with pytest.raises(meromorph.InputError, match="99999"):
        meromorph.match(source, target, landmarks=[[0, 99999]])
