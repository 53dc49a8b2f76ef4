#!/usr/bin/env python3
"""Python overhead (issue 16's benchmark): what `import obscura` adds over the CLI and the C++
paths. Run from the repository root after building:

    PYTHONPATH=build/python python3 bench/python_overhead.py [--cli build/obscura] [--repeat 5]

1. A 1-spp 512x512 path-traced Cornell box: the CLI's own render time (its summary line, the
   renderer alone) and wall time of the process, against render() in Python (RenderResult.seconds,
   the same library timer, and the wall time of the call including the numpy hand-over).
2. Vectorized Camera.project of 10^6 points against the same pinhole formula in NumPy, and
   project / unproject throughput of every camera model.
3. Colour of a 3840x2160 float32 image: convert() srgb-linear -> display-p3 (the per-colour
   library functions, threaded; color_bench's BM_ConvertLin709ToP3_F32 is the same work in C++)
   and develop() to Display P3 8-bit (the table path the C++
   color_bench measures; build/bench/color_bench runs too when it was built).
Prints CPU and wall times and the machine's load (/proc/loadavg) so that runs can be compared.
"""

import argparse
import os
import re
import resource
import statistics
import subprocess
import tempfile
import time

import numpy as np

import obscura


def cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def timed(call, repeat):
    walls, cpus, value = [], [], None
    for _ in range(repeat):
        c0, w0 = cpu_seconds(), time.perf_counter()
        value = call()
        walls.append(time.perf_counter() - w0)
        cpus.append(cpu_seconds() - c0)
    return statistics.median(walls), statistics.median(cpus), value


def loadavg():
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


def cli_render(cli, repeat):
    renders, walls, cpus = [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(repeat):
            w0 = time.perf_counter()
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            out = subprocess.run([cli, "render", "cornell-box", "--spp", "1", "--width", "512",
                                  "--height", "512", "-o", os.path.join(tmp, "a.exr")],
                                 capture_output=True, text=True, check=True)
            walls.append(time.perf_counter() - w0)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpus.append(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
            match = re.search(r"rendered .* in ([0-9.]+) ?(ms|s)\b", out.stderr)
            if match:
                renders.append(float(match.group(1)) / (1000 if match.group(2) == "ms" else 1))
    return (statistics.median(renders) if renders else float("nan"), statistics.median(walls),
            statistics.median(cpus))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default="build/obscura")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    print(f"load before: {loadavg()}  (cores: {os.cpu_count()})")

    # 1. render overhead
    cli_seconds, cli_wall, cli_cpu = cli_render(args.cli, args.repeat)
    scene = obscura.load_scene("cornell-box")
    camera = scene.camera
    camera.width, camera.height = 512, 512
    obscura.render(scene, camera, spp=1)  # warm-up: first-touch of the process's pools
    render_seconds = []

    def one_render():
        result = obscura.render(scene, camera, spp=1)
        render_seconds.append(result.seconds)
        return result

    py_wall, py_cpu, _ = timed(one_render, args.repeat)
    py_render = statistics.median(render_seconds)
    print("1-spp 512x512 Cornell box, path tracer (medians of %d)" % args.repeat)
    print(f"  CLI: render {cli_seconds * 1e3:8.1f} ms   process wall {cli_wall * 1e3:8.1f} ms"
          f"   CPU {cli_cpu * 1e3:8.1f} ms")
    print(f"  Python render(): renderer {py_render * 1e3:8.1f} ms   call wall {py_wall * 1e3:8.1f} ms"
          f"   CPU {py_cpu * 1e3:8.1f} ms")
    print(f"  overhead of the call over its own render: {100 * (py_wall / py_render - 1):+.1f} %;"
          f" over the CLI's render time: {100 * (py_wall / cli_seconds - 1):+.1f} %")

    # 2. projection throughput
    rng = np.random.default_rng(0)
    points = rng.uniform([-3, -2, -12], [3, 2, -1], size=(1_000_000, 3))
    cam = obscura.Camera.perspective(fov=55, width=640, height=480)
    cam.project(points)  # warm-up: TBB's workers and the first touch of the output pages
    wall, cpu, _ = timed(lambda: cam.project(points), args.repeat)
    f = 240 / np.tan(np.radians(27.5))

    def numpy_pinhole():
        z = -points[:, 2]
        return np.stack([320 + f * points[:, 0] / z, 240 - f * points[:, 1] / z], axis=1)

    nwall, ncpu, _ = timed(numpy_pinhole, args.repeat)
    print("Camera.project, 10^6 points")
    print(f"  obscura: {len(points) / wall / 1e6:6.1f} M points/s (wall {wall * 1e3:.1f} ms, "
          f"CPU {cpu * 1e3:.1f} ms)")
    print(f"  NumPy pinhole: {len(points) / nwall / 1e6:6.1f} M points/s (wall {nwall * 1e3:.1f} "
          f"ms, CPU {ncpu * 1e3:.1f} ms)")
    k = np.array([[500, 0, 320], [0, 500, 240], [0, 0, 1.0]])
    models = {
        "orthographic": obscura.Camera.orthographic(view_height=4, width=640, height=480),
        "spherical": obscura.Camera.spherical(width=640, height=320),
        "fisheye": obscura.Camera.fisheye(width=640, height=480),
        "calibrated (OpenCV k1 k2)": obscura.Camera.calibrated(
            k, distortion="opencv", coefficients=[-0.1, 0.01, 0, 0, 0], width=640, height=480),
    }
    for name, model in [("perspective", cam)] + list(models.items()):
        film, depth = model.project(points)
        seen = ~np.isnan(depth)
        film = np.where(seen[:, None], film, 320.0)
        depth = np.where(seen, depth, 1.0)
        pw, _, _ = timed(lambda: model.project(points), args.repeat)
        uw, _, _ = timed(lambda: model.unproject(film, depth), args.repeat)
        print(f"  {name:26s} project {len(points) / pw / 1e6:6.1f}  unproject "
              f"{len(points) / uw / 1e6:6.1f} M points/s")

    # 3. colour of a 4K image
    u = rng.uniform(0, 1, size=(2160, 3840, 3)).astype(np.float32)
    image = np.where(rng.uniform(size=u.shape) < 1 / 16, -0.25 * u, 4 * u * u).astype(np.float32)
    wall, cpu, _ = timed(lambda: obscura.convert(image, "srgb-linear", "display-p3"), args.repeat)
    dwall, dcpu, _ = timed(lambda: obscura.develop(image, display="display-p3"), args.repeat)
    print("3840x2160 float32 RGB")
    print(f"  convert srgb-linear -> display-p3: wall {wall * 1e3:8.1f} ms, CPU {cpu * 1e3:8.1f} ms")
    print(f"  develop to Display P3 8-bit:       wall {dwall * 1e3:8.1f} ms, CPU {dcpu * 1e3:8.1f} ms")
    bench = os.path.join(os.path.dirname(args.cli), "bench", "color_bench")
    if os.path.exists(bench):
        for name in ["BM_ConvertLin709ToP3_F32", "BM_Lin709ToP3_U8"]:
            out = subprocess.run([bench, f"--benchmark_filter={name}/threads:2/"],
                                 capture_output=True, text=True).stdout
            print("  C++ color_bench: " + " ".join(out.strip().splitlines()[-1].split()[:3]))
    print(f"load after: {loadavg()}")


if __name__ == "__main__":
    main()
