#!/usr/bin/env python3
"""Fixed costs (issue 18): what a process pays before any work. Run from the repository root:

    python3 bench/startup.py [--build build] [--build OTHER_BUILD …] [--repeat 20]

Times `BUILD/obscura --version`, `python3 -c "import obscura"` (PYTHONPATH=BUILD/python), renders
of 8×8 pixels at 1 spp to each output format (PNG, EXR, JPEG, TIFF, HDR load the image codecs;
PFM needs none), renders that read an EXR or HDR environment map (to PFM), and `obscura info` of
a glTF with a PNG and one with a JPEG texture. Each runs REPEAT times, alternating between the
cases and between the builds (when several are given, e.g. before and after a change), and the
median and range of wall time and of peak resident memory (the child's ru_maxrss, from wait4)
are printed, with the shared libraries each loads (the dynamic loader's own count,
LD_DEBUG=libs, dlopened plugins included; for Python, /proc/PID/maps of a process that has done
the same start-up) and the machine's load (/proc/loadavg) before and after. A plain
`python3 -c pass` is timed too, as the floor of the import row: the interpreter's own start-up,
which no change to Obscura removes.
"""

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time


def run_once(command, env):
    start = time.perf_counter()
    process = subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"{' '.join(command)} failed ({status})")
    return wall, usage.ru_maxrss / 1024.0  # ru_maxrss is in KiB on Linux


def loaded_libraries(command, env):
    """Shared objects mapped once start-up is done: the command runs with a probe appended that
    lists its own maps, so the count is the process's own, not ldd's guess."""
    out = subprocess.run(command, env=env, capture_output=True, text=True, check=True).stdout
    return len({line.split()[-1] for line in out.splitlines() if ".so" in line})


def ld_debug_libraries(command, env):
    """Shared objects the dynamic loader initialised (LD_DEBUG=libs): start-up and dlopen both."""
    out = subprocess.run(command, env=dict(env, LD_DEBUG="libs"), capture_output=True,
                         text=True).stderr
    return len(set(re.findall(r"calling init: (\S+)", out)))


def prepare_inputs(cli, scratch, env):
    """Environment maps and textured glTF files for the read rows, written by `cli` itself."""
    tiny = [cli, "render", "--width", "16", "--height", "8", "--spp", "1", "--quiet", "-o"]
    for name in ("env.exr", "env.hdr", "texture.jpg"):
        subprocess.run(tiny + [os.path.join(scratch, name)], env=env, check=True,
                       stdout=subprocess.DEVNULL)
    box = os.path.join("tests", "data", "gltf", "BoxTextured", "glTF")
    for name in os.listdir(box):
        shutil.copy(os.path.join(box, name), scratch)
    with open(os.path.join(scratch, "BoxTextured.gltf")) as f:
        gltf = f.read()
    with open(os.path.join(scratch, "BoxTexturedJpeg.gltf"), "w") as f:
        f.write(gltf.replace("CesiumLogoFlat.png", "texture.jpg"))


def cases_for(build, scratch):
    cli = os.path.join(build, "obscura")
    tiny = [cli, "render", "--width", "8", "--height", "8", "--spp", "1", "--quiet"]
    out = lambda ext: ["-o", os.path.join(scratch, f"tiny-{abs(hash(build))}.{ext}")]
    cases = {"obscura --version": [cli, "--version"]}
    for ext in ("png", "exr", "jpg", "tif", "hdr", "pfm"):
        cases[f"obscura render 8x8 -o .{ext}"] = tiny + out(ext)
    for ext in ("exr", "hdr"):
        cases[f"render --environment .{ext} -o .pfm"] = (
            tiny + ["--environment", os.path.join(scratch, f"env.{ext}")] + out("pfm"))
    cases["obscura info glTF + PNG texture"] = [cli, "info",
                                               os.path.join(scratch, "BoxTextured.gltf")]
    cases["obscura info glTF + JPEG texture"] = [cli, "info",
                                                os.path.join(scratch, "BoxTexturedJpeg.gltf")]
    cases["python3 -c 'import obscura'"] = [sys.executable, "-c", "import obscura"]
    cases["python3 -c pass (floor)"] = [sys.executable, "-c", "pass"]
    return cases


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", action="append",
                        help="build folder (repeat to compare builds; default: build)")
    parser.add_argument("--repeat", type=int, default=20)
    args = parser.parse_args()
    builds = args.build or ["build"]
    scratch = tempfile.mkdtemp(prefix="obscura-startup-")
    envs = {b: dict(os.environ, PYTHONPATH=os.path.join(b, "python")) for b in builds}
    prepare_inputs(os.path.join(builds[0], "obscura"), scratch, envs[builds[0]])
    cases = {b: cases_for(b, scratch) for b in builds}
    print("load before:", open("/proc/loadavg").read().strip())
    samples = {(b, name): [] for b in builds for name in cases[b]}
    for _ in range(args.repeat):
        for name in cases[builds[0]]:
            for b in builds:
                samples[(b, name)].append(run_once(cases[b][name], envs[b]))
    print("load after: ", open("/proc/loadavg").read().strip())
    maps_probe = "import sys; sys.stdout.write(open('/proc/self/maps').read())"
    libraries = {}
    for b in builds:
        for name, command in cases[b].items():
            if name.startswith("python3"):
                code = ("import obscura; " if "import" in name else "") + maps_probe
                libraries[(b, name)] = loaded_libraries([sys.executable, "-c", code], envs[b])
            else:
                libraries[(b, name)] = ld_debug_libraries(command, envs[b])
    print(f"{'command':52} {'wall ms median (min–max)':>26} {'peak RSS MiB median (min–max)':>31}"
          f" {'shared libs':>11}")
    for name in cases[builds[0]]:
        for b in builds:
            runs = samples[(b, name)]
            walls = [1000 * w for w, _ in runs]
            rss = [r for _, r in runs]
            label = name if len(builds) == 1 else f"{name} [{b}]"
            print(f"{label:52} {statistics.median(walls):9.1f} ({min(walls):6.1f}–"
                  f"{max(walls):6.1f})   {statistics.median(rss):12.1f} ({min(rss):6.1f}–"
                  f"{max(rss):6.1f})   {libraries[(b, name)]:>11}")
    shutil.rmtree(scratch)


if __name__ == "__main__":
    main()
