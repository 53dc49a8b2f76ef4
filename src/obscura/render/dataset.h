// A dataset: every view of render/dataset_views.h rendered with the outputs asked for, and the
// calibration of all of them in the formats computer-vision tools read (docs/camera.md,
// "Datasets"). In the dataset's folder:
//
//   images/view_0000.png           each view's image (the format asked for), and with AOVs
//                                  images/view_0000.normal.exr, ... beside it
//   ground_truth/view_0000.exr     each view's ground truth (docs/ground_truth.md), its flow
//                                  channels between consecutive views (below)
//   sparse/0/cameras.txt, images.txt, points3D.txt
//                                  ONE COLMAP text model: every view an image named by its image
//                                  file below images/, views with the same intrinsics sharing a
//                                  camera
//   transforms.json                ONE NeRF file: a frame per view, file_path the image's path
//                                  relative to it ("images/view_0000.png")
//   opencv/view_0000.yaml          each view's OpenCV FileStorage file (K, distortion, R, T)
//
// Flow in a dataset's ground truth is between views, not over time: flow.forward at pixel p of
// view i is where the point p sees lands in view i + 1 (its raster point minus p's centre), and
// flow.backward where it lands in view i − 1; NaN for the last (first) view, for misses and where
// the point is not on the other view's film (no occlusion test, as for time flow).
//
// Resumable: a view whose files are all there and read back whole is not rendered again. Views
// can be rendered by many processes at once (each takes the next view from a shared counter);
// the model files depend only on the views, so whoever writes them writes the same bytes.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "obscura/film/tiles.h"
#include "obscura/io/image_io.h"
#include "obscura/render/dataset_views.h"
#include "obscura/render/frame_settings.h"

namespace obscura {

class RenderSession;

struct DatasetOutputs {
  std::string image_format = "png";  // the images' extension: png, exr, jpg, tif, hdr, pfm
  ImageWriteOptions image;           // how the images are developed (display formats)
  bool ground_truth = false;         // ground_truth/VIEW.exr
  bool aovs = false;                 // the AOVs beside each image
  // The calibration files: "colmap", "nerf", "opencv" (empty: none).
  std::vector<std::string> formats = {"colmap", "nerf", "opencv"};
};

struct DatasetPlan {
  std::string directory;
  std::vector<DatasetView> views;
  FrameSettings settings;  // the renderer, samples, seed, ... (the whole frame: no share)
  DatasetOutputs outputs;
};

// The files of view i (paths in the dataset's folder).
std::string dataset_image_path(const DatasetPlan& plan, size_t view);
std::string dataset_ground_truth_path(const DatasetPlan& plan, size_t view);

// Checks the plan before any rendering: a known image format and calibration formats, views of
// one film size, ground truth from a renderer that has it, and that every calibration format
// can hold every view's camera (obscura::Error naming the format and the view otherwise).
// Returns what the formats leave out (a fisheye's field limit in COLMAP and NeRF), one warning
// each, once per distinct message.
std::vector<std::string> check_dataset_plan(const DatasetPlan& plan);

// Whether view i's files are all there and complete (resume).
bool dataset_view_finished(const DatasetPlan& plan, size_t view);

// Renders view i through `session` and writes its files (atomically). Returns the renderer's
// warnings. A frame stopped early (cancel, time limit) writes nothing and returns with
// `*stopped` set.
std::vector<std::string> render_dataset_view(RenderSession& session, const DatasetPlan& plan,
                                             size_t view, bool* stopped = nullptr,
                                             const ProgressCallback& progress = {});

// Writes the calibration files of every view (sparse/0/, transforms.json, opencv/).
void write_dataset_model(const DatasetPlan& plan);

struct DatasetReport {
  int rendered = 0, skipped = 0;  // by this process
  bool stopped = false;           // a view stopped early (cancel, time limit)
  std::vector<std::string> warnings;
};

// The whole dataset in this process, or this process's share of it: takes view numbers from
// `next_view` (default: 0, 1, 2, ...) until one is past the last, skipping finished views and
// rendering the others; `on_view(view, rendered)` after each. Writes the model files when
// `write_model` (one process of many). Throws obscura::Error as check_dataset_plan.
DatasetReport render_dataset(RenderSession& session, const DatasetPlan& plan,
                             const std::function<int64_t()>& next_view = {},
                             const std::function<void(size_t, bool)>& on_view = {},
                             bool write_model = true);

}  // namespace obscura
