#!/usr/bin/env python3
"""Fixed costs (issue 18): what a process pays before any work. Run from the repository root:

    python3 bench/startup.py [--build build] [--repeat 20]

Times `BUILD/obscura --version`, `python3 -c "import obscura"` (PYTHONPATH=BUILD/python) and, for
the cost that moved rather than vanished, a render of 8×8 pixels at 1 spp to a PNG (which loads
the image codecs) and to a PFM (which needs none), each REPEAT times, alternating, and prints the median and range of wall time and of peak resident
memory (the child's ru_maxrss, from wait4), the shared libraries each loads (counted in
/proc/PID/maps of a process that has done the same start-up), and the machine's load
(/proc/loadavg) before and after. A plain `python3 -c pass` is timed too, as the floor of the
import row: the interpreter's own start-up, which no change to Obscura removes.
"""

import argparse
import os
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--repeat", type=int, default=20)
    args = parser.parse_args()
    env = dict(os.environ, PYTHONPATH=os.path.join(args.build, "python"))
    cli = os.path.join(args.build, "obscura")
    scratch = tempfile.mkdtemp(prefix="obscura-startup-")
    tiny = [cli, "render", "--width", "8", "--height", "8", "--spp", "1", "--quiet", "-o"]
    cases = {
        "obscura --version": [cli, "--version"],
        "obscura render 8x8 -o .png": tiny + [os.path.join(scratch, "tiny.png")],
        "obscura render 8x8 -o .pfm": tiny + [os.path.join(scratch, "tiny.pfm")],
        "python3 -c 'import obscura'": [sys.executable, "-c", "import obscura"],
        "python3 -c pass (floor)": [sys.executable, "-c", "pass"],
    }
    print("load before:", open("/proc/loadavg").read().strip())
    samples = {name: [] for name in cases}
    for _ in range(args.repeat):
        for name, command in cases.items():
            samples[name].append(run_once(command, env))
    print("load after: ", open("/proc/loadavg").read().strip())
    maps_probe = "import sys; sys.stdout.write(open('/proc/self/maps').read())"
    libraries = {
        "python3 -c 'import obscura'": loaded_libraries(
            [sys.executable, "-c", "import obscura; " + maps_probe], env),
        "python3 -c pass (floor)": loaded_libraries([sys.executable, "-c", maps_probe], env),
    }
    ldd = subprocess.run(["ldd", cases["obscura --version"][0]], capture_output=True, text=True)
    libraries["obscura --version"] = len(ldd.stdout.splitlines())
    libraries["obscura render 8x8 -o .png"] = libraries["obscura render 8x8 -o .pfm"] = 0
    print(f"{'command':32} {'wall ms median (min–max)':>26} {'peak RSS MiB median (min–max)':>31}"
          f" {'shared libs':>11}")
    for name, runs in samples.items():
        walls = [1000 * w for w, _ in runs]
        rss = [r for _, r in runs]
        print(f"{name:32} {statistics.median(walls):9.1f} ({min(walls):6.1f}–{max(walls):6.1f})"
              f"   {statistics.median(rss):12.1f} ({min(rss):6.1f}–{max(rss):6.1f})"
              f"   {libraries[name] or '':>11}")
    for name in os.listdir(scratch):
        os.remove(os.path.join(scratch, name))
    os.rmdir(scratch)


if __name__ == "__main__":
    main()
