#include "view_server.h"

#include "usage_error.h"

#ifndef OBSCURA_WITH_VIEW

namespace obscura::app {

void run_view_server(const ViewServerOptions&) {
  throw UsageError(
      "this obscura was built without cpp-httplib, the live view's server (scripts/setup "
      "installs libcpp-httplib-dev; then build again)");
}

}  // namespace obscura::app

#else

#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <random>
#include <string_view>
#include <thread>
#include <utility>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "obscura/io/calibration_file.h"
#include "obscura/io/camera_calibration.h"
#include "obscura/io/colmap_model.h"
#include "obscura/io/image_io.h"
#include "obscura/math/error.h"
#include "obscura/math/request_error.h"
#include "tracer_options.h"
#include "view_renderer.h"

extern char** environ;

namespace obscura::app {

namespace view_page {
extern const std::pair<std::string_view, std::string_view> files[];
extern const int file_count;
}  // namespace view_page

namespace {

using Json = nlohmann::json;

// Bounds that keep a misbehaving client from holding the server: request bodies (the page
// sends a camera of a few hundred bytes), worker threads, and event streams at once (each
// holds a worker while it lasts).
constexpr size_t kMaxBodyBytes = 16 * 1024;
constexpr int kWorkerThreads = 12;
constexpr int kMaxEventStreams = 6;
// A stream writes at least this often, so that one whose client left is found out (its write
// fails) and its worker freed within about two of these.
constexpr auto kEventKeepAlive = std::chrono::seconds(1);

// 128 random bits from the kernel, as hex: what every request must carry.
std::string random_token() {
  std::random_device device;
  std::string token;
  char hex[9];
  for (int i = 0; i < 4; ++i) {
    std::snprintf(hex, sizeof hex, "%08x", unsigned(device()));
    token += hex;
  }
  return token;
}

// Compares in time independent of where the strings differ.
bool same_secret(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  unsigned char difference = 0;
  for (size_t i = 0; i < a.size(); ++i) difference |= static_cast<unsigned char>(a[i] ^ b[i]);
  return difference == 0;
}

std::string_view page_file(std::string_view name) {
  for (int i = 0; i < view_page::file_count; ++i)
    if (view_page::files[i].first == name) return view_page::files[i].second;
  return {};
}

void replace_all(std::string& text, std::string_view from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

void send_json(httplib::Response& res, const std::string& json, int status = 200) {
  res.status = status;
  res.set_content(json, "application/json");
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, Json{{"error", message}}.dump(), status);
}

// x and y of a JSON body {"x": …, "y": …}: raster coordinates on the frame.
std::pair<double, double> point_of(const std::string& body) {
  Json json;
  try {
    json = Json::parse(body);
  } catch (const Json::exception&) {
    throw RequestError("point", "expected a JSON object {\"x\": …, \"y\": …}");
  }
  if (!json.is_object() || !json.contains("x") || !json.contains("y") || !json["x"].is_number() ||
      !json["y"].is_number())
    throw RequestError("point", "expected a JSON object {\"x\": …, \"y\": …}");
  return {json["x"].get<double>(), json["y"].get<double>()};
}

// Asks the desktop to open the page; the view goes on whatever it answers.
void open_in_browser(const std::string& url) {
  const char* argv[] = {"xdg-open", url.c_str(), nullptr};
  pid_t pid;
  if (posix_spawnp(&pid, "xdg-open", nullptr, nullptr, const_cast<char**>(argv), environ) != 0) {
    std::fprintf(stderr, "warning: --open: xdg-open could not be started; open %s yourself\n",
                 url.c_str());
    return;
  }
  std::thread([pid] { waitpid(pid, nullptr, 0); }).detach();
}

class Routes {
 public:
  Routes(ViewRenderer& renderer, std::string token, int port, int max_requests_per_second,
         std::string output)
      : renderer_(renderer),
        token_(std::move(token)),
        port_(port),
        max_requests_per_second_(max_requests_per_second),
        output_(std::move(output)) {}

  void install(httplib::Server& server) {
    server.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      return admit(req, res) && within_rate(res) ? httplib::Server::HandlerResponse::Unhandled
                                                 : httplib::Server::HandlerResponse::Handled;
    });
    server.set_post_routing_handler([](const httplib::Request&, httplib::Response& res) {
      // The token travels in the page's URLs: no other site is told it, nor may frame the page.
      res.set_header("Referrer-Policy", "no-referrer");
      res.set_header("X-Content-Type-Options", "nosniff");
      res.set_header("X-Frame-Options", "DENY");
      res.set_header("Cache-Control", "no-store");
    });
    server.Get("/", [this](const httplib::Request&, httplib::Response& res) {
      std::string page(page_file("index.html"));
      replace_all(page, "__OBSCURA_TOKEN__", token_);
      res.set_header("Content-Security-Policy",
                     "default-src 'self'; img-src 'self' blob:; connect-src 'self'; "
                     "style-src 'self'; script-src 'self'; frame-ancestors 'none'");
      res.set_content(page, "text/html; charset=utf-8");
    });
    server.Get("/view.js", [](const httplib::Request&, httplib::Response& res) {
      res.set_content(std::string(page_file("view.js")), "text/javascript; charset=utf-8");
    });
    server.Get("/view.css", [](const httplib::Request&, httplib::Response& res) {
      res.set_content(std::string(page_file("view.css")), "text/css; charset=utf-8");
    });
    server.Get("/api/state", [this](const httplib::Request&, httplib::Response& res) {
      send_json(res, renderer_.event_json());
    });
    server.Get("/api/frame", [this](const httplib::Request& req, httplib::Response& res) {
      const std::string view = req.has_param("view") ? req.get_param_value("view") : "beauty";
      const std::shared_ptr<const ViewFrame> frame = renderer_.latest();
      if (!frame) return send_error(res, 503, "no frame yet");
      const std::string png = frame->png(view);
      if (png.empty()) return send_error(res, 404, "no view '" + view + "' of this frame");
      res.set_header("X-Obscura-Event", std::to_string(frame->event));
      res.set_content(png, "image/png");
    });
    server.Post("/api/camera", [this](const httplib::Request& req, httplib::Response& res) {
      try {
        send_json(res, renderer_.set_camera(req.body));
      } catch (const Error& e) {
        send_error(res, 400, e.what());
      }
    });
    // The camera shown as a calibration file (what `obscura camera --export` writes): OpenCV's
    // YAML or JSON, NeRF's transforms.json, COLMAP's cameras.txt and images.txt.
    server.Get("/api/export", [this](const httplib::Request& req, httplib::Response& res) {
      const std::shared_ptr<const ViewFrame> frame = renderer_.latest();
      if (!frame || !frame->camera) return send_error(res, 503, "no frame yet");
      const std::string name = req.get_param_value("format");
      const std::optional<CalibrationFormat> format = calibration_format_from_name(name);
      if (!format) return send_error(res, 400, "format: opencv-yaml, opencv-json, nerf or colmap");
      try {
        const CameraCalibration calibration = calibration_of(*frame->camera);
        Json answer = {{"format", name},
                       {"omissions", calibration_omissions(*format, calibration)}};
        if (*format == CalibrationFormat::colmap) {
          const ColmapModelText model = colmap_model_text(calibration);
          answer["text"] = "# cameras.txt\n" + model.cameras + "# images.txt\n" + model.images;
        } else {
          answer["text"] = calibration_text(*format, calibration);
        }
        send_json(res, answer.dump());
      } catch (const Error& e) {
        send_error(res, 422, e.what());  // a camera the format cannot express
      }
    });
    server.Post("/api/save", [this](const httplib::Request&, httplib::Response& res) {
      const std::shared_ptr<const ViewFrame> frame = renderer_.latest();
      if (!frame) return send_error(res, 503, "no frame yet");
      try {
        // The file says what it is: the renderer, how far it got and the command that renders
        // it whole.
        ImageWriteOptions write{.display = frame->display, .exr_half = false, .metadata = {}};
        write.metadata.description =
            "obscura view: " + frame->renderer + ", " + std::to_string(frame->samples) + " of " +
            std::to_string(frame->samples_target) +
            (frame->renderer == "raster" ? " frames" : " spp") + "; " + frame->command;
        write_image(output_, frame->image, write);
        send_json(res, Json{{"path", output_}, {"final", frame->final}}.dump());
      } catch (const Error& e) {
        send_error(res, 500, e.what());
      }
    });
    server.Post("/api/focus", [this](const httplib::Request& req, httplib::Response& res) {
      try {
        const auto [x, y] = point_of(req.body);
        uint64_t generation = 0;
        const std::optional<double> depth = renderer_.focus_at(x, y, &generation);
        if (!depth) return send_error(res, 404, "nothing at that point to focus on");
        send_json(res, Json{{"depth_m", *depth}, {"generation", generation}}.dump());
      } catch (const Error& e) {
        send_error(res, 400, e.what());
      }
    });
    server.Get("/api/depth", [this](const httplib::Request& req, httplib::Response& res) {
      try {
        const double x = std::stod(req.get_param_value("x")),
                     y = std::stod(req.get_param_value("y"));
        const std::optional<double> depth = renderer_.depth_at(x, y);
        if (!depth) return send_error(res, 404, "nothing there");
        send_json(res, Json{{"depth_m", *depth}}.dump());
      } catch (const std::logic_error&) {
        send_error(res, 400, "expected ?x=…&y=… (raster coordinates)");
      }
    });
    server.Get("/api/events", [this](const httplib::Request&, httplib::Response& res) {
      if (++streams_ > kMaxEventStreams) {
        --streams_;
        return send_error(res, 503, "too many event streams open");
      }
      res.set_chunked_content_provider(
          "text/event-stream",
          [this, sent = uint64_t(0)](size_t, httplib::DataSink& sink) mutable {
            if (renderer_.stopping()) return false;
            const uint64_t event = renderer_.wait_event(
                sent, std::chrono::duration_cast<std::chrono::milliseconds>(kEventKeepAlive));
            if (renderer_.stopping()) return false;
            std::string message;
            if (event == sent) {
              message = ": still here\n\n";  // a write that finds a client gone ends the stream
            } else {
              sent = event;
              message = "event: state\ndata: " + renderer_.event_json() + "\n\n";
            }
            return sink.write(message.data(), message.size());
          },
          [this](bool) { --streams_; });
    });
  }

 private:
  // Only requests for this server by its loopback name (a page elsewhere that resolves its own
  // name to 127.0.0.1 sends its own Host: DNS rebinding), with the token.
  bool admit(const httplib::Request& req, httplib::Response& res) const {
    const std::string host = req.get_header_value("Host");
    const std::string port = ":" + std::to_string(port_);
    if (host != "127.0.0.1" + port && host != "localhost" + port) {
      res.status = 403;
      res.set_content("forbidden: this server answers only to 127.0.0.1" + port + "\n",
                      "text/plain");
      return false;
    }
    const std::string given = req.has_param("token") ? req.get_param_value("token")
                                                     : req.get_header_value("X-Obscura-Token");
    if (!same_secret(given, token_)) {
      res.status = 403;
      res.set_content("forbidden: the page's address printed by `obscura view` has its token\n",
                      "text/plain");
      return false;
    }
    return true;
  }

  // At most max_requests_per_second_ admitted requests in each second (a fixed window): a client
  // in a loop cannot keep the workers from everyone else for long.
  bool within_rate(httplib::Response& res) {
    const int64_t second = std::chrono::duration_cast<std::chrono::seconds>(
                               std::chrono::steady_clock::now().time_since_epoch())
                               .count();
    std::lock_guard lock(rate_mutex_);
    if (second != window_) window_ = second, in_window_ = 0;
    if (++in_window_ <= max_requests_per_second_) return true;
    res.status = 429;
    res.set_header("Retry-After", "1");
    res.set_content(
        "too many requests: at most " + std::to_string(max_requests_per_second_) + " a second\n",
        "text/plain");
    return false;
  }

  ViewRenderer& renderer_;
  std::string token_;
  int port_;
  int max_requests_per_second_;
  std::string output_;
  std::mutex rate_mutex_;
  int64_t window_ = 0;
  int in_window_ = 0;
  std::atomic<int> streams_{0};
};

}  // namespace

void run_view_server(const ViewServerOptions& options) {
  httplib::Server server;
  // SO_REUSEADDR alone (httplib's default adds SO_REUSEPORT, which would let a second view share
  // the port silently): a port in use is refused, one left in TIME_WAIT is not.
  server.set_socket_options([](int socket) {
    int yes = 1;
    setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  server.new_task_queue = [] { return new httplib::ThreadPool(kWorkerThreads); };
  server.set_payload_max_length(kMaxBodyBytes);
  server.set_read_timeout(5, 0);
  server.set_write_timeout(5, 0);
  server.set_keep_alive_timeout(5);
  int port = options.port;
  if (port != 0) {
    if (!server.bind_to_port("127.0.0.1", port))
      throw Error("--port " + std::to_string(port),
                  "127.0.0.1:" + std::to_string(port) +
                      " is in use (another obscura view?): give another --port, or none for a "
                      "free one");
  } else {
    port = server.bind_to_any_port("127.0.0.1");
    if (port <= 0) throw Error("obscura view", "no free port on 127.0.0.1");
  }
  // The port first: a second view on it says so before loading anything.
  ViewRenderer renderer(options.arguments, !options.no_watch);
  const std::string token = random_token();
  Routes routes(renderer, token, port, options.max_requests_per_second, options.output);
  routes.install(server);
  // Ctrl-C and SIGTERM stop the server (listen_after_bind returns once it has), from the moment
  // the address is printed.
  InterruptGuard interrupt;
  renderer.start();

  const std::string url = "http://127.0.0.1:" + std::to_string(port) + "/?token=" + token;
  std::printf("%s\n", url.c_str());
  std::fflush(stdout);
  std::fprintf(stderr, "obscura view: serving on 127.0.0.1:%d; Ctrl-C stops\n", port);
  if (options.open) open_in_browser(url);

  std::atomic<bool> done{false};
  std::thread watcher([&] {
    while (!done && !InterruptGuard::requested())
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    renderer.stop();  // wakes the event streams, so the workers can finish
    // Until listening has ended: a stop before it began would be missed.
    while (!done) {
      server.stop();
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  });
  server.listen_after_bind();
  done = true;
  watcher.join();
  renderer.stop();
}

}  // namespace obscura::app

#endif
