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

The same fit is made of each run's CPU time (user + system of the whole process, from
getrusage): its slope is a sample's CPU cost, with start-up, loading and scene sync left in the
fixed part. On a machine other work shares, wall time grows with the load while CPU time
mostly does not, so the CPU ratio is printed beside the wall ratio, and the load average at
start and end.

--environment MAP lights the scenes with an equirectangular map (an .hdr or .exr file) instead
of the uniform white world, in both renderers in the same orientation (environment_map.py says
how). Its references (Cycles at 4096 spp, seed 1) are made on first use and kept under --cache
(default: $XDG_CACHE_HOME/obscura/time-to-error, else ~/.cache/...); the reference's own noise is
then estimated from the Cycles runs themselves (c_cycles / sqrt(4096)).

  bench/fidelity/time_to_error.py [--models DamagedHelmet,CesiumMilkTruck] [--spp "64 256"]
                                  [--threads 2] [--repeats 1] [--build build] [--out DIR]
                                  [--environment MAP.hdr] [--cache DIR]
"""
import argparse, json, math, os, re, resource, statistics, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gltf_fidelity as fid  # noqa: E402


REFERENCE_SPP = 4096


def children_cpu_s():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def cycles_run(model, out, name, spp, seed, camera, threads, envmap):
    """Cycles' render time (s), the CPU time of its processes (s) and its image."""
    cpu = children_cpu_s()
    image, log = fid.cycles(model, out, name, spp, seed, camera, threads=threads, depth="float",
                            environment_map=envmap)
    return float(re.search(r"render_s=([0-9.]+)", log).group(1)), children_cpu_s() - cpu, image


def obscura_run(binary, scene, out, spp, seed, threads, envmap):
    """Obscura's render time (s) and the CPU time of its process (s)."""
    cmd = [binary, "render", scene, "--environment", envmap or "white", "--width", str(fid.SIZE),
           "--height", str(fid.SIZE), "--renderer", "path", "--spp", str(spp), "--seed",
           str(seed), "--threads", str(threads), "--filter", "box", "--filter-radius", "0.5",
           "-o", out]
    cpu = children_cpu_s()
    log = fid.run(cmd)
    return float(re.search(r" in ([0-9.]+)s", log).group(1)), children_cpu_s() - cpu


def environment_reference(binary, model, name, camera, envmap, cache):
    """The 4096-spp Cycles reference of `name` under `envmap`, made once and kept in `cache`."""
    stem = os.path.splitext(os.path.basename(envmap))[0]
    path = os.path.join(cache, "%s-%s-%d.exr" % (name, stem, REFERENCE_SPP))
    if not os.path.exists(path):
        os.makedirs(cache, exist_ok=True)
        print("%-16s making the %d-spp Cycles reference under %s" % (name, REFERENCE_SPP, stem),
              flush=True)
        image, _ = fid.cycles(model, cache, "%s-%s-ref" % (name, stem), REFERENCE_SPP, 1, camera,
                              threads=os.cpu_count(), depth="float", environment_map=envmap)
        os.replace(image, path)
    return path


def fit_line(points):
    """Least-squares (intercept, slope) of y over x for [(x, y)]."""
    n = len(points)
    mean_x = sum(p[0] for p in points) / n
    mean_y = sum(p[1] for p in points) / n
    slope = sum((p[0] - mean_x) * (p[1] - mean_y) for p in points) / \
        sum((p[0] - mean_x) ** 2 for p in points)
    return mean_y - slope * mean_x, slope


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--build", default=os.path.join(fid.ROOT, "build"))
    p.add_argument("--models", default="DamagedHelmet,CesiumMilkTruck")
    p.add_argument("--spp", default="64 256")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--repeats", type=int, default=1)
    p.add_argument("--out", default="")
    p.add_argument("--environment", default="", help="an equirectangular map (default: white)")
    p.add_argument("--cache", default=os.path.join(
        os.environ.get("XDG_CACHE_HOME", os.path.expanduser("~/.cache")), "obscura",
        "time-to-error"), help="where references under --environment are kept")
    a = p.parse_args()
    envmap = os.path.abspath(a.environment) if a.environment else ""
    if envmap and not os.path.isfile(envmap):
        sys.exit("--environment: %s is not a file" % a.environment)
    binary = os.path.join(a.build, "obscura")
    out = os.path.abspath(a.out or tempfile.mkdtemp(prefix="time-to-error."))
    os.makedirs(out, exist_ok=True)
    print("date %s, %d cores, load at start %s, threads %d, environment %s" % (
        time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), os.cpu_count(),
        open("/proc/loadavg").read().split()[:3], a.threads,
        os.path.basename(envmap) if envmap else "white"), flush=True)
    summary = []
    for name in a.models.split(","):
        model = os.path.join(fid.SHARED, "assets", "gltf", fid.MODELS[name])
        camera = os.path.join(fid.REFS, name + ".camera.json")
        ref = os.path.join(fid.REFS, name + ".exr")
        if envmap:
            ref = environment_reference(binary, model, name, camera, envmap, a.cache)
        scene = os.path.join(out, name + ".json")
        fid.obscura_scene(fid.lambert_copy(model, out, name), camera, scene)
        runs = {"cycles": [], "obscura": []}  # (spp, seconds, rmse, cpu seconds)
        for rep in range(a.repeats):
            for spp in [int(s) for s in a.spp.split()]:
                seed = 10 + rep
                seconds, cpu, image = cycles_run(model, out, "%s-c%d-%d" % (name, spp, rep),
                                                 spp, seed, camera, a.threads, envmap)
                error = fid.rmse(binary, image, ref)
                runs["cycles"].append((spp, seconds, error, cpu))
                print("%-16s cycles  %5d spp %7.2f s (CPU %7.2f s)  rmse %.5f" % (
                    name, spp, seconds, cpu, error), flush=True)
                image = os.path.join(out, "%s-o%d-%d.exr" % (name, spp, rep))
                seconds, cpu = obscura_run(binary, scene, image, spp, seed, a.threads, envmap)
                error = fid.rmse(binary, image, ref)
                runs["obscura"].append((spp, seconds, error, cpu))
                print("%-16s obscura %5d spp %7.2f s (CPU %7.2f s)  rmse %.5f" % (
                    name, spp, seconds, cpu, error), flush=True)
        if envmap:
            # Cycles' runs: RMSE^2 = c^2 (1/spp + 1/4096) with the reference's noise included.
            c_cycles = statistics.median(
                r[2] / math.sqrt(1 / r[0] + 1 / REFERENCE_SPP) for r in runs["cycles"])
            reference_noise = c_cycles / math.sqrt(REFERENCE_SPP)
        else:
            cycles_256 = json.load(open(os.path.join(fid.REFS, name + ".cycles.json")))[
                "cycles_rmse"]
            reference_noise = cycles_256 / 4  # 4096 spp
        fit = {}
        for renderer, rows in runs.items():
            fixed, cost = fit_line([(r[0], r[1]) for r in rows])
            cpu_fixed, cpu_cost = fit_line([(r[0], r[3]) for r in rows])
            # Render times are reported to 0.1 s: too few samples can leave no slope to fit.
            if cost <= 0 or cpu_cost <= 0:
                sys.exit("%s: %s's time does not grow with spp; use larger sample counts" % (
                    name, renderer))
            c = statistics.median(
                math.sqrt(max(r[2] ** 2 - reference_noise ** 2, 0.0) * r[0]) for r in rows)
            fit[renderer] = (cost, c, cpu_cost)
            print("%-16s %-7s fixed %.2f s + %.2f ms/spp; CPU %.2f s + %.2f ms/spp; "
                  "RMSE %.5f / sqrt(spp/256)" % (name, renderer, max(fixed, 0.0), cost * 1e3,
                                                 cpu_fixed, cpu_cost * 1e3, c / 16), flush=True)
        (co, eo, uo), (cc, ec, uc) = fit["obscura"], fit["cycles"]
        summary.append((name, co / cc, eo / ec, (eo ** 2 * co) / (ec ** 2 * cc), uo / uc,
                        (eo ** 2 * uo) / (ec ** 2 * uc)))
        print("%-16s Obscura / Cycles: time per sample %.2fx, error at equal samples %.2fx, "
              "time to equal error %.2fx; CPU time per sample %.2fx, CPU time to equal error "
              "%.2fx" % summary[-1], flush=True)
    print("load at end %s" % open("/proc/loadavg").read().split()[:3])
    json.dump({n: {"time_per_sample": t, "error_at_equal_samples": e, "time_to_equal_error": r,
                   "cpu_time_per_sample": ut, "cpu_time_to_equal_error": ur}
               for n, t, e, r, ut, ur in summary},
              open(os.path.join(out, "summary.json"), "w"), indent=1)


if __name__ == "__main__":
    main()
