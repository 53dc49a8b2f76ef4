#include "obscura/raster/scene_rasterizer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <variant>

#include <tbb/parallel_for.h>

#include "obscura/math/error.h"
#include "obscura/math/safe_index.h"
#include "obscura/raster/depth_range.h"
#include "obscura/raster/msaa.h"
#include "obscura/raster/pipeline.h"
#include "obscura/raster/scene_draws.h"
#include "obscura/raster/scene_program.h"
#include "obscura/scene/tangents.h"
#include "obscura/shading/scene_lighting.h"

namespace obscura::raster {

std::optional<ShadingMode> parse_shading_mode(std::string_view name) {
  if (name == "flat") return ShadingMode::kFlat;
  if (name == "gouraud") return ShadingMode::kGouraud;
  if (name == "phong") return ShadingMode::kPhong;
  if (name == "blinn-phong") return ShadingMode::kBlinnPhong;
  return std::nullopt;
}

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Object-space vertices of a mesh. Meshes without normals get one vertex per corner carrying the
// face normal (what the tracer shades them with), drawn unindexed. Tangents are filled in only
// for a mesh drawn with a normal map (`normal_map_uv_set` ≥ 0): the file's, or generated from
// that UV set (scene/tangents.h).
void compile_mesh(const Mesh& mesh, int normal_map_uv_set, std::vector<MeshVertex>& vertices,
                  std::vector<uint32_t>& indices) {
  std::vector<Vector4f> generated;
  if (normal_map_uv_set >= 0 && mesh.tangents.empty())
    generated = generate_tangents(mesh, uint32_t(normal_map_uv_set));
  const std::vector<Vector4f>& tangents =
      normal_map_uv_set < 0 || mesh.tangents.empty() ? generated : mesh.tangents;
  auto vertex = [&](uint32_t i, Vector3f n) {
    return MeshVertex{mesh.positions[i],
                      n,
                      mesh.uvs.empty() ? Point2f() : mesh.uvs[i],
                      mesh.colors.empty() ? Rgb(1.f) : mesh.colors[i],
                      mesh.color_alphas.empty() ? 1.f : mesh.color_alphas[i],
                      mesh.uvs1.empty() ? Point2f() : mesh.uvs1[i],
                      tangents.empty() ? Vector4f() : tangents[i]};
  };
  if (!mesh.normals.empty()) {
    vertices.reserve(mesh.positions.size());
    for (uint32_t i = 0; i < mesh.positions.size(); ++i)
      vertices.push_back(vertex(i, to_vector(mesh.normals[i])));
    indices = mesh.indices;
    return;
  }
  vertices.reserve(mesh.indices.size());
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t* c = &mesh.indices[t];
    Vector3f n = cross(mesh.positions[c[1]] - mesh.positions[c[0]],
                       mesh.positions[c[2]] - mesh.positions[c[0]]);
    float len = length(n);
    n = len > 0 ? n / len : Vector3f();
    for (int k = 0; k < 3; ++k) vertices.push_back(vertex(c[k], n));
  }
}

// Hands `store` the scene texture's linear RGBA at each texel centre (x, y), rows in parallel.
template <class Store>
void for_each_texel(const obscura::Texture& t, Store&& store) {
  tbb::parallel_for(0, t.height, [&](int y) {
    for (int x = 0; x < t.width; ++x)
      store(x, y, sample_texture(t, {(x + 0.5f) / t.width, (y + 0.5f) / t.height}));
  });
}

// A scene texture decoded to linear RGB, mipmapped.
Texture compile_texture(const obscura::Texture& t) {
  Image image(t.width, t.height, 3);
  for_each_texel(t, [&](int x, int y, Vector4f v) { image.set_rgb(x, y, {v.x, v.y, v.z}); });
  return Texture(image, t.wrap_u, t.wrap_v);
}

void mark_used(const TextureRef& ref, std::vector<bool>& used) {
  if (ref.valid() && size_t(ref.texture) < used.size()) used[ref.texture] = true;
}

// A scene texture's alpha channel as a grey raster texture, or nothing where it is opaque.
std::optional<Texture> compile_alpha_texture(const obscura::Texture& t) {
  Image image(t.width, t.height, 3);
  std::atomic<bool> translucent = false;
  for_each_texel(t, [&](int x, int y, Vector4f v) {
    if (v.w < 1) translucent.store(true, std::memory_order_relaxed);
    image.set_rgb(x, y, Rgb(v.w));
  });
  if (!translucent) return std::nullopt;
  return Texture(image, t.wrap_u, t.wrap_v);
}

// The scene textures whose alpha some material uses: for its coverage (glTF base colour textures
// of materials with alphaMode MASK or BLEND), its specular strength or its sheen roughness.
std::vector<bool> alpha_channel_textures(const Scene& scene) {
  std::vector<bool> used(scene.textures.size(), false);
  for (const Material& m : scene.materials)
    if (const auto* mr = std::get_if<MetallicRoughnessMaterial>(&m.model);
        mr && m.alpha_mode != AlphaMode::kOpaque)
      mark_used(mr->base_color_texture, used);
  // KHR_materials_specular keeps its strength, KHR_materials_sheen its roughness in the alpha
  // channel.
  for (const Material& m : scene.materials)
    if (const auto* mr = std::get_if<MetallicRoughnessMaterial>(&m.model)) {
      mark_used(mr->specular_texture, used);
      if (mr->has_sheen()) mark_used(mr->sheen_roughness_texture, used);
    }
  return used;
}

std::vector<bool> used_textures(const Scene& scene) {
  std::vector<bool> used(scene.textures.size(), false);
  for (const Material& m : scene.materials) {
    mark_used(m.emission_texture, used);
    mark_used(m.normal_texture, used);
    std::visit(
        [&](const auto& model) {
          using T = std::decay_t<decltype(model)>;
          if constexpr (std::is_same_v<T, DiffuseMaterial>)
            mark_used(model.reflectance_texture, used);
          if constexpr (std::is_same_v<T, obscura::PhongMaterial>)
            mark_used(model.diffuse_texture, used);
          if constexpr (std::is_same_v<T, MetallicRoughnessMaterial>) {
            mark_used(model.base_color_texture, used);
            mark_used(model.metallic_roughness_texture, used);
            mark_used(model.occlusion_texture, used);
            mark_used(model.specular_color_texture, used);
            for (const TextureRef* r :
                 {&model.clearcoat_texture, &model.clearcoat_roughness_texture,
                  &model.clearcoat_normal_texture, &model.sheen_color_texture,
                  &model.sheen_roughness_texture})
              mark_used(*r, used);
            if (model.transmission > 0) mark_used(model.transmission_texture, used);
          }
        },
        m.model);
  }
  return used;
}

Matrix4 to_matrix(const Transform& t) {
  return t.matrix();
}

// NDC of the full image → NDC of the crop window (affine, so it applies to clip coordinates).
Matrix4 crop_from_full_ndc(const Camera& camera) {
  Bounds2i crop = camera.film.crop_pixels();
  double cw = crop.width(), ch = crop.height();
  Matrix4 crop_ndc_from_raster = Matrix4::from_rows({{{2 / cw, 0, 0, -2 * crop.min.x / cw - 1},
                                                      {0, -2 / ch, 0, 1 + 2 * crop.min.y / ch},
                                                      {0, 0, 1, 0},
                                                      {0, 0, 0, 1}}});
  return crop_ndc_from_raster * camera.raster_from_ndc();
}

// An orthographic projection's clip w is 1, which the tile rasterizer keeps as the aovs' view
// depth: there the view depth is read back from the window depth instead, which is linear in it
// (z_ndc = a·z + b for camera-space z = −depth, window z = (z_ndc + 1) / 2).
void orthographic_view_depth(RenderTarget& target, const Matrix4& projection) {
  const double a = projection[2][2], b = projection[2][3];
  float* view_depth = target.view_depth();
  for (int y = 0; y < target.height(); ++y)
    for (int x = 0; x < target.width(); ++x)
      for (int s = 0; s < target.samples(); ++s) {
        float& depth = view_depth[target.sample_index(x, y, s)];
        if (std::isfinite(depth)) depth = float(-((2.0 * target.depth_at(x, y, s) - 1) - b) / a);
      }
}

// The target's colours resolved to one per pixel (the mean of its samples), row-major.
std::vector<Rgb> resolved_colors(const RenderTarget& target) {
  std::vector<Rgb> pixels(size_t(target.width()) * size_t(target.height()));
  const int samples = target.samples();
  tbb::parallel_for(0, target.height(), [&](int y) {
    for (int x = 0; x < target.width(); ++x) {
      Rgb sum;
      for (int s = 0; s < samples; ++s) sum += target.color(target.sample_index(x, y, s));
      pixels[size_t(y) * size_t(target.width()) + size_t(x)] = sum / float(samples);
    }
  });
  return pixels;
}

}  // namespace

SceneRasterizer::SceneRasterizer(const Scene& scene, RasterSettings settings,
                                 std::shared_ptr<const Surfaces> share)
    : settings_(settings) {
  if (!is_valid_sample_count(settings.msaa_samples))
    throw Error("raster settings",
                "MSAA samples must be 1, 4 or 8; got " + std::to_string(settings.msaa_samples));
  scene.validate();
  vertices_.resize(scene.meshes.size());
  indices_.resize(scene.meshes.size());
  // The UV set of the normal map each mesh is drawn with, if any (the first one found).
  normal_map_uv_set_.assign(scene.meshes.size(), -1);
  for (const Instance& instance : scene.instances) {
    const TextureRef& normal_map =
        tangent_space_texture(scene.materials[scene.material_of(instance)]);
    if (normal_map.valid() && normal_map_uv_set_[instance.mesh] < 0)
      normal_map_uv_set_[instance.mesh] = int(normal_map.uv_set);
  }
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    compile_mesh(scene.meshes[m], normal_map_uv_set_[m], vertices_[m], indices_[m]);
    if (scene.meshes[m].deforms()) deforming_.emplace(uint32_t(m), scene.meshes[m]);
  }

  surfaces_ = share ? std::move(share) : prepare_surfaces(scene);
  for (const Instance& instance : scene.instances) {
    CompiledInstance c{instance.mesh, scene.material_of(instance), instance.world_from_object, {}};
    if (instance.animated()) {
      std::vector<AnimatedTransform::Key> keys;
      for (const TransformKey& k : instance.motion)
        keys.push_back({k.time_seconds, k.world_from_object});
      try {
        c.motion.emplace(std::move(keys));
      } catch (const Error& e) {
        warnings_.push_back("instance '" + instance.name +
                            "': motion keys the rasterizer cannot interpolate (" + e.what() +
                            "); drawn at its time-0 pose");
      }
    }
    instances_.push_back(std::move(c));
  }
  bounds_ = instance_bounds(scene);

  gather_lights(scene);
}

std::shared_ptr<const SceneRasterizer::Surfaces> SceneRasterizer::prepare_surfaces(
    const Scene& scene) {
  auto prepared = std::make_shared<Surfaces>();
  Surfaces& surfaces = *prepared;
  std::vector<bool> used = used_textures(scene);
  auto table = std::make_shared<TextureTable>();
  std::vector<const Texture*>& texture_of = table->color;
  texture_of.assign(scene.textures.size(), nullptr);
  surfaces.textures.reserve(scene.textures.size());
  for (size_t t = 0; t < scene.textures.size(); ++t)
    if (used[t] && scene.textures[t].width > 0 && scene.textures[t].height > 0)
      surfaces.textures.push_back(compile_texture(scene.textures[t]));
  for (size_t t = 0, k = 0; t < scene.textures.size(); ++t)
    if (used[t] && scene.textures[t].width > 0 && scene.textures[t].height > 0)
      texture_of[t] = &surfaces.textures[k++];
  // Coverage textures, built first and pointed to after: the vector no longer reallocates.
  std::vector<bool> coverage = alpha_channel_textures(scene);
  std::vector<const Texture*>& alpha_of = table->alpha;
  alpha_of.assign(scene.textures.size(), nullptr);
  std::vector<int> alpha_index(scene.textures.size(), -1);
  for (size_t t = 0; t < scene.textures.size(); ++t)
    if (coverage[t] && scene.textures[t].width > 0 && scene.textures[t].height > 0)
      if (std::optional<Texture> alpha = compile_alpha_texture(scene.textures[t])) {
        alpha_index[t] = int(surfaces.alpha_textures.size());
        surfaces.alpha_textures.push_back(std::move(*alpha));
      }
  for (size_t t = 0; t < scene.textures.size(); ++t)
    if (alpha_index[t] >= 0) alpha_of[t] = &surfaces.alpha_textures[size_t(alpha_index[t])];
  surfaces.texture_table = std::move(table);
  for (const Material& m : scene.materials)
    surfaces.materials.push_back(compile_material(m, surfaces.texture_table.get()));

  if (scene.environment) {
    const Environment& env = *scene.environment;
    surfaces.environment_scale = env.color * env.intensity;
    surfaces.environment_from_world = inverse(env.world_from_environment);
    if (env.texture >= 0) {
      const obscura::Texture& t = scene.textures[env.texture];
      Image& map = surfaces.environment_map = Image(t.width, t.height, 3);
      for_each_texel(t, [&](int x, int y, Vector4f v) { map.set_rgb(x, y, {v.x, v.y, v.z}); });
    }
    surfaces.environment_lighting =
        surfaces.environment_map.width > 0
            ? std::make_shared<const EnvironmentLighting>(surfaces.environment_map,
                                                          surfaces.environment_scale,
                                                          surfaces.environment_from_world)
            : std::make_shared<const EnvironmentLighting>(surfaces.environment_scale);
  }
  return prepared;
}

void SceneRasterizer::gather_lights(const Scene& scene) {
  lights_ = {};
  shading::add_scene_lights(scene, lights_);
  if (settings_.surface_lights) shading::add_emissive_surface_lights(scene, lights_);
  if (scene.environment) {
    lights_.ambient = shading::environment_mean_radiance(scene);
    lights_.environment = surfaces_->environment_lighting.get();
  }
}

Bounds3f SceneRasterizer::instance_bounds(const Scene& scene) {
  Bounds3f bounds;
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[instance.mesh];
    auto cover = [&](Point3f p) {
      bounds = unite(bounds, instance.world_from_object(p));
      for (const TransformKey& k : instance.motion) bounds = unite(bounds, k.world_from_object(p));
    };
    for (Point3f p : mesh.positions) cover(p);
    for (const std::vector<Point3f>& step : mesh.deformation.positions)
      for (Point3f p : step) cover(p);
  }
  return bounds;
}

void SceneRasterizer::update_meshes(const Scene& scene, std::span<const uint32_t> meshes) {
  for (uint32_t m : meshes) {
    if (m >= scene.meshes.size() || m >= vertices_.size())
      throw Error("raster", "a posed mesh index beyond the scene's meshes: " + std::to_string(m));
    compile_mesh(scene.meshes[m], normal_map_uv_set_[m], vertices_[m], indices_[m]);
    if (scene.meshes[m].deforms())
      deforming_.insert_or_assign(m, scene.meshes[m]);
    else
      deforming_.erase(m);
  }
  bounds_ = instance_bounds(scene);
  gather_lights(scene);  // an emissive mesh's surface light moves with it
}

std::pair<const std::vector<MeshVertex>*, const std::vector<uint32_t>*> SceneRasterizer::mesh_at(
    uint32_t mesh, double time_s, std::vector<MeshVertex>& scratch,
    std::vector<uint32_t>& scratch_indices) const {
  auto found = deforming_.find(mesh);
  if (found == deforming_.end()) return {&vertices_[mesh], &indices_[mesh]};
  compile_mesh(found->second.posed_at(time_s), normal_map_uv_set_[mesh], scratch, scratch_indices);
  return {&scratch, &scratch_indices};
}

Transform SceneRasterizer::world_from_object(const CompiledInstance& instance,
                                             double time_s) const {
  return instance.motion ? instance.motion->at(time_s) : instance.world_from_object;
}

RenderTarget SceneRasterizer::make_target(const Camera& camera) const {
  Bounds2i crop = camera.film.crop_pixels();
  return RenderTarget(crop.width(), crop.height(), settings_.msaa_samples, settings_.aovs);
}

void SceneRasterizer::draw_background(const Matrix4& world_from_clip, RenderTarget& target,
                                      float exposure) const {
  if (surfaces_->environment_map.width == 0) {
    target.clear(surfaces_->environment_scale * exposure);
    return;
  }
  target.clear();
  const int w = target.width(), h = target.height();
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      if (!target.draws_pixel(x, y)) continue;  // another process's pixel
      double nx = 2 * (x + 0.5) / w - 1, ny = 1 - 2 * (y + 0.5) / h;
      Vector4d a = world_from_clip * Vector4d(nx, ny, -1, 1);
      Vector4d b = world_from_clip * Vector4d(nx, ny, 0, 1);
      Vector3f d(float(b.x / b.w - a.x / a.w), float(b.y / b.w - a.y / a.w),
                 float(b.z / b.w - a.z / a.w));
      Vector3f l = normalize(surfaces_->environment_from_world(d));
      // The tracer's equirectangular mapping: u = 0.5 along −Z, growing towards +X; v = θ/π.
      float theta = std::atan2(std::sqrt(l.x * l.x + l.z * l.z), l.y);
      float u = 0.5f + std::atan2(l.x, -l.z) / (2 * kPi);
      u -= std::floor(u);
      int tx = cell_index(u * surfaces_->environment_map.width, surfaces_->environment_map.width);
      int ty = cell_index(theta / kPi * surfaces_->environment_map.height,
                          surfaces_->environment_map.height);
      Rgb c = surfaces_->environment_map.rgb(tx, ty) * surfaces_->environment_scale * exposure;
      for (int s = 0; s < target.samples(); ++s) target.set_color(target.sample_index(x, y, s), c);
    }
  });
}

ShadowMap SceneRasterizer::render_shadow_map(const Matrix4& clip_from_world, float texel_world,
                                             bool perspective, double time_s) const {
  ShadowMap map(clip_from_world, settings_.shadow_map_size, texel_world, perspective);
  for (const CompiledInstance& instance : instances_) {
    const Matrix4f clip_from_object(clip_from_world * world_from_object(instance, time_s).matrix());
    const SurfaceMaterial& material = surfaces_->materials[instance.material];
    std::vector<MeshVertex> scratch;
    std::vector<uint32_t> scratch_indices;
    auto [vertices, indices] = mesh_at(instance.mesh, time_s, scratch, scratch_indices);
    if (material.alpha_mode == AlphaMode::kOpaque) {
      draw_shadow_depth(map.depth, DrawState{}, clip_from_object, nullptr, *vertices, *indices);
      continue;
    }
    // Cut-outs cast cut-out shadows. A depth map cannot hold a partial shadow, so a blended
    // surface shadows where it covers at least half (the tracer's shadow is 1 − α there).
    DrawState state;
    state.alpha_test = true;
    state.alpha_cutoff = material.alpha_mode == AlphaMode::kMask ? material.alpha_cutoff : 0.5f;
    draw_shadow_depth(map.depth, state, clip_from_object, &material, *vertices, *indices);
  }
  return map;
}

void SceneRasterizer::render_frame(const Camera& camera, const RasterFrame& frame,
                                   RenderTarget& target) const {
  Bounds2i crop = camera.film.crop_pixels();
  if (target.width() != crop.width() || target.height() != crop.height())
    throw Error("render_frame",
                "the target (" + std::to_string(target.width()) + "x" +
                    std::to_string(target.height()) + ") must match the camera's crop (" +
                    std::to_string(crop.width()) + "x" + std::to_string(crop.height()) + ")");
  const Matrix4 view = frame.view ? *frame.view : camera.view_matrix(frame.time_s);
  const Matrix4 projection = frame.projection ? *frame.projection : camera.projection_matrix();
  const Matrix4 fitted = fit_depth_range(projection, view, bounds_, camera.near_m);
  const Matrix4 clip_from_world = crop_from_full_ndc(camera) * fitted * view;
  std::optional<Matrix4> world_from_clip = inverse(clip_from_world);
  std::optional<Matrix4> world_from_camera = inverse(view);
  if (!world_from_clip || !world_from_camera)
    throw Error("render_frame", "the view or projection matrix is singular");
  const auto exposure = float(camera.exposure_scale());
  draw_background(*world_from_clip, target, exposure);

  // Shadow maps at this shutter time.
  std::vector<ShadowMap> directional_shadows, spot_shadows;
  if (settings_.shadow_map_size > 0 && !bounds_.empty()) {
    const int size = settings_.shadow_map_size;
    float texel = 0;
    for (const DirectionalLight& l : lights_.directional) {
      Matrix4 m = directional_shadow_projection(-l.to_light, bounds_, size, &texel);
      directional_shadows.push_back(render_shadow_map(m, texel, false, frame.time_s));
    }
    for (const SpotLight& l : lights_.spot) {
      Matrix4 m = spot_shadow_projection(l.position, l.direction,
                                         std::acos(std::clamp(l.cos_outer, -1.f, 1.f)), bounds_,
                                         size, &texel);
      ShadowMap& map = spot_shadows.emplace_back(render_shadow_map(m, texel, true, frame.time_s));
      map.light_position = l.position;
      map.light_axis = l.direction;
    }
  }

  InstanceUniforms base;
  base.shadows = {directional_shadows, spot_shadows};
  const Matrix4& wc = *world_from_camera;
  // A projection whose w does not depend on z is orthographic: the eye is infinitely far.
  base.eye_at_infinity = projection[3][2] == 0;
  base.eye = Point3f(float(wc[0][3]), float(wc[1][3]), float(wc[2][3]));
  base.to_viewer = normalize(Vector3f(float(wc[0][2]), float(wc[1][2]), float(wc[2][2])));
  base.lights = &lights_;
  base.exposure = exposure;
  base.flat = settings_.shading == ShadingMode::kFlat;
  base.force_blinn = settings_.shading == ShadingMode::kBlinnPhong;

  // Opaque and cut-out surfaces first; then transmissive ones, which show the frame drawn so far
  // through them (as glTF's real-time viewers do: glass is not seen through glass); blended ones
  // over everything.
  std::vector<size_t> blended, transmissive;
  for (size_t i = 0; i < instances_.size(); ++i) {
    const SurfaceMaterial& m = surfaces_->materials[instances_[i].material];
    if (m.alpha_mode == AlphaMode::kBlend) {
      blended.push_back(i);
    } else if (m.transmits()) {
      transmissive.push_back(i);
    } else {
      draw_instance(target, base, clip_from_world, i, frame.time_s);
    }
  }
  std::vector<Rgb> behind;
  if (!transmissive.empty()) {
    behind = resolved_colors(target);
    base.behind = {behind.data(), target.width()};
    for (size_t i : transmissive) draw_instance(target, base, clip_from_world, i, frame.time_s);
  }
  if (!blended.empty()) draw_blended(target, base, clip_from_world, view, blended, frame.time_s);
  if (base.eye_at_infinity && target.has_aovs()) orthographic_view_depth(target, fitted);
}

void SceneRasterizer::draw_instance(RenderTarget& target, const InstanceUniforms& base,
                                    const Matrix4& clip_from_world, size_t i, double time_s,
                                    std::span<const uint32_t> sorted) const {
  const CompiledInstance& instance = instances_[i];
  const Transform world_from_object = this->world_from_object(instance, time_s);
  const SurfaceMaterial& material = surfaces_->materials[instance.material];
  InstanceUniforms u = base;
  u.clip_from_object = Matrix4f(clip_from_world * to_matrix(world_from_object));
  u.world_from_object = Matrix4f(world_from_object.matrix());
  u.normal_from_object = Matrix4f(transpose(world_from_object.inverse_matrix()));
  u.handedness = world_from_object.swaps_handedness() ? -1.f : 1.f;
  u.material = &material;
  DrawState state;
  state.object_id = uint32_t(i + 1);
  state.cull = settings_.cull_back_faces ? CullMode::kBack : CullMode::kNone;
  // A mirroring transform turns counter-clockwise faces clockwise.
  state.front_face =
      world_from_object.swaps_handedness() ? FrontFace::kClockwise : FrontFace::kCounterClockwise;
  state.wireframe = settings_.wireframe;
  state.alpha_test = material.alpha_mode == AlphaMode::kMask;
  state.alpha_cutoff = material.alpha_cutoff;
  if (material.alpha_mode == AlphaMode::kBlend) {
    // Depth-tested against what is drawn, but not hiding what is drawn after it.
    state.depth_write = false;
    state.blend = BlendMode::kOver;
  }
  std::vector<MeshVertex> scratch;
  std::vector<uint32_t> scratch_indices;
  auto [posed_vertices, posed_indices] = mesh_at(instance.mesh, time_s, scratch, scratch_indices);
  const std::span<const MeshVertex> vertices = *posed_vertices;
  // `sorted`, where given, orders the triangles of this same pose (draw_blended).
  const std::span<const uint32_t> indices = sorted.empty() ? *posed_indices : sorted;
  const bool gouraud = settings_.shading == ShadingMode::kGouraud;
  const bool coverage = material.alpha_mode != AlphaMode::kOpaque;
  if (gouraud) return draw_gouraud_shaded(target, state, u, coverage, vertices, indices);
  if (coverage) return draw_pixel_shaded_with_coverage(target, state, u, vertices, indices);
  draw_pixel_shaded(target, state, u, vertices, indices);
}

void SceneRasterizer::draw_blended(RenderTarget& target, const InstanceUniforms& base,
                                   const Matrix4& clip_from_world, const Matrix4& camera_from_world,
                                   const std::vector<size_t>& blended, double time_s) const {
  // "Over" composes correctly only back to front. Instances are sorted by the view depth of
  // their bounds' centre, and each one's triangles by the view depth of their centroids.
  struct Sorted {
    double depth;
    size_t instance;
    std::vector<uint32_t> indices;
  };
  std::vector<Sorted> order;
  for (size_t i : blended) {
    const CompiledInstance& instance = instances_[i];
    std::vector<MeshVertex> scratch;
    std::vector<uint32_t> scratch_indices;
    auto [posed_vertices, posed_indices] = mesh_at(instance.mesh, time_s, scratch, scratch_indices);
    const std::vector<MeshVertex>& vertices = *posed_vertices;
    const std::vector<uint32_t>& indices = *posed_indices;
    if (vertices.empty()) continue;
    const Matrix4 camera_from_object =
        camera_from_world * world_from_object(instance, time_s).matrix();
    std::vector<double> depth(vertices.size());  // along the view direction (camera −z)
    double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest;
    for (size_t v = 0; v < vertices.size(); ++v) {
      Point3f p = vertices[v].position;
      depth[v] = -(camera_from_object[2][0] * p.x + camera_from_object[2][1] * p.y +
                   camera_from_object[2][2] * p.z + camera_from_object[2][3]);
      nearest = std::min(nearest, depth[v]), farthest = std::max(farthest, depth[v]);
    }
    const size_t triangles = (indices.empty() ? vertices.size() : indices.size()) / 3;
    auto corner = [&](size_t t, int k) {
      return indices.empty() ? uint32_t(3 * t + k) : indices[3 * t + k];
    };
    std::vector<double> key(triangles);  // three times the centroid's depth
    for (size_t t = 0; t < triangles; ++t)
      key[t] = depth[corner(t, 0)] + depth[corner(t, 1)] + depth[corner(t, 2)];
    std::vector<uint32_t> by_depth(triangles);
    std::iota(by_depth.begin(), by_depth.end(), 0u);
    // Stable: equally deep triangles keep the file's order, so the image is deterministic.
    std::stable_sort(by_depth.begin(), by_depth.end(),
                     [&](uint32_t a, uint32_t b) { return key[a] > key[b]; });
    Sorted s{(nearest + farthest) / 2, i, {}};
    s.indices.reserve(3 * triangles);
    for (uint32_t t : by_depth)
      for (int k = 0; k < 3; ++k) s.indices.push_back(corner(t, k));
    order.push_back(std::move(s));
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const Sorted& a, const Sorted& b) { return a.depth > b.depth; });
  for (const Sorted& s : order)
    draw_instance(target, base, clip_from_world, s.instance, time_s, s.indices);
}

void SceneRasterizer::render(const Camera& camera, Film& film, RenderTarget* target) const {
  std::optional<RenderTarget> own;
  if (!target) target = &own.emplace(make_target(camera));
  RasterFrame frame;
  frame.time_s = camera.shutter.time_at(0.5);
  render_frame(camera, frame, *target);
  target->accumulate_into(film);
}

Image id_image(const RenderTarget& target) {
  if (!target.has_aovs()) throw Error("id_image", "the render target has no aovs");
  Image image(target.width(), target.height(), 1);
  image.channel_names = {"id"};
  for (int y = 0; y < target.height(); ++y)
    for (int x = 0; x < target.width(); ++x)
      image.at(x, y, 0) = float(int64_t(target.object_id_at(x, y)) - 1);
  return image;
}

Image depth_image(const RenderTarget& target) {
  Image image = target.view_depth_image();
  image.channel_names = {"Z"};
  return image;
}

Image range_image(const RenderTarget& target, const Camera& camera) {
  Image image = target.view_depth_image();
  image.channel_names = {"range"};
  if (!std::holds_alternative<Perspective>(camera.projection)) return image;
  Bounds2i crop = camera.film.crop_pixels();
  const PreparedCamera prepared = camera.prepare();
  for (int y = 0; y < target.height(); ++y)
    for (int x = 0; x < target.width(); ++x) {
      // The ray through the pixel centre travels |(wx, wy, −1)| per unit of depth.
      Point2d w = prepared.window_from_raster({crop.min.x + x + 0.5, crop.min.y + y + 0.5});
      image.at(x, y, 0) *= float(std::sqrt(w.x * w.x + w.y * w.y + 1));
    }
  return image;
}

Image normal_image(const RenderTarget& target) {
  Image image = target.normal_image();
  image.channel_names = {"X", "Y", "Z"};
  return image;
}

}  // namespace obscura::raster
