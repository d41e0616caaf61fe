"""docs/python.md: every python block runs, in order, in a folder with the tutorial's meshes."""

import os
import re
import shutil

from conftest import DATA, REPOSITORY


def test_every_block_of_the_tutorial_runs(tmp_path, capsys):
    text = (REPOSITORY / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) >= 6
    for name in ("eight.off", "torus.off"):
        shutil.copy(DATA / name, tmp_path / name)
    here = os.getcwd()
    os.chdir(tmp_path)
    try:
        namespace = {}
        for block in blocks:
            exec(compile(block, "docs/python.md", "exec"), namespace)
    finally:
        os.chdir(here)
    printed = capsys.readouterr().out
    assert "valid" in printed and "cancelled" in printed and "vertices 7" in printed
    assert (tmp_path / "eight.uv.ply").is_file() and (tmp_path / "out" / "table.csv").is_file()
    assert "eight ok 2 2" in printed and "torus ok 1 2" in printed


def test_the_set_up_makes_the_package_importable_for_debians_python(tmp_path):
    import subprocess
    environment = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    found = subprocess.run(["/usr/bin/python3", "-c", "import meromorph; print(meromorph.__file__)"],
                           capture_output=True, text=True, cwd=tmp_path, env=environment)
    assert found.returncode == 0, found.stderr
    assert found.stdout.strip().endswith("python/meromorph/__init__.py"), found.stdout
