// Scenes: loading a file or a built-in scene (io/scene_loader.h), and building one from numpy
// arrays — meshes, materials, lights and an environment (scene/*.h, the authoring model both
// renderers compile).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstring>

#include "arrays.h"
#include "bindings.h"
#include "obscura/camera/shutter.h"
#include "obscura/io/default_environment.h"
#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "obscura/render/camera_request.h"
#include "obscura/scene/material_variants.h"
#include "obscura/scene/scene.h"
#include "session.h"

namespace obscura::python {

namespace {

using Vec3 = std::array<double, 3>;

Rgb rgb(const Vec3& v) {
  return {float(v[0]), float(v[1]), float(v[2])};
}

std::vector<uint32_t> checked_indices(const py::handle& value, size_t vertex_count) {
  if (!py::isinstance<py::array>(value))
    throw py::type_error("add_mesh(indices): expected a numpy integer array of shape (M, 3)");
  py::array a = py::reinterpret_borrow<py::array>(value);
  if (a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
    throw py::type_error("add_mesh(indices): expected an integer dtype, got " +
                         std::string(py::str(a.dtype())));
  if (!(a.ndim() == 2 && a.shape(1) == 3) && !(a.ndim() == 1 && a.shape(0) % 3 == 0))
    throw py::value_error("add_mesh(indices): expected shape (M, 3) or (3M,)");
  py::array_t<int64_t, py::array::c_style | py::array::forcecast> as64(a);
  std::vector<uint32_t> indices(size_t(as64.size()));
  const int64_t* p = as64.data();
  for (size_t i = 0; i < indices.size(); ++i) {
    if (p[i] < 0 || uint64_t(p[i]) >= vertex_count)
      throw py::value_error("add_mesh(indices): index " + std::to_string(p[i]) + " at position " +
                            std::to_string(i) + " is outside [0, " + std::to_string(vertex_count) +
                            ")");
    indices[i] = uint32_t(p[i]);
  }
  return indices;
}

template <typename T, int N>
std::vector<T> attribute(const py::handle& value, const char* what, size_t count) {
  py::array a = checked_points(value, what, N);
  if (size_t(a.shape(0)) != count)
    throw py::value_error(std::string(what) + ": expected " + std::to_string(count) +
                          " rows, one per position, got " + std::to_string(a.shape(0)));
  std::vector<double> v = as_doubles(a);
  std::vector<T> out(count);
  for (size_t i = 0; i < count; ++i) {
    const double* row = &v[i * N];
    if constexpr (N == 3)
      out[i] = T{float(row[0]), float(row[1]), float(row[2])};
    else
      out[i] = T{float(row[0]), float(row[1])};
  }
  return out;
}

Transform transform_from(const py::handle& value) {
  return Transform(array_to_matrix(value, "transform"));
}

uint32_t add_material(Scene& scene, const std::string& kind, const Vec3& color,
                      const Vec3& emission, double roughness, double metallic, double ior,
                      const std::string& name) {
  Material material;
  material.name = name;
  material.emission = rgb(emission);
  if (kind == "diffuse") {
    DiffuseMaterial m;
    m.reflectance = rgb(color);
    material.model = m;
  } else if (kind == "metallic-roughness") {
    MetallicRoughnessMaterial m;
    m.base_color = rgb(color);
    m.metallic = float(metallic);
    m.roughness = float(roughness);
    m.ior = float(ior);
    material.model = m;
  } else if (kind == "conductor") {
    ConductorMaterial m;
    m.roughness = float(roughness);
    material.model = m;
  } else if (kind == "dielectric") {
    DielectricMaterial m;
    m.ior = float(ior);
    m.roughness = float(roughness);
    m.transmittance = rgb(color);
    material.model = m;
  } else if (kind == "emissive") {
    material.model = EmissiveMaterial{};
  } else {
    throw py::value_error(
        "add_material(kind): expected 'diffuse', 'metallic-roughness', "
        "'conductor', 'dielectric' or 'emissive', got '" +
        kind + "'");
  }
  scene.materials.push_back(std::move(material));
  return uint32_t(scene.materials.size() - 1);
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<Scene> scene(m, "Scene",
                          "A scene: meshes placed by instances, materials, lights, an "
                          "environment and cameras. Load one with load_scene() or build one: "
                          "Scene(), then add_material, add_mesh, add_*_light, set_environment.");
  scene.def(py::init<>(), "An empty scene with the default camera.");
  scene.def_readwrite("name", &Scene::name);
  scene.def_readwrite("camera", &Scene::camera,
                      "The camera to render with (a copy; assign a "
                      "Camera to change it).");
  scene.def_readonly("cameras", &Scene::cameras, "Every camera the file names, in file order.");
  scene.def_readonly("warnings", &Scene::warnings,
                     "What the loader skipped or approximated, for the user.");
  scene.def_readonly("material_variants", &Scene::material_variants);
  scene.def(
      "camera_named",
      [](const Scene& s, const std::string& name) {
        for (const Camera& c : s.cameras)
          if (c.name == name) return c;
        throw Error("camera", "the scene has no camera named '" + name + "'");
      },
      py::arg("name"), "The scene's camera called `name` (raises obscura.Error when none is).");
  scene.def(
      "stats",
      [](const Scene& s) {
        SceneStats st = s.stats();
        py::dict d;
        d["triangles"] = st.triangles;
        d["vertices"] = st.vertices;
        d["meshes"] = st.meshes;
        d["instances"] = st.instances;
        d["materials"] = st.materials;
        d["textures"] = st.textures;
        d["lights"] = st.lights;
        d["emissive_meshes"] = st.emissive_meshes;
        d["cameras"] = st.cameras;
        return d;
      },
      "Counts as `obscura info` prints them.");
  scene.def(
      "bounds",
      [](const Scene& s) {
        Bounds3f b = s.bounds();
        return py::make_tuple(Vec3{b.min.x, b.min.y, b.min.z}, Vec3{b.max.x, b.max.y, b.max.z});
      },
      "World-space bounds ((min x, y, z), (max x, y, z)) of every instance at time 0.");
  scene.def("validate", &Scene::validate,
            "Raises obscura.Error naming the first invalid mesh, index, reference or value.");
  scene.def(
      "select_variant", [](Scene& s, const std::string& name) { select_material_variant(s, name); },
      py::arg("name"), "Selects a glTF material variant (KHR_materials_variants) by name.");

  scene.def("add_material", &add_material, py::arg("kind") = "diffuse",
            py::arg("color") = Vec3{0.8, 0.8, 0.8}, py::arg("emission") = Vec3{0, 0, 0},
            py::arg("roughness") = 0.5, py::arg("metallic") = 0.0, py::arg("ior") = 1.5,
            py::arg("name") = "",
            "Adds a material and returns its index: 'diffuse' (Lambert, `color` = albedo), "
            "'metallic-roughness' (glTF's PBR model: base colour, metallic, roughness, ior), "
            "'conductor' (gold-like metal of `roughness`), 'dielectric' (glass of `ior`, "
            "`color` = transmittance) or 'emissive'. `emission` (linear radiance) makes any of "
            "them an area light.");

  scene.def(
      "add_mesh",
      [](Scene& s, const py::handle& positions, const py::handle& indices,
         const py::handle& normals, const py::handle& uvs, uint32_t material,
         const py::handle& transform, const std::string& name) {
        Mesh mesh;
        mesh.name = name;
        py::array p = checked_points(positions, "add_mesh(positions)", 3);
        mesh.positions = attribute<Point3f, 3>(p, "add_mesh(positions)", size_t(p.shape(0)));
        mesh.indices = checked_indices(indices, mesh.positions.size());
        if (!normals.is_none())
          mesh.normals =
              attribute<Normal3f, 3>(normals, "add_mesh(normals)", mesh.positions.size());
        if (!uvs.is_none())
          mesh.uvs = attribute<Point2f, 2>(uvs, "add_mesh(uvs)", mesh.positions.size());
        if (material >= s.materials.size())
          throw py::value_error("add_mesh(material): index " + std::to_string(material) +
                                " but the scene has " + std::to_string(s.materials.size()) +
                                " materials (add_material first)");
        mesh.material = material;
        return s.add_mesh(std::move(mesh),
                          transform.is_none() ? Transform() : transform_from(transform));
      },
      py::arg("positions"), py::arg("indices"), py::arg("normals") = py::none(),
      py::arg("uvs") = py::none(), py::arg("material") = 0, py::arg("transform") = py::none(),
      py::arg("name") = "",
      "Adds a triangle mesh with one instance and returns the mesh index: positions (N, 3) "
      "float, indices (M, 3) integers, optional unit normals (N, 3) and uvs (N, 2), a material "
      "index and a 4x4 world_from_object transform. The mesh index is what the 'id' AOV "
      "reports.");

  scene.def(
      "add_point_light",
      [](Scene& s, Vec3 position, Vec3 intensity, const std::string& name) {
        s.lights.push_back({name, PointLight{.position = {float(position[0]), float(position[1]),
                                                          float(position[2])},
                                             .intensity = rgb(intensity)}});
      },
      py::arg("position"), py::arg("intensity") = Vec3{1, 1, 1}, py::arg("name") = "",
      "Adds a point light of radiant intensity `intensity` (W/sr, RGB).");
  scene.def(
      "add_spot_light",
      [](Scene& s, Vec3 position, Vec3 direction, Vec3 intensity, double inner, double outer,
         const std::string& name) {
        SpotLight l;
        l.position = {float(position[0]), float(position[1]), float(position[2])};
        l.direction =
            normalize(Vector3f{float(direction[0]), float(direction[1]), float(direction[2])});
        l.intensity = rgb(intensity);
        l.inner_cone_radians = float(inner);
        l.outer_cone_radians = float(outer);
        s.lights.push_back({name, l});
      },
      py::arg("position"), py::arg("direction"), py::arg("intensity") = Vec3{1, 1, 1},
      py::arg("inner_cone") = 0.0, py::arg("outer_cone") = 0.7853981633974483, py::arg("name") = "",
      "Adds a spot light at `position` pointing along `direction` (cone angles in radians).");
  scene.def(
      "add_directional_light",
      [](Scene& s, Vec3 direction, Vec3 irradiance, const std::string& name) {
        DirectionalLight l;
        l.direction =
            normalize(Vector3f{float(direction[0]), float(direction[1]), float(direction[2])});
        l.irradiance = rgb(irradiance);
        s.lights.push_back({name, l});
      },
      py::arg("direction"), py::arg("irradiance") = Vec3{1, 1, 1}, py::arg("name") = "",
      "Adds a distant light travelling along `direction` with `irradiance` (W/m^2, RGB).");
  scene.def(
      "set_environment",
      [](Scene& s, Vec3 color, double intensity, std::optional<std::string> file) {
        if (file) {
          apply_environment(
              s,
              {.source = EnvironmentSource::kFile, .file = *file, .intensity = float(intensity)});
          return;
        }
        Environment environment;
        environment.color = rgb(color);
        environment.intensity = float(intensity);
        s.environment = environment;
      },
      py::arg("color") = Vec3{1, 1, 1}, py::arg("intensity") = 1.0, py::arg("file") = py::none(),
      "Light from far away: a uniform `color`, or an equirectangular radiance map `file` "
      "(EXR, HDR, ...), times `intensity`.");
  scene.def("__repr__", [](const Scene& s) {
    SceneStats st = s.stats();
    return "<obscura.Scene '" + s.name + "' " + std::to_string(st.triangles) + " triangles, " +
           std::to_string(st.lights) + " lights>";
  });

  m.def(
      "builtin_scenes",
      [] {
        std::vector<std::pair<std::string, std::string>> out;
        for (const BuiltinScene& b : builtin_scenes()) out.emplace_back(b.name, b.description);
        return out;
      },
      "The built-in scenes as (name, description), the default first (`obscura render "
      "--scene-list`).");

  m.def(
      "load_scene",
      [](const std::string& name_or_path, const std::string& environment,
         double environment_intensity, const std::string& gltf_scene,
         const std::string& gltf_animation, std::optional<double> time, const std::string& variant,
         std::optional<std::string> shutter_text) {
        py::gil_scoped_release release;
        // As `obscura render` loads it: skins and morphs posed across the shutter (`shutter`, as
        // --shutter, else the default one), moved to be centred on `time` when one is given.
        const Shutter shutter = pose_shutter(time, shutter_text);
        GltfLoadOptions gltf{.scene = gltf_scene,
                             .animation = gltf_animation,
                             .time_s = shutter.time_at(0.5),
                             .exposure_s = shutter.duration_s()};
        Scene s = load_scene(name_or_path, gltf);
        if (!variant.empty()) select_material_variant(s, variant);
        EnvironmentChoice choice = parse_environment_choice(environment);
        choice.intensity = float(environment_intensity);
        apply_environment(s, choice);
        // The camera `obscura render` renders the file with: its film from the scene file's
        // render.width/height (render/camera_request.h).
        s.camera = resolve_camera(s, CameraRequest{}, std::nullopt, std::nullopt, &s.warnings);
        if (time) {
          s.camera.shutter.open_s = shutter.open_s;
          s.camera.shutter.close_s = shutter.close_s;
        }
        s.validate();
        return s;
      },
      py::arg("name_or_path") = "", py::arg("environment") = "auto",
      py::arg("environment_intensity") = 1.0, py::arg("gltf_scene") = "",
      py::arg("gltf_animation") = "", py::arg("time") = py::none(), py::arg("variant") = "",
      py::arg("shutter") = py::none(),
      "Loads a built-in scene by name (builtin_scenes(); empty: the default Cornell box) or a "
      "scene file: Obscura JSON, glTF (.gltf/.glb), OBJ, PLY, STL or any format Assimp reads. "
      "`environment` as `obscura render --environment`: 'auto' (the studio environment when "
      "the scene has no light of its own), 'none', 'studio', 'white' or a map file. Raises "
      "obscura.Error naming the file and what was wrong.");
}

}  // namespace obscura::python
