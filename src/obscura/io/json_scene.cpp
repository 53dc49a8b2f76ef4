#include "obscura/io/json_scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <map>
#include <numbers>

#include "obscura/camera/frames.h"
#include "obscura/color/blackbody_spectrum.h"
#include "obscura/io/camera_mapping.h"
#include "obscura/io/gltf_animation.h"
#include "obscura/io/json_reader.h"
#include "obscura/io/model_file.h"
#include "obscura/io/texture_loader.h"
#include "obscura/math/error.h"
#include "obscura/scene/shapes.h"

namespace obscura {

namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180;

Point3f point(Vector3d v) {
  return {float(v.x), float(v.y), float(v.z)};
}

class JsonSceneReader {
 public:
  explicit JsonSceneReader(std::string path)
      : path_(std::move(path)), directory_(std::filesystem::path(path_).parent_path()) {}

  Scene read(const nlohmann::ordered_json& document) {
    JsonReader root(document, path_, "$");
    scene_.name = root.string("name", std::filesystem::path(path_).stem().string());
    if (root.has("render")) read_render(root.object("render"));
    if (root.has("materials")) read_materials(root.object("materials"));
    for (JsonReader& object : root.objects("objects")) read_object(object);
    for (JsonReader& light : root.objects("lights")) read_light(light);
    if (root.has("environment")) read_environment(root.object("environment"));
    for (JsonReader& camera : root.objects("cameras"))
      scene_.cameras.push_back(camera_from_json(camera));
    std::string active = root.string("camera", "");
    root.string("description", "");  // free text for people
    root.finish();
    finish_cameras(scene_, active, path_ + ": $.camera");
    return std::move(scene_);
  }

 private:
  std::string resolve(const std::string& relative) const {
    std::filesystem::path p(relative);
    return (p.is_absolute() ? p : directory_ / p).lexically_normal().string();
  }

  void read_render(JsonReader json) {
    if (json.has("width")) scene_.render.width = json.integer("width", 0, 1, 1 << 16);
    if (json.has("height")) scene_.render.height = json.integer("height", 0, 1, 1 << 16);
    if (json.has("spp"))
      scene_.render.samples_per_pixel = json.integer("spp", 0, 1, kMaxSamplesPerPixel);
    if (json.has("seed")) scene_.render.seed = uint64_t(json.integer("seed", 0, 0, 1 << 30));
    if (json.has("spectral")) scene_.render.spectral = json.boolean("spectral", false);
    if (json.has("glare")) scene_.render.glare_strength = json.number_in("glare", 1, 0, 1000);
    if (json.has("glare_radius"))
      scene_.render.glare_radius_px = json.integer("glare_radius", 256, 1, 4096);
    if (json.has("flare")) scene_.render.flare = json.boolean("flare", false);
    if (json.has("reyes")) read_reyes(json.object("reyes"));
    json.finish();
  }

  // REYES's knobs, in the ranges the renderer takes (scene/reyes_knobs.h).
  void read_reyes(JsonReader json) {
    namespace k = reyes_knobs;
    SceneReyesSettings& r = scene_.render.reyes;
    if (json.has("shading_rate"))
      r.shading_rate = json.number_in("shading_rate", k::kDefaultShadingRate, k::kMinShadingRate,
                                      k::kMaxShadingRate);
    if (json.has("grid_size"))
      r.grid_size = json.integer("grid_size", k::kDefaultGridSize, 1, k::kMaxGridSize);
    if (json.has("bucket_size"))
      r.bucket_size = json.integer("bucket_size", k::kDefaultBucketSize, 1, k::kMaxBucketSize);
    if (json.has("pixel_samples"))
      r.pixel_samples =
          json.integer("pixel_samples", k::kDefaultPixelSamples, 1, k::kMaxPixelSamples);
    if (json.has("eye_splits"))
      r.eye_splits = json.integer("eye_splits", k::kDefaultEyeSplits, 0, k::kMaxEyeSplits);
    json.finish();
  }

  TextureRef texture(JsonReader& json, const std::string& key, TextureEncoding encoding) {
    if (!json.has(key)) return {};
    std::string file = resolve(json.string(key));
    auto found = textures_.find({file, encoding});
    if (found != textures_.end()) return {found->second, 0};
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
      json.fail(key, "texture '" + file + "' does not exist");
    Texture t = read_texture(file, encoding, &scene_.warnings);
    scene_.input_files.push_back(file);
    auto index = int32_t(scene_.textures.size());
    scene_.textures.push_back(std::move(t));
    textures_[{file, encoding}] = index;
    return {index, 0};
  }

  void read_materials(JsonReader json) {
    // A map from name to material; read every key, in the file's order of names.
    for (const std::string& name : json.keys()) {
      JsonReader m = json.object(name);
      material_index_[name] = uint32_t(scene_.materials.size());
      scene_.materials.push_back(read_material(m, name));
    }
    json.finish();
  }

  Material read_material(JsonReader& json, const std::string& name) {
    Material m;
    m.name = name;
    std::string type = json.string("type");
    if (type == "diffuse") {
      DiffuseMaterial d;
      d.reflectance = json.rgb("reflectance", d.reflectance, 1);
      d.reflectance_texture = texture(json, "reflectance_texture", TextureEncoding::kSrgb);
      m.model = d;
    } else if (type == "phong") {
      PhongMaterial p;
      p.ambient = json.rgb("ambient", p.ambient, 1);
      p.diffuse = json.rgb("diffuse", p.diffuse, 1);
      p.specular = json.rgb("specular", p.specular, 1);
      p.shininess = float(json.number_in("shininess", 0, 0, 1e6));
      p.diffuse_texture = texture(json, "diffuse_texture", TextureEncoding::kSrgb);
      p.blinn = json.boolean("blinn", true);
      m.model = p;
    } else if (type == "conductor") {
      ConductorMaterial c;
      c.eta = json.rgb("eta", c.eta, 100);
      c.k = json.rgb("k", c.k, 100);
      c.roughness = float(json.number_in("roughness", 0, 0, 1));
      m.model = c;
    } else if (type == "dielectric") {
      DielectricMaterial d;
      d.ior = float(json.number_in("ior", 1.5, 1e-3, 10));
      d.roughness = float(json.number_in("roughness", 0, 0, 1));
      d.transmittance = json.rgb("transmittance", d.transmittance, 1);
      d.abbe_number = float(json.number_in("abbe_number", 0, 0, 1000));
      if (d.abbe_number > 0 && d.abbe_number < 1)
        json.fail("abbe_number",
                  "an Abbe number is 0 (no dispersion) or at least 1 (glasses: "
                  "about 17–95); got " +
                      json.at("abbe_number").dump());
      m.model = d;
    } else if (type == "metallic-roughness") {
      MetallicRoughnessMaterial mr;
      mr.base_color = json.rgb("base_color", mr.base_color, 1);
      mr.base_color_texture = texture(json, "base_color_texture", TextureEncoding::kSrgb);
      mr.metallic = float(json.number_in("metallic", 1, 0, 1));
      mr.roughness = float(json.number_in("roughness", 1, 0, 1));
      mr.metallic_roughness_texture =
          texture(json, "metallic_roughness_texture", TextureEncoding::kLinear);
      mr.specular = float(json.number_in("specular", 1, 0, 1));
      mr.specular_color = json.rgb("specular_color", mr.specular_color, 1e3);
      mr.ior = float(json.number_in("ior", 1.5, 1, 10));
      m.model = mr;
    } else if (type == "emissive") {
      m.model = EmissiveMaterial{};
    } else {
      json.fail("type", "unknown material type '" + type +
                            "'; expected diffuse, phong, conductor, dielectric, "
                            "metallic-roughness or emissive");
    }
    const float strength = float(json.number_in("emission_strength", 1, 0, 1e9));
    if (json.has("emission_kelvin")) {
      // A blackbody: its colour for RGB mode, its spectrum for spectral mode.
      if (json.has("emission"))
        json.fail("emission_kelvin", "give either an emission colour or a blackbody temperature");
      m.emission_kelvin = float(json.number_in("emission_kelvin", 6504, 500, 1e6));
      m.emission = BlackbodySpectrum(m.emission_kelvin).working_rgb() * strength;
    } else {
      m.emission = json.rgb("emission", Rgb()) * strength;
    }
    m.emission_texture = texture(json, "emission_texture", TextureEncoding::kSrgb);
    m.normal_texture = texture(json, "normal_texture", TextureEncoding::kLinear);
    m.double_sided = json.boolean("double_sided", true);
    // Displacement (REYES): metres along the normal, times a scalar texture's first channel.
    m.displacement = float(json.number_in("displacement", 0, -1e6, 1e6));
    m.displacement_texture = texture(json, "displacement_texture", TextureEncoding::kLinear);
    if (json.has("displacement_bound"))
      m.displacement_bound = float(json.number_in("displacement_bound", 0, 0, 1e6));
    json.finish();
    return m;
  }

  uint32_t material(JsonReader& json, const std::string& key) {
    std::string name = json.string(key);
    auto found = material_index_.find(name);
    if (found == material_index_.end())
      json.fail(key, "no material named '" + name + "' in $.materials");
    return found->second;
  }

  // {"translate": [x,y,z], "rotate_degrees": [x,y,z], "scale": s | [x,y,z]} applied as
  // T · Rz · Ry · Rx · S, or {"matrix": 16 numbers, row-major}.
  Transform transform(JsonReader json) {
    if (json.has("matrix")) {
      std::vector<double> v = json.numbers("matrix", 16);
      Matrix4 m;
      for (int i = 0; i < 16; ++i) m.m[i / 4][i % 4] = v[i];
      json.finish();
      std::optional<Matrix4> inv = inverse(m);
      if (!inv) json.fail("matrix", "the matrix is singular");
      return Transform(m, *inv);
    }
    Vector3d t = json.vector3("translate", {0, 0, 0});
    Vector3d r = json.vector3("rotate_degrees", {0, 0, 0}) * kRadiansPerDegree;
    Vector3d s(1, 1, 1);
    if (json.has("scale")) {
      if (json.at("scale").is_number()) {
        double k = json.number("scale");
        s = {k, k, k};
      } else {
        s = json.vector3("scale");
      }
      if (s.x == 0 || s.y == 0 || s.z == 0) json.fail("scale", "scale must not be zero");
    }
    json.finish();
    return Transform::translate(t) * Transform::rotate_z(r.z) * Transform::rotate_y(r.y) *
           Transform::rotate_x(r.x) * Transform::scale(s.x, s.y, s.z);
  }

  // Edge lengths that must be positive and finite (as floats), `count` of them.
  std::vector<double> sizes(JsonReader& json, const std::string& key, size_t count) {
    if (!json.has(key)) return std::vector<double>(count, 1.0);
    std::vector<double> v = json.numbers(key, count);
    for (double x : v)
      if (!(x > 0 && x <= 1e9))
        json.fail(key, "sizes must be positive and at most 1e9; got " + json.at(key).dump());
    return v;
  }

  // The index of the one unit mesh of a kind, made on first use.
  uint32_t unit_mesh(const std::string& key, const std::function<Mesh()>& make) {
    auto found = unit_meshes_.find(key);
    if (found != unit_meshes_.end()) return found->second;
    auto index = uint32_t(scene_.meshes.size());
    scene_.meshes.push_back(make());
    unit_meshes_[key] = index;
    return index;
  }

  // A generated shape as one shared unit mesh and the scale that gives it the object's size: a
  // scene of 200,000 spheres holds one sphere mesh and 200,000 instances, not 200,000 meshes.
  struct Shape {
    uint32_t mesh = 0;
    Transform object_from_unit;
  };

  Shape shape(JsonReader& json, const std::string& kind) {
    if (kind == "sphere") {
      double r = json.number_in("radius", 1, 1e-6, 1e9);
      int segments = json.integer("segments", 64, 3, 4096);
      return {
          unit_mesh("sphere/" + std::to_string(segments), [&] { return make_sphere(1, segments); }),
          Transform::scale(r, r, r)};
    }
    if (kind == "analytic_sphere") {
      // Kept as a unit sphere placed by its centre and radius: REYES dices the sphere itself,
      // the tracer and the rasterizer draw its tessellation into `segments`.
      const Vector3d center = json.vector3("center", {0, 0, 0});
      if (!(std::abs(center.x) <= 1e9 && std::abs(center.y) <= 1e9 && std::abs(center.z) <= 1e9))
        json.fail("center", "expected coordinates within ±1e9; got " + json.at("center").dump());
      const double r = json.number_in("radius", 1, 1e-6, 1e9);
      const int segments = json.integer("segments", 64, 3, 4096);
      return {unit_mesh("analytic_sphere/" + std::to_string(segments),
                        [&] { return make_analytic_sphere(1, segments); }),
              Transform::translate(center) * Transform::scale(r, r, r)};
    }
    if (kind == "rectangle") {
      std::vector<double> size = sizes(json, "size", 2);
      return {unit_mesh("rectangle", [] { return make_rectangle(1, 1); }),
              Transform::scale(size[0], 1, size[1])};
    }
    if (kind == "box") {
      std::vector<double> size = sizes(json, "size", 3);
      return {unit_mesh("box",
                        [] {
                          return make_box({1, 1, 1});
                        }),
              Transform::scale(size[0], size[1], size[2])};
    }
    if (kind == "mesh") {
      scene_.meshes.push_back(triangle_mesh(json));
      return {uint32_t(scene_.meshes.size() - 1), Transform()};
    }
    json.fail("shape", "unknown shape '" + kind +
                           "'; expected sphere, analytic_sphere, rectangle, box or mesh");
  }

  Mesh triangle_mesh(JsonReader& json) {
    Mesh m;
    m.name = "mesh";
    const nlohmann::ordered_json& p = json.at("positions");
    const nlohmann::ordered_json& i = json.at("indices");
    if (!p.is_array() || p.size() % 3 != 0 ||
        !std::all_of(p.begin(), p.end(), [](auto& v) { return v.is_number(); }))
      json.fail("positions", "expected a flat array of numbers, three per vertex");
    if (!i.is_array() || i.size() % 3 != 0 ||
        !std::all_of(i.begin(), i.end(), [](auto& v) { return v.is_number_unsigned(); }))
      json.fail("indices", "expected a flat array of non-negative integers, three per triangle");
    for (size_t k = 0; k < p.size(); k += 3) {
      Point3f position(p[k].get<float>(), p[k + 1].get<float>(), p[k + 2].get<float>());
      // 1e39 is a JSON number, but no float: it would become Inf.
      if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z))
        json.fail("positions", "vertex " + std::to_string(k / 3) +
                                   " is not finite as a 32-bit float (|x| < 3.4e38)");
      m.positions.push_back(position);
    }
    for (const nlohmann::ordered_json& v : i) {
      uint64_t index = v.get<uint64_t>();
      if (index >= m.positions.size())
        json.fail("indices", "index " + std::to_string(index) + " is past the vertex count " +
                                 std::to_string(m.positions.size()));
      m.indices.push_back(uint32_t(index));
    }
    return m;
  }

  std::vector<TransformKey> motion(JsonReader& json) {
    std::vector<TransformKey> keys;
    for (JsonReader& key : json.objects("motion")) {
      double time = key.number("time");
      if (!keys.empty() && time <= keys.back().time_seconds)
        key.fail("time", "motion keys must be in increasing time order");
      keys.push_back({time, transform(key.object("transform"))});
      key.finish();
    }
    return keys;
  }

  void read_object(JsonReader& json) {
    std::string name = json.string("name", "");
    Transform world_from_object =
        json.has("transform") ? transform(json.object("transform")) : Transform();
    std::vector<TransformKey> keys = motion(json);
    if (!keys.empty()) world_from_object = keys.front().world_from_object;
    if (json.has("model") == json.has("shape"))
      throw Error(path_ + ": " + json.path(),
                  "an object needs exactly one of \"model\" or \"shape\"");
    if (json.has("shape")) {
      auto meshes_before = scene_.meshes.size();
      Shape s = shape(json, json.string("shape"));
      Instance instance;
      instance.mesh = s.mesh;
      // Shared meshes take their material from the instance.
      instance.material = int32_t(material(json, "material"));
      if (scene_.meshes.size() > meshes_before)  // a new mesh: its first user's material
        scene_.meshes[s.mesh].material = uint32_t(instance.material);
      instance.name = name.empty() ? scene_.meshes[s.mesh].name : name;
      instance.world_from_object = world_from_object * s.object_from_unit;
      for (const TransformKey& key : keys)
        instance.motion.push_back({key.time_seconds, key.world_from_object * s.object_from_unit});
      scene_.instances.push_back(std::move(instance));
      json.finish();
      return;
    }
    std::string file = resolve(json.string("model"));
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
      json.fail("model", "model file '" + file + "' does not exist");
    std::string up = json.string("up", "y");
    if (up != "y" && up != "z") json.fail("up", "expected \"y\" or \"z\"");
    std::optional<uint32_t> override_material;
    if (json.has("material")) override_material = material(json, "material");
    json.finish();
    Scene model = load_model_file(file);
    // A Z-up model turns so that its +Z becomes the world's +Y.
    Transform up_fix = y_up_from(up == "z" ? UpAxis::z : UpAxis::y);
    merge(std::move(model), world_from_object * up_fix, keys, up_fix, name, override_material);
  }

  void merge(Scene model, const Transform& world_from_model, const std::vector<TransformKey>& keys,
             const Transform& up_fix, const std::string& name,
             std::optional<uint32_t> override_material) {
    auto mesh_base = uint32_t(scene_.meshes.size());
    auto material_base = uint32_t(scene_.materials.size());
    auto texture_base = int32_t(scene_.textures.size());
    auto shift = [&](TextureRef& r) {
      if (r.valid()) r.texture += texture_base;
    };
    for (Material& m : model.materials) {
      shift(m.emission_texture);
      shift(m.normal_texture);
      shift(m.displacement_texture);
      std::visit(
          [&](auto& v) {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, DiffuseMaterial>) shift(v.reflectance_texture);
            if constexpr (std::is_same_v<T, PhongMaterial>) shift(v.diffuse_texture);
            if constexpr (std::is_same_v<T, MetallicRoughnessMaterial>) {
              shift(v.base_color_texture);
              shift(v.metallic_roughness_texture);
              shift(v.occlusion_texture);
              for (TextureRef* r :
                   {&v.transmission_texture, &v.clearcoat_texture, &v.clearcoat_roughness_texture,
                    &v.clearcoat_normal_texture, &v.sheen_color_texture, &v.sheen_roughness_texture,
                    &v.specular_texture, &v.specular_color_texture})
                shift(*r);
            }
          },
          m.model);
      scene_.materials.push_back(std::move(m));
    }
    for (Texture& t : model.textures) scene_.textures.push_back(std::move(t));
    for (std::string& f : model.input_files) scene_.input_files.push_back(std::move(f));
    for (Mesh& m : model.meshes) {
      m.material += material_base;
      scene_.meshes.push_back(std::move(m));
    }
    for (Instance& instance : model.instances) {
      instance.mesh += mesh_base;
      if (override_material)
        instance.material = int32_t(*override_material);
      else if (instance.material >= 0)
        instance.material += int32_t(material_base);
      if (!name.empty()) instance.name = name + "/" + instance.name;
      Transform model_from_object = instance.world_from_object;
      instance.world_from_object = world_from_model * model_from_object;
      for (const TransformKey& key : keys)
        instance.motion.push_back(
            {key.time_seconds, key.world_from_object * up_fix * model_from_object});
      scene_.instances.push_back(std::move(instance));
    }
    for (Light& light : model.lights) scene_.lights.push_back(transformed(light, world_from_model));
    for (Camera& camera : model.cameras) {
      // Cameras follow the model's placement, without its scale.
      std::vector<AnimatedTransform::Key> keys = camera.world_from_camera.keys();
      for (AnimatedTransform::Key& key : keys)
        key.transform = without_scale((world_from_model * key.transform).matrix());
      camera.world_from_camera = AnimatedTransform(keys);
      scene_.cameras.push_back(std::move(camera));
    }
    for (std::string& w : model.warnings) scene_.warnings.push_back(std::move(w));
  }

  static Light transformed(Light light, const Transform& t) {
    std::visit(
        [&](auto& l) {
          using T = std::decay_t<decltype(l)>;
          if constexpr (!std::is_same_v<T, DirectionalLight>) l.position = t(l.position);
          if constexpr (!std::is_same_v<T, PointLight>) l.direction = normalize(t(l.direction));
        },
        light.model);
    return light;
  }

  // Light in the scene's one convention (docs/scene-format.md, "Light units"): photometric,
  // as glTF's KHR_lights_punctual — point and spot intensity in candela, directional light in
  // lux — so that the film holds luminance in cd/m² and the physical exposure's calibration
  // applies. Each quantity may instead be given in another unit, converted here: a point or spot
  // light's luminous power in lumens (I = Φ / 4π, as KHR_lights_punctual converts, a spot too),
  // or radiometric watts through the luminous efficacy `efficacy_lm_w` (683 lm/W, light at
  // 555 nm, unless the light's spectrum says otherwise). One key per quantity.
  static double efficacy(JsonReader& json) {
    return json.number_in("efficacy_lm_w", 683, 1e-6, 683);
  }

  static double one_of(JsonReader& json, std::initializer_list<const char*> keys) {
    const char* given = nullptr;
    for (const char* key : keys)
      if (json.has(key)) {
        if (given)
          json.fail(key, std::string("give the light's strength once: '") + given + "' is given");
        given = key;
      }
    return given ? json.number_in(given, 1, 0, 1e12) : 1;
  }

  static double punctual_intensity_cd(JsonReader& json) {
    const double v =
        one_of(json, {"intensity", "intensity_cd", "power_lm", "intensity_w_sr", "power_w"});
    constexpr double kFourPi = 4 * std::numbers::pi;
    if (json.has("power_lm")) return v / kFourPi;
    if (json.has("intensity_w_sr")) return v * efficacy(json);
    if (json.has("power_w")) return v * efficacy(json) / kFourPi;
    return v;
  }

  static double illuminance_lux(JsonReader& json) {
    const double v = one_of(json, {"irradiance", "illuminance_lux", "irradiance_w_m2"});
    if (json.has("irradiance_w_m2")) return v * efficacy(json);
    return v;
  }

  void read_light(JsonReader& json) {
    Light light;
    light.name = json.string("name", "light " + std::to_string(scene_.lights.size()));
    std::string type = json.string("type");
    Rgb color = json.rgb("color", Rgb(1.f));
    if (type == "point") {
      light.model =
          PointLight{point(json.vector3("position")), color * float(punctual_intensity_cd(json))};
    } else if (type == "spot") {
      Vector3d position = json.vector3("position");
      Vector3d target = json.vector3("target");
      if (length(target - position) == 0)
        json.fail("target", "the spot light's target equals its position");
      double inner = json.number_in("inner_cone_degrees", 0, 0, 90);
      double outer = json.number_in("outer_cone_degrees", 45, inner, 90);
      light.model = SpotLight{point(position), Vector3f(normalize(target - position)),
                              color * float(punctual_intensity_cd(json)),
                              float(inner * kRadiansPerDegree), float(outer * kRadiansPerDegree)};
    } else if (type == "directional") {
      Vector3d direction = json.vector3("direction");
      if (length(direction) == 0) json.fail("direction", "the direction must not be zero");
      light.model =
          DirectionalLight{Vector3f(normalize(direction)), color * float(illuminance_lux(json))};
    } else {
      json.fail("type", "unknown light type '" + type + "'; expected point, spot or directional");
    }
    json.finish();
    scene_.lights.push_back(std::move(light));
  }

  void read_environment(JsonReader json) {
    Environment env;
    if (json.has("file")) {
      std::string file = resolve(json.string("file"));
      std::error_code ec;
      if (!std::filesystem::is_regular_file(file, ec))
        json.fail("file", "environment map '" + file + "' does not exist");
      env.texture = int32_t(scene_.textures.size());
      Texture t = read_texture(file, TextureEncoding::kLinear, &scene_.warnings);
      scene_.input_files.push_back(file);
      t.wrap_v = TextureWrap::kClampToEdge;
      scene_.textures.push_back(std::move(t));
    }
    env.color = json.rgb("color", Rgb(1.f));
    env.intensity = float(json.number_in("intensity", 1, 0, 1e12));
    double rotation = json.number("rotate_y_degrees", 0);
    env.world_from_environment = Transform::rotate_y(rotation * kRadiansPerDegree);
    json.finish();
    scene_.environment = env;
  }

  std::string path_;
  std::filesystem::path directory_;
  Scene scene_;
  std::map<std::string, uint32_t> material_index_;
  std::map<std::pair<std::string, TextureEncoding>, int32_t> textures_;
  std::map<std::string, uint32_t> unit_meshes_;  // generated shapes' shared meshes, by kind
};

}  // namespace

Scene load_json_scene(const std::string& path) {
  return JsonSceneReader(path).read(parse_json_file(path));
}

Scene load_json_scene_text(const std::string& text, const std::string& path) {
  return JsonSceneReader(path).read(parse_json_text(text, path));
}

}  // namespace obscura
