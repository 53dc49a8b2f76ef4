"""The module finds the example scenes (built-in scenes stored as files, the studio map that lights
models without lights) from where the module itself is, whatever the working directory: from the
build tree, and from an installed package that carries its own copy (docs/python.md)."""

import os
import pathlib
import shutil
import subprocess
import sys

import pytest

import obscura

# Run in a fresh interpreter, from a working directory with no scenes in it. Prints what the test
# checks: the built-in scene stored as a JSON file, and how a model without lights is lit.
PROBE = """
import sys
import obscura
try:
    bunny = obscura.load_scene('bunny')
    print('bunny:', bunny.name, bunny.stats()['triangles'])
except obscura.Error as e:
    print('bunny: error', e)
box = obscura.load_scene(sys.argv[1])
print('box textures:', box.stats()['textures'])
for warning in box.warnings:
    print('box warning:', warning)
"""



@pytest.fixture
def probe(source_dir):
    """Runs the probe from `working_dir` with only `pythonpath` to import from, and without
    OBSCURA_SCENES_DIR unless `env` sets it; returns its output lines."""
    box = source_dir / "tests/data/gltf/Box/Box.glb"  # a model without lights

    def run(working_dir, pythonpath, **env):
        environment = {k: v for k, v in os.environ.items() if k != "OBSCURA_SCENES_DIR"}
        environment.update(PYTHONPATH=str(pythonpath), PYTHONDONTWRITEBYTECODE="1", **env)
        result = subprocess.run([sys.executable, "-c", PROBE, str(box)], cwd=working_dir,
                                env=environment, capture_output=True, text=True, check=True,
                                timeout=120)
        return result.stdout.splitlines()

    return run


def module_import_dir():
    """The folder `import obscura` found the package in (the one holding obscura/)."""
    return pathlib.Path(obscura.__file__).resolve().parents[1]


def assert_scenes_found(lines, bunny_name="bunny"):
    assert lines[0].startswith(f"bunny: {bunny_name} "), lines
    assert int(lines[0].split()[-1]) > 16000  # the bunny's triangles and the floor's
    # Box.glb has no texture and no light: its one texture is the studio map.
    assert "box textures: 1" in lines
    warnings = [line for line in lines if line.startswith("box warning:")]
    assert any("lit by the studio environment" in w for w in warnings), lines
    assert not any("uniform white" in w or "not found" in w for w in warnings), lines


def test_the_module_finds_the_scenes_from_another_working_directory(tmp_path, probe):
    assert_scenes_found(probe(tmp_path, module_import_dir()))


def test_without_a_scenes_folder_the_messages_say_where_they_looked(tmp_path, probe):
    empty = tmp_path / "no-scenes"
    empty.mkdir()
    lines = probe(tmp_path, module_import_dir(), OBSCURA_SCENES_DIR=str(empty))
    assert lines[0].startswith("bunny: error"), lines
    assert str(empty / "bunny.json") in lines[0] and "OBSCURA_SCENES_DIR" in lines[0]
    assert "box textures: 0" in lines
    warnings = [line for line in lines if line.startswith("box warning:")]
    assert any("uniform white" in w and str(empty / "assets/envmaps/studio.exr") in w
               for w in warnings), lines


def build_tree_of_module():
    """The CMake build tree the imported module was built in, or None (an installed module)."""
    for folder in module_import_dir().parents:
        if (folder / "CMakeCache.txt").is_file():
            return folder
    return None


def test_the_installed_package_finds_its_own_scenes(tmp_path, probe):
    build = build_tree_of_module()
    cmake = shutil.which("cmake")
    if build is None or cmake is None:
        pytest.skip("needs cmake and the module's build tree")
    prefix = tmp_path / "prefix"
    subprocess.run([cmake, "--install", str(build), "--component", "python", "--prefix",
                    str(prefix)], check=True, capture_output=True, timeout=120)
    [package] = prefix.rglob("obscura/__init__.py")
    # Marks the installed copy of the scene, so that the scene read from the source tree (the
    # module's last resort) would fail the test.
    assert (package.parent / "scenes/assets/envmaps/studio.exr").is_file()
    installed_bunny = package.parent / "scenes/bunny.json"
    text = installed_bunny.read_text()
    installed_bunny.write_text(text.replace('"name": "bunny"', '"name": "installed-bunny"', 1))
    working_dir = tmp_path / "elsewhere"
    working_dir.mkdir()
    assert_scenes_found(probe(working_dir, package.parents[1]), bunny_name="installed-bunny")
