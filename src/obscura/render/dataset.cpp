#include "obscura/render/dataset.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "obscura/film/ground_truth_buffer.h"
#include "obscura/io/aov_files.h"
#include "obscura/io/atomic_file.h"
#include "obscura/io/calibration_file.h"
#include "obscura/io/colmap_model.h"
#include "obscura/io/finished_image.h"
#include "obscura/io/ground_truth_file.h"
#include "obscura/io/nerf_transforms.h"
#include "obscura/io/opencv_calibration.h"
#include "obscura/math/error.h"
#include "obscura/render/render_session.h"
#include "obscura/render/renderer_backend.h"
#include "obscura/scene/ground_truth.h"

namespace obscura {

namespace {

namespace fs = std::filesystem;

constexpr const char* kColmapFolder = "sparse/0";

std::string joined(const std::string& directory, const std::string& relative) {
  return (fs::path(directory) / relative).string();
}

std::string image_relative(const DatasetPlan& plan, size_t view) {
  return "images/" + plan.views[view].name + "." + plan.outputs.image_format;
}

bool wants(const DatasetPlan& plan, const std::string& format) {
  const auto& f = plan.outputs.formats;
  return std::find(f.begin(), f.end(), format) != f.end();
}

// Each view's calibration, its image named as the format names it: COLMAP relative to the
// image folder, NeRF relative to transforms.json.
std::vector<CameraCalibration> calibrations(const DatasetPlan& plan, bool colmap_names) {
  std::vector<CameraCalibration> out;
  for (size_t i = 0; i < plan.views.size(); ++i) {
    CameraCalibration c;
    try {
      c = calibration_of(plan.views[i].camera);
    } catch (const Error& e) {
      throw Error("dataset " + plan.views[i].name,
                  std::string(e.what()) +
                      " (or write no calibration files: the formats none, --formats none)");
    }
    const std::string relative = image_relative(plan, i);
    c.image_name = colmap_names ? relative.substr(relative.find('/') + 1) : relative;
    out.push_back(std::move(c));
  }
  return out;
}

void write_text(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.write(text);
  file.commit();
}

void make_folder(const std::string& path) {
  std::error_code error;
  fs::create_directories(path, error);
  if (!fs::is_directory(path))
    throw Error(path, "cannot create the dataset's folder (" +
                          (error ? error.message() : std::string("not a directory")) + ")");
}

// Flow from each pixel of `buffer` (view `camera`) to where its point lands in `other`.
void set_view_flow(GroundTruthBuffer& buffer, const Camera& camera, const Camera* other,
                   bool forward) {
  const Bounds2i crop = camera.film.crop_pixels();
  std::optional<PreparedCamera> prepared;
  if (other) prepared.emplace(*other);
  const double time = other ? other->shutter.open_s : 0;
  for (int y = 0; y < buffer.height(); ++y)
    for (int x = 0; x < buffer.width(); ++x) {
      std::optional<Vector2d> flow;
      const Point3d p(buffer.value(x, y, "P.X"), buffer.value(x, y, "P.Y"),
                      buffer.value(x, y, "P.Z"));
      if (prepared && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
        if (std::optional<FilmProjection> at = prepared->project(p, time))
          flow = Vector2d(at->film_point.x - (crop.min.x + x + 0.5),
                          at->film_point.y - (crop.min.y + y + 0.5));
      if (forward)
        buffer.set_forward_flow(x, y, flow);
      else
        buffer.set_backward_flow(x, y, flow);
    }
}

}  // namespace

std::string dataset_image_path(const DatasetPlan& plan, size_t view) {
  return joined(plan.directory, image_relative(plan, view));
}

std::string dataset_ground_truth_path(const DatasetPlan& plan, size_t view) {
  return joined(plan.directory, "ground_truth/" + plan.views[view].name + ".exr");
}

std::vector<std::string> check_dataset_plan(const DatasetPlan& plan) {
  if (plan.views.empty()) throw Error("dataset", "no views to render");
  const ImageFormat image_format = image_format_for_path("view." + plan.outputs.image_format);
  if (image_format == ImageFormat::kY4m)
    throw Error("dataset",
                "the images cannot be a .y4m video: give png, exr, jpg, tif, hdr or pfm");
  for (const std::string& f : plan.outputs.formats)
    if (f != "colmap" && f != "nerf" && f != "opencv")
      throw Error("dataset",
                  "unknown calibration format '" + f + "': expected colmap, nerf or opencv");
  if (plan.outputs.ground_truth && !plan.settings.renderer.capabilities().ground_truth)
    throw Error("dataset", "the " + std::string(plan.settings.renderer.name()) +
                               " renderer has no ground truth");
  for (const DatasetView& view : plan.views) {
    const Bounds2i crop = view.camera.film.crop_pixels();
    if (crop.width() != view.camera.film.width_px || crop.height() != view.camera.film.height_px)
      throw Error("dataset " + view.name,
                  "a dataset's views are whole frames, as their calibrations describe them: "
                  "leave the crop out");
  }
  std::vector<std::string> warnings;
  auto warn = [&](const std::vector<std::string>& more) {
    for (const std::string& w : more)
      if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
  };
  if (plan.outputs.formats.empty()) return warnings;
  const std::vector<CameraCalibration> views = calibrations(plan, false);
  for (const std::string& f : plan.outputs.formats) {
    const CalibrationFormat format =
        *calibration_format_from_name(f == "opencv" ? "opencv-yaml" : f);
    for (const CameraCalibration& c : views) warn(calibration_omissions(format, c));
    try {
      if (f == "colmap") colmap_model_text(views);
      if (f == "nerf") nerf_transforms_text(views);
      if (f == "opencv")
        for (const CameraCalibration& c : views) opencv_yaml_text(c);
    } catch (const Error& e) {
      throw Error("dataset " + f, std::string(e.what()) +
                                      " (leave the format out of the dataset's formats to "
                                      "render without it)");
    }
  }
  return warnings;
}

bool dataset_view_finished(const DatasetPlan& plan, size_t view) {
  const Bounds2i crop = plan.views[view].camera.film.crop_pixels();
  const int w = crop.width(), h = crop.height();
  const std::string image = dataset_image_path(plan, view);
  if (!finished_image_exists(image, w, h)) return false;
  if (plan.outputs.ground_truth &&
      !finished_image_exists(dataset_ground_truth_path(plan, view), w, h))
    return false;
  if (plan.outputs.aovs)
    for (const std::string& aov : aov_paths(image, plan.settings.renderer.capabilities().albedo))
      if (!finished_image_exists(aov, w, h)) return false;
  return true;
}

std::vector<std::string> render_dataset_view(RenderSession& session, const DatasetPlan& plan,
                                             size_t view, bool* stopped,
                                             const ProgressCallback& progress) {
  if (stopped) *stopped = false;
  const Camera& camera = plan.views[view].camera;
  FrameSettings settings = plan.settings;
  settings.share = {};
  RenderedFrame frame = session.render(camera, settings, plan.outputs.aovs, progress);
  bool unfinished = false;
  const Image image = frame.finished(settings.cancel, &unfinished);
  if (frame.stats.partial() || unfinished) {
    if (stopped) *stopped = true;
    return frame.stats.warnings;
  }
  make_folder(joined(plan.directory, "images"));
  const std::string path = dataset_image_path(plan, view);
  write_image(path, image, plan.outputs.image);
  if (plan.outputs.aovs && frame.aovs) write_aovs(path, *frame.aovs);
  if (plan.outputs.ground_truth) {
    make_folder(joined(plan.directory, "ground_truth"));
    const GroundTruthTimes times = default_ground_truth_times(camera);
    GroundTruthBuffer buffer = session.ground_truth(camera, settings, times);
    set_view_flow(buffer, camera,
                  view + 1 < plan.views.size() ? &plan.views[view + 1].camera : nullptr, true);
    set_view_flow(buffer, camera, view > 0 ? &plan.views[view - 1].camera : nullptr, false);
    write_ground_truth(dataset_ground_truth_path(plan, view), buffer, camera, times);
  }
  return frame.stats.warnings;
}

void write_dataset_model(const DatasetPlan& plan) {
  make_folder(plan.directory);
  if (wants(plan, "colmap")) {
    const std::string folder = joined(plan.directory, kColmapFolder);
    make_folder(folder);
    const ColmapModelText model = colmap_model_text(calibrations(plan, true));
    write_text(joined(folder, "cameras.txt"), model.cameras);
    write_text(joined(folder, "images.txt"), model.images);
    write_text(joined(folder, "points3D.txt"),
               "# 3D point list with one line of data per point:\n"
               "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n"
               "# Number of points: 0, mean track length: 0\n");
  }
  if (wants(plan, "nerf"))
    write_text(joined(plan.directory, "transforms.json"),
               nerf_transforms_text(calibrations(plan, false)));
  if (wants(plan, "opencv")) {
    const std::string folder = joined(plan.directory, "opencv");
    make_folder(folder);
    const std::vector<CameraCalibration> views = calibrations(plan, false);
    for (size_t i = 0; i < views.size(); ++i)
      write_text(joined(folder, plan.views[i].name + ".yaml"), opencv_yaml_text(views[i]));
  }
}

DatasetReport render_dataset(RenderSession& session, const DatasetPlan& plan,
                             const std::function<int64_t()>& next_view,
                             const std::function<void(size_t, bool)>& on_view, bool write_model) {
  DatasetReport report;
  report.warnings = check_dataset_plan(plan);
  make_folder(plan.directory);
  if (write_model) write_dataset_model(plan);
  int64_t counter = 0;
  for (;;) {
    const int64_t view = next_view ? next_view() : counter++;
    if (view < 0 || view >= int64_t(plan.views.size())) break;
    if (report.stopped) continue;  // take the remaining tickets, render nothing
    const size_t v = size_t(view);
    if (dataset_view_finished(plan, v)) {
      ++report.skipped;
      if (on_view) on_view(v, false);
      continue;
    }
    bool stopped = false;
    for (const std::string& w : render_dataset_view(session, plan, v, &stopped))
      if (std::find(report.warnings.begin(), report.warnings.end(), w) == report.warnings.end())
        report.warnings.push_back(w);
    if (stopped) {
      report.stopped = true;
      continue;
    }
    ++report.rendered;
    if (on_view) on_view(v, true);
  }
  return report;
}

}  // namespace obscura
