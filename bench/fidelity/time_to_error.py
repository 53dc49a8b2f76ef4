#!/usr/bin/env python3
"""Time to equal error: Obscura's path tracer and Blender Cycles on textured glTF sample models.

The scenes are the fidelity suite's (gltf_fidelity.py): one model, materials reduced to Lambert,
a uniform white environment, the stored camera, 128 x 128, both renderers converging to the same
image, the stored 4096-spp Cycles reference. For every sample count the two renderers run
alternately (so both see the same machine load) and each run's render time and RMSE against the
reference are recorded: Cycles' time is its render call (Blender's start-up and the glTF import
excluded; scene sync and BVH build included), Obscura's the render loop from the CLI's summary
(loading and BVH build excluded; they take milliseconds on these models). The RMSE of an
unbiased estimator falls as 1/sqrt(time), so k = RMSE * sqrt(time) is constant per renderer; the
ratio of the times both need for one error is (k_obscura / k_cycles)^2.

  bench/fidelity/time_to_error.py [--models DamagedHelmet,CesiumMilkTruck] [--spp "64 256"]
                                  [--threads 2] [--repeats 1] [--build build] [--out DIR]
"""
import argparse, json, math, os, re, statistics, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gltf_fidelity as fid  # noqa: E402


def cycles_run(model, out, name, spp, seed, camera, threads):
    script = os.path.join(fid.SHARED, "tools", "peers", "cycles", "gltf_cycles.py")
    cmd = ["blender", "-b", "--factory-startup", "--python",
           os.path.join(fid.HERE, "linear_textures.py"), "--python", script, "--", "--model",
           model, "--out", out, "--name", name, "--spp", str(spp), "--seed", str(seed),
           "--threads", str(threads), "--max-bounces", "64", "--fov", "40", "--size",
           str(fid.SIZE), "--diffuse", "--camera", camera]
    log = fid.run(cmd)
    seconds = float(re.search(r"render_s=([0-9.]+)", log).group(1))
    rgba = os.path.join(out, name + ".exr")
    opaque = os.path.join(out, name + ".rgb.exr")
    fid.run(["oiiotool", rgba, "--pattern", "constant:color=1,1,1,1",
             "%dx%d" % (fid.SIZE, fid.SIZE), "4", "--over", "--ch", "R,G,B", "-o", opaque])
    return seconds, opaque


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
        k = {"cycles": [], "obscura": []}
        for rep in range(a.repeats):
            for spp in [int(s) for s in a.spp.split()]:
                seed = 10 + rep
                seconds, image = cycles_run(model, out, "%s-c%d-%d" % (name, spp, rep), spp,
                                            seed, camera, a.threads)
                error = fid.rmse(binary, image, ref)
                k["cycles"].append(error * math.sqrt(seconds))
                print("%-16s cycles  %5d spp %7.2f s  rmse %.5f" % (name, spp, seconds, error),
                      flush=True)
                image = os.path.join(out, "%s-o%d-%d.exr" % (name, spp, rep))
                seconds = obscura_run(binary, scene, image, spp, seed, a.threads)
                error = fid.rmse(binary, image, ref)
                k["obscura"].append(error * math.sqrt(seconds))
                print("%-16s obscura %5d spp %7.2f s  rmse %.5f" % (name, spp, seconds, error),
                      flush=True)
        ratio = (statistics.median(k["obscura"]) / statistics.median(k["cycles"])) ** 2
        summary.append((name, ratio))
        print("%-16s Obscura's time to Cycles' error: %.2fx Cycles' time" % (name, ratio),
              flush=True)
    print("load at end %s" % open("/proc/loadavg").read().split()[:3])
    json.dump(dict(summary), open(os.path.join(out, "summary.json"), "w"), indent=1)


if __name__ == "__main__":
    main()
