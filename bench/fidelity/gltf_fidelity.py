#!/usr/bin/env python3
"""glTF fidelity suite: Obscura's two renderers next to Blender Cycles on the Khronos sample models.

Every model is lit only by a uniform white environment (radiance 1) and seen through one fixed
pinhole camera per model (a three-quarter view framing its bounds, chosen once by the Cycles
script and stored in references/NAME.camera.json). Materials are reduced to Lambert in both
renderers ("-lambert": base colour x texture x COLOR_0, alpha and emission kept; metallic,
roughness, specular and normal maps dropped), because Blender 3.4's Principled BSDF is not the glTF
BRDF; what remains isolates the features (textures, transforms, vertex colours, alpha, emission,
instancing, node transforms) from that difference.

  bench/fidelity/gltf_fidelity.py                     # compare with the stored references
  bench/fidelity/gltf_fidelity.py --references        # (re)make them with Blender (slow)
  bench/fidelity/gltf_fidelity.py --models Duck,Box   # some models only

A reference is Cycles at REF_SPP samples per pixel (seed 1); Cycles' own noise is the RMSE of a
256-spp Cycles render (seed 2) against it, stored with the reference. The table printed (and
written to OUT/table.md) gives, per model, Obscura's path tracer RMSE at 256 spp and the
rasterizer's RMSE against the reference, and the tracer's ratio to Cycles' noise.
Needs: the build's `obscura`, `oiiotool` (openimageio-tools); for --references Debian's `blender`
and `python3-numpy` (the Cycles script imports it).
"""
import argparse, json, os, shutil, struct, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SHARED = os.environ.get("SHARED", os.path.join(ROOT, "..", "shared"))
REFS = os.path.join(ROOT, "data", "reference", "gltf")
SIZE = 128

# name -> model path relative to shared/assets/gltf
MODELS = {
    "Box": "Box/Box.glb",
    "BoxInterleaved": "BoxInterleaved/BoxInterleaved.glb",
    "BoxTextured": "BoxTextured/BoxTextured.glb",
    "BoxVertexColors": "BoxVertexColors/BoxVertexColors.glb",
    "Duck": "Duck/Duck.glb",
    "Avocado": "Avocado/glTF/Avocado.gltf",
    "Suzanne": "Suzanne/glTF/Suzanne.gltf",
    "OrientationTest": "OrientationTest/OrientationTest.glb",
    "TextureCoordinateTest": "TextureCoordinateTest/TextureCoordinateTest.glb",
    "TextureTransformTest": "TextureTransformTest/glTF/TextureTransformTest.gltf",
    "TextureSettingsTest": "TextureSettingsTest/TextureSettingsTest.glb",
    "NegativeScaleTest": "NegativeScaleTest/NegativeScaleTest.glb",
    "AlphaBlendModeTest": "AlphaBlendModeTest/AlphaBlendModeTest.glb",
    "SimpleInstancing": "SimpleInstancing/SimpleInstancing.glb",
    "EmissiveStrengthTest": "EmissiveStrengthTest/EmissiveStrengthTest.glb",
    "TwoSidedPlane": "TwoSidedPlane/glTF/TwoSidedPlane.gltf",
    "CesiumMilkTruck": "CesiumMilkTruck/CesiumMilkTruck.glb",
    "DamagedHelmet": "DamagedHelmet/DamagedHelmet.glb",
    "WaterBottle": "WaterBottle/glTF/WaterBottle.gltf",
}


def run(cmd, **kw):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)
    if r.returncode != 0:
        sys.exit("failed (%d): %s\n%s" % (r.returncode, " ".join(cmd), r.stdout[-3000:]))
    return r.stdout


# --- the "-lambert" copy of a glTF file for Obscura -------------------------------------------

def read_gltf(path):
    data = open(path, "rb").read()
    if data[:4] == b"glTF":
        n = struct.unpack("<I", data[12:16])[0]
        doc = json.loads(data[20:20 + n])
        rest = data[20 + n:]
        return doc, rest
    return json.loads(data), None


def write_gltf(path, doc, rest):
    text = json.dumps(doc).encode()
    if rest is None:
        open(path, "wb").write(text)
        return
    text += b" " * ((4 - len(text) % 4) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + rest
    open(path, "wb").write(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)


def lambert_copy(model, out_dir, name):
    """Metallic 0, roughness 1, KHR_materials_specular factor 0 (purely diffuse in Obscura), no
    metallic-roughness or normal texture; primitives without a material get glTF's default
    material made diffuse. A .gltf is copied with its folder (its buffers and images are
    relative to it); returns the copy's path."""
    doc, rest = read_gltf(model)
    if rest is None:
        folder = os.path.join(out_dir, name + "-model")
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(os.path.dirname(os.path.abspath(model)), folder)
        out_path = os.path.join(folder, name + "-lambert.gltf")
    else:
        out_path = os.path.join(out_dir, name + "-lambert.glb")
    mats = doc.setdefault("materials", [])
    default = None
    for mesh in doc.get("meshes", []):
        for prim in mesh.get("primitives", []):
            if "material" not in prim:
                if default is None:
                    mats.append({"name": "gltf-default"})
                    default = len(mats) - 1
                prim["material"] = default
    for m in mats:
        pbr = m.setdefault("pbrMetallicRoughness", {})
        pbr["metallicFactor"] = 0.0
        pbr["roughnessFactor"] = 1.0
        pbr.pop("metallicRoughnessTexture", None)
        m.pop("normalTexture", None)
        ext = m.setdefault("extensions", {})
        for name in ("KHR_materials_clearcoat", "KHR_materials_sheen", "KHR_materials_transmission",
                     "KHR_materials_volume"):
            ext.pop(name, None)
        ext["KHR_materials_specular"] = {"specularFactor": 0.0}
    used = doc.setdefault("extensionsUsed", [])
    if "KHR_materials_specular" not in used:
        used.append("KHR_materials_specular")
    write_gltf(out_path, doc, rest)
    return out_path


# --- renders ---------------------------------------------------------------------------------

def cycles(model, out, name, spp, seed, camera, write_camera=False, threads=2, depth="half",
           environment_map=""):
    """Cycles' render composited over the background, as NAME.rgb.exr (`depth`: half or float);
    returns its path and Blender's log. With `environment_map` (an equirectangular image) the
    world is that map, as Obscura's `--environment FILE` orients it, and the background is
    rendered, not composited."""
    script = os.path.join(SHARED, "tools", "peers", "cycles", "gltf_cycles.py")
    # linear_textures.py: Cycles filters colour textures in linear light, as Obscura does.
    cmd = ["blender", "-b", "--factory-startup", "--python",
           os.path.join(HERE, "linear_textures.py")]
    env = None
    if environment_map:
        cmd += ["--python", os.path.join(HERE, "environment_map.py")]
        env = dict(os.environ, OBSCURA_FIDELITY_ENVMAP=environment_map)
    cmd += ["--python", script, "--", "--model", model,
           "--out", out, "--name", name, "--spp", str(spp), "--seed", str(seed), "--threads",
           str(threads), "--max-bounces", "64", "--fov", "40", "--size", str(SIZE), "--diffuse"]
    cmd += (["--write-camera", camera] if write_camera else ["--camera", camera])
    log = run(cmd, env=env)
    # Transparent film: composite over the background radiance 1, keep RGB, store as half.
    rgba = os.path.join(out, name + ".exr")
    opaque = os.path.join(out, name + ".rgb.exr")
    # --nosoftwareattrib and the two attributes: no command line (with this machine's paths)
    # is written into a file the project keeps.
    run(["oiiotool", "--nosoftwareattrib", rgba, "--pattern", "constant:color=1,1,1,1",
         "%dx%d" % (SIZE, SIZE), "4", "--over", "--ch", "R,G,B", "--sattrib", "Software",
         "Blender Cycles; composited over radiance 1 by oiiotool", "--sattrib",
         "Exif:ImageHistory", "", "-d", depth, "--compression", "zip", "-o", opaque])
    return opaque, log


def obscura_scene(model_copy, camera_json, path):
    cam = json.load(open(camera_json))
    scene = {"objects": [{"model": model_copy}],
             "cameras": [{"name": "fidelity", "position": cam["eye"], "target": cam["target"],
                          "up": cam["up"], "fov_degrees": cam["vfov_deg"]}],
             "camera": "fidelity"}
    json.dump(scene, open(path, "w"), indent=1)


def obscura(binary, scene, out, renderer, spp):
    cmd = [binary, "render", scene, "-q", "--environment", "white", "--width", str(SIZE),
           "--height", str(SIZE), "--renderer", renderer, "-o", out]
    if renderer != "raster":
        # Cycles' settings: a 1-pixel box pixel filter.
        cmd += ["--spp", str(spp), "--seed", "3", "--filter", "box", "--filter-radius", "0.5"]
    else:
        cmd += ["--msaa", "4"]
    return run(cmd)


def rmse(binary, a, b):
    return json.loads(run([binary, "image", "diff", "--json", a, b]))["rmse"]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--models", default="", help="comma-separated names (default: all)")
    p.add_argument("--references", action="store_true", help="make the Cycles references")
    p.add_argument("--ref-spp", type=int, default=4096)
    p.add_argument("--spp", type=int, default=256)
    p.add_argument("--out", default="")
    a = p.parse_args()
    binary = os.path.join(a.build, "obscura")
    out = os.path.abspath(a.out or tempfile.mkdtemp(prefix="gltf-fidelity."))
    os.makedirs(out, exist_ok=True)
    names = a.models.split(",") if a.models else list(MODELS)
    rows = []
    for name in names:
        model = os.path.join(SHARED, "assets", "gltf", MODELS[name])
        camera = os.path.join(REFS, name + ".camera.json")
        ref = os.path.join(REFS, name + ".exr")
        noise_file = os.path.join(REFS, name + ".cycles.json")
        if a.references:
            os.makedirs(REFS, exist_ok=True)
            r, _ = cycles(model, out, name + "-ref", a.ref_spp, 1, camera, write_camera=True)
            shutil.copyfile(r, ref)
            c, _ = cycles(model, out, name + "-cycles", a.spp, 2, camera)
            json.dump({"reference_spp": a.ref_spp, "spp": a.spp,
                       "cycles_rmse": rmse(binary, c, ref)}, open(noise_file, "w"), indent=1)
        copy = lambert_copy(model, out, name)
        scene = os.path.join(out, name + ".json")
        obscura_scene(copy, camera, scene)
        traced = os.path.join(out, name + "-path.exr")
        rastered = os.path.join(out, name + "-raster.exr")
        obscura(binary, scene, traced, "path", a.spp)
        obscura(binary, scene, rastered, "raster", a.spp)
        noise = json.load(open(noise_file))["cycles_rmse"]
        t, r = rmse(binary, traced, ref), rmse(binary, rastered, ref)
        rows.append((name, noise, t, t / noise if noise > 0 else float("inf"), r))
        print("%-22s cycles %.4f  path %.4f (%.2fx)  raster %.4f" % rows[-1], flush=True)
    table = ["| model | Cycles %d spp RMSE | Obscura path %d spp RMSE | ratio | Obscura raster RMSE |"
             % (a.spp, a.spp), "|---|---|---|---|---|"]
    table += ["| %s | %.4f | %.4f | %.2f | %.4f |" % row for row in rows]
    open(os.path.join(out, "table.md"), "w").write("\n".join(table) + "\n")
    print("\n".join(table))
    print("renders in", out)


if __name__ == "__main__":
    main()
