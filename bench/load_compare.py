# Time from process start to a built tracer scene, for several obscura binaries side by side:
# runs `BINARY info --bvh [--threads N] FILE` for each binary in turn (alternating, so that the
# machine's load falls on all of them alike), ROUNDS times, and prints the medians of wall time,
# CPU time (user + system, all threads) and peak resident memory (the child's ru_maxrss), with
# the load average before and after. BENCHMARKS.md ("Loading a mesh and building its BVH").
#
#   python3 bench/load_compare.py [--rounds 3] [--threads N] FILE BINARY [BINARY ...]
import argparse
import os
import re
import statistics
import subprocess
import time


def run_once(binary, path, threads):
    command = [binary, "info", "--bvh", path]
    if threads:
        command[2:2] = ["--threads", str(threads)]
    start = time.perf_counter()
    child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    out = child.stdout.read()
    child.stdout.close()
    child.stderr.close()
    if status != 0:
        raise SystemExit(f"{' '.join(command)} failed with status {status}")
    scene_mb = float(re.search(r"memory\s+([0-9.]+) MB in the scene", out).group(1))
    # "Embree holds N MB"; early builds of this option wrote "N MB held by Embree".
    held = re.search(r"Embree holds ([0-9.]+) MB|([0-9.]+) MB held by Embree", out)
    embree_mb = float(held.group(1) or held.group(2))
    before_mb = float(re.search(r"above the ([0-9.]+) MB before loading", out).group(1))
    return {
        "wall_s": wall,
        "cpu_s": usage.ru_utime + usage.ru_stime,
        "peak_mb": usage.ru_maxrss * 1024 / 1e6,
        "baseline_mb": before_mb,
        "scene_mb": scene_mb,
        "embree_mb": embree_mb,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--threads", type=int, default=0, help="0: all cores")
    parser.add_argument("file")
    parser.add_argument("binaries", nargs="+")
    args = parser.parse_args()
    runs = {b: [] for b in args.binaries}
    load_before = os.getloadavg()[0]
    for _ in range(args.rounds):
        for b in args.binaries:
            runs[b].append(run_once(b, args.file, args.threads))
    load_after = os.getloadavg()[0]
    print(f"{args.file}, {args.rounds} rounds, threads {args.threads or 'all'}, "
          f"load average {load_before:.1f} before, {load_after:.1f} after")
    print("| binary | wall s (range) | CPU s (range) | peak RSS MB | above start MB | "
          "scene MB | Embree MB | peak above start / (scene + Embree) |")
    print("|---|---|---|---|---|---|---|---|")
    for b, rs in runs.items():
        def med(key):
            return statistics.median(r[key] for r in rs)

        def rng(key):
            return f"{min(r[key] for r in rs):.2f}–{max(r[key] for r in rs):.2f}"

        above = med("peak_mb") - med("baseline_mb")
        final = med("scene_mb") + med("embree_mb")
        print(f"| {b} | {med('wall_s'):.3f} ({rng('wall_s')}) | {med('cpu_s'):.3f} "
              f"({rng('cpu_s')}) | {med('peak_mb'):.1f} | {above:.1f} | {med('scene_mb'):.1f} | "
              f"{med('embree_mb'):.1f} | {above / final:.2f}× |")


if __name__ == "__main__":
    main()
