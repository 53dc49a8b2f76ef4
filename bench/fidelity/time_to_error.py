#!/usr/bin/env python3
"""Time to equal error: Obscura's path tracer and Blender Cycles on textured glTF sample models.

The scenes are the fidelity suite's (gltf_fidelity.py): one model, materials reduced to Lambert,
a uniform white environment, the stored camera, 128 x 128, both renderers converging to the same
image, the stored 4096-spp Cycles reference. For every sample count the two renderers run
alternately (so both see the same machine load) and each run's render time and RMSE against the
reference are recorded: Cycles' time is its render call (Blender's start-up and the glTF import
excluded; scene sync and BVH build included), Obscura's the render loop from the CLI's summary
(loading and BVH build excluded; they take milliseconds on these models).

Each renderer's time is fitted as t = fixed + cost * spp (least squares over the sample counts;
Cycles' fixed part is its scene sync and BVH build) and its error as RMSE = c / sqrt(spp), with
the reference's own noise (Cycles' 256-spp RMSE / 4 at 4096 spp) taken out of each RMSE in
quadrature. Printed per model: the cost of a sample and the error at equal samples, Obscura's
over Cycles', and their product (c_o^2 cost_o) / (c_c^2 cost_c): Obscura's time over Cycles' to
reach any one error once fixed costs are paid (what long renders see).

  bench/fidelity/time_to_error.py [--models DamagedHelmet,CesiumMilkTruck] [--spp "64 256"]
                                  [--threads 2] [--repeats 1] [--build build] [--out DIR]
"""
import argparse, json, math, os, re, statistics, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gltf_fidelity as fid  # noqa: E402


def cycles_run(model, out, name, spp, seed, camera, threads):
    image, log = fid.cycles(model, out, name, spp, seed, camera, threads=threads, depth="float")
    return float(re.search(r"render_s=([0-9.]+)", log).group(1)), image


def obscura_run(binary, scene, out, spp, seed, threads):
    cmd = [binary, "render", scene, "--environment", "white", "--width", str(fid.SIZE),
           "--height", str(fid.SIZE), "--renderer", "path", "--spp", str(spp), "--seed",
           str(seed), "--threads", str(threads), "--filter", "box", "--filter-radius", "0.5",
           "-o", out]
    log = fid.run(cmd)
    return float(re.search(r" in ([0-9.]+)s", log).group(1))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--build", default=os.path.join(fid.ROOT, "build"))
    p.add_argument("--models", default="DamagedHelmet,CesiumMilkTruck")
    p.add_argument("--spp", default="64 256")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--repeats", type=int, default=1)
    p.add_argument("--out", default="")
    a = p.parse_args()
    binary = os.path.join(a.build, "obscura")
    out = os.path.abspath(a.out or tempfile.mkdtemp(prefix="time-to-error."))
    os.makedirs(out, exist_ok=True)
    print("date %s, %d cores, load at start %s, threads %d" % (
        time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), os.cpu_count(),
        open("/proc/loadavg").read().split()[:3], a.threads), flush=True)
    summary = []
    for name in a.models.split(","):
        model = os.path.join(fid.SHARED, "assets", "gltf", fid.MODELS[name])
        camera = os.path.join(fid.REFS, name + ".camera.json")
        ref = os.path.join(fid.REFS, name + ".exr")
        scene = os.path.join(out, name + ".json")
        fid.obscura_scene(fid.lambert_copy(model, out, name), camera, scene)
        runs = {"cycles": [], "obscura": []}  # (spp, seconds, rmse)
        for rep in range(a.repeats):
            for spp in [int(s) for s in a.spp.split()]:
                seed = 10 + rep
                seconds, image = cycles_run(model, out, "%s-c%d-%d" % (name, spp, rep), spp,
                                            seed, camera, a.threads)
                error = fid.rmse(binary, image, ref)
                runs["cycles"].append((spp, seconds, error))
                print("%-16s cycles  %5d spp %7.2f s  rmse %.5f" % (name, spp, seconds, error),
                      flush=True)
                image = os.path.join(out, "%s-o%d-%d.exr" % (name, spp, rep))
                seconds = obscura_run(binary, scene, image, spp, seed, a.threads)
                error = fid.rmse(binary, image, ref)
                runs["obscura"].append((spp, seconds, error))
                print("%-16s obscura %5d spp %7.2f s  rmse %.5f" % (name, spp, seconds, error),
                      flush=True)
        cycles_256 = json.load(open(os.path.join(fid.REFS, name + ".cycles.json")))["cycles_rmse"]
        reference_noise = cycles_256 / 4  # 4096 spp
        fit = {}
        for renderer, rows in runs.items():
            n = len(rows)
            mean_s = sum(r[0] for r in rows) / n
            mean_t = sum(r[1] for r in rows) / n
            cost = sum((r[0] - mean_s) * (r[1] - mean_t) for r in rows) / \
                sum((r[0] - mean_s) ** 2 for r in rows)
            # Render times are reported to 0.1 s: too few samples can leave no slope to fit.
            if cost <= 0:
                sys.exit("%s: %s's time does not grow with spp; use larger sample counts" % (
                    name, renderer))
            fixed = max(mean_t - cost * mean_s, 0.0)
            c = statistics.median(
                math.sqrt(max(r[2] ** 2 - reference_noise ** 2, 0.0) * r[0]) for r in rows)
            fit[renderer] = (fixed, cost, c)
            print("%-16s %-7s fixed %.2f s + %.2f ms/spp; RMSE %.5f / sqrt(spp/256)" % (
                name, renderer, fixed, cost * 1e3, c / 16), flush=True)
        (_, co, eo), (_, cc, ec) = fit["obscura"], fit["cycles"]
        summary.append((name, co / cc, eo / ec, (eo ** 2 * co) / (ec ** 2 * cc)))
        print("%-16s Obscura / Cycles: time per sample %.2fx, error at equal samples %.2fx, "
              "time to equal error %.2fx" % summary[-1], flush=True)
    print("load at end %s" % open("/proc/loadavg").read().split()[:3])
    json.dump({n: {"time_per_sample": t, "error_at_equal_samples": e, "time_to_equal_error": r}
               for n, t, e, r in summary},
              open(os.path.join(out, "summary.json"), "w"), indent=1)


if __name__ == "__main__":
    main()
