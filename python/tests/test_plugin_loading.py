"""`import obscura` loads no image codecs (they are plugins loaded on the first image read or
write, docs/architecture.md); the first image file loads the native codecs but not OpenImageIO,
and a missing plugin is an obscura.Error naming where it was looked for."""

import os
import subprocess
import sys

# Run in a fresh interpreter: this one may already have written images. Prints which of the
# libraries of interest are mapped after the import, and after writing an image.
PROBE = """
import sys, numpy as np
import obscura
def mapped():
    maps = open('/proc/self/maps').read()
    return ','.join(n for n in ('libOpenImageIO', 'libobscura_image_codecs', 'libmpi') if n in maps)
print('import:', mapped())
try:
    obscura.write_image(sys.argv[1], np.full((2, 2, 3), 0.5, np.float32))
    print('write: ok', mapped())
except obscura.Error as e:
    print('write: error', e)
"""


def run_probe(out_file, **env):
    return subprocess.run([sys.executable, "-c", PROBE, str(out_file)], capture_output=True,
                          text=True, check=True, timeout=120, env={**os.environ, **env})


def test_import_loads_no_codecs_and_the_first_write_does(tmp_path):
    lines = run_probe(tmp_path / "a.png").stdout.splitlines()
    assert lines[0] == "import: "
    assert lines[1].startswith("write: ok")
    assert "libobscura_image_codecs" in lines[1] and "libOpenImageIO" not in lines[1]
    assert (tmp_path / "a.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_missing_codecs_plugin_is_an_error_naming_where_it_looked(tmp_path):
    empty = tmp_path / "plugins"
    empty.mkdir()
    result = run_probe(tmp_path / "a.png", OBSCURA_PLUGIN_DIR=str(empty))
    assert "write: error" in result.stdout
    assert str(empty / "libobscura_image_codecs.so") + ": not there" in result.stdout
    assert not (tmp_path / "a.png").exists()
