"""`obscura view`'s server over loopback (docs/view.md): the token, the page's assets and nothing
else, frames before and after a camera move, the copied command reproducing the frame bit for bit,
click-to-focus, malformed requests, clients that leave mid-stream, many clients at once, memory,
a second view on the same port, and the scene file edited well and badly. Every loop is bounded
in count; no assertion is about time.

Run by CTest (tests/CMakeLists.txt) with OBSCURA_CLI and OBSCURA_SOURCE_DIR set; exits 77
(skipped) when the CLI was built without the server."""

import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from view_client import ViewServer, command_arguments, decode_png  # noqa: E402

CLI = os.environ["OBSCURA_CLI"]
SOURCE = os.environ["OBSCURA_SOURCE_DIR"]
WIDTH, HEIGHT = 160, 90
# The measured Cornell box's back wall is the plane z = 559.2 mm; its published camera stands at
# z = -0.8 m looking along +z, so every pixel on that wall is 1.3592 m deep along the axis.
BACK_WALL_DEPTH_M = 0.5592 + 0.8


# Every setting of the page back to the scene's camera (position aside).
RESET = {"f_number": None, "focus_distance_m": None, "focal_length_mm": None, "exposure_ev": None,
         "shutter_s": None, "iso": None, "physical_exposure": None, "lens": None, "sensor": None,
         "size": None}


def base_args(*extra):
    return ["cornell-box", "--width", str(WIDTH), "--height", str(HEIGHT), "--spp", "4",
            "--threads", "2", *extra]


def test_token_is_required(view):
    assert view.request("GET", "/", token=False)[0] == 403
    assert view.request("GET", "/api/state", token=False)[0] == 403
    assert view.request("GET", "/api/events", token=False)[0] == 403
    assert view.request("GET", "/api/frame", token=False)[0] == 403
    assert view.request("POST", "/api/camera", body="{}", token=False)[0] == 403
    assert view.request("GET", "/?token=" + "0" * 32, token=False)[0] == 403
    assert view.request("GET", "/?token=" + view.token[:-1], token=False)[0] == 403
    # The token in a header does as well as in the address.
    assert view.request("GET", "/api/state", token=False,
                        headers={"X-Obscura-Token": view.token})[0] == 200
    # Another name for this address (DNS rebinding) is refused even with the token.
    assert view.request("GET", "/", headers={"Host": "attacker.example:%d" % view.port})[0] == 403


def test_serves_only_its_page(view):
    status, headers, body = view.request("GET", "/")
    assert status == 200 and b"view.js?token=" + view.token.encode() in body
    assert "default-src 'self'" in headers.get("Content-Security-Policy", "")
    assert view.request("GET", "/view.js")[0] == 200
    assert view.request("GET", "/view.css")[0] == 200
    for path in ["/etc/passwd", "/../CMakeLists.txt", "/%2e%2e/%2e%2e/etc/passwd",
                 "/view_page/index.html", "/index.html", "/app/view_page/view.js",
                 "/scenes/cornell-box.json", "/api/frame/../../etc/passwd"]:
        status = view.request("GET", path)[0]
        assert status in (400, 404), (path, status)


def test_camera_move_renders_again(view):
    state = view.wait_frame()
    frame = state["frame"]
    assert frame["renderer"] == "path" and frame["samples"] == frame["samples_target"] == 4
    assert (frame["width"], frame["height"]) == (WIDTH, HEIGHT)
    _, before = view.frame_png()
    w, h, _, pixels_before = decode_png(before)
    assert (w, h) == (WIDTH, HEIGHT)
    camera = frame["camera"]
    generation = view.move({"position": [camera["position"][0] + 0.15, camera["position"][1] + 0.05,
                                         camera["position"][2]],
                            "target": camera["target"], "up": [0, 1, 0]})
    state = view.wait_frame(generation=generation)
    assert state["frame"]["generation"] == generation
    assert "--position" in state["frame"]["command"]
    _, after = view.frame_png()
    assert decode_png(after)[3] != pixels_before
    for aov in ["depth", "normal", "id", "raster"]:
        assert decode_png(view.frame_png(aov)[1])[:2] == (WIDTH, HEIGHT)
    assert view.request("GET", "/api/frame?view=albedo")[0] == 404


def test_copied_command_reproduces_the_frame(view, workdir):
    view.move({"focal_length_mm": 28.5, "f_number": 4, "focus_distance_m": 1.1,
               "exposure_ev": 0.5, "position": [0.3, 0.31, -0.7], "target": [0.25, 0.25, 0.3],
               "up": [0.05, 1, 0]})
    state = view.wait_frame()
    command = state["frame"]["command"]
    _, served = view.frame_png()
    output = os.path.join(workdir, "copied.png")
    result = subprocess.run([CLI, "render", *command_arguments(command), "-q", "-o", output],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, (command, result.stderr)
    with open(output, "rb") as f:
        rendered = decode_png(f.read())
    assert rendered == decode_png(served), "the copied command renders another frame: " + command
    print("  copied command:", command)


def render_copied_command(state, workdir, name):
    output = os.path.join(workdir, name)
    result = subprocess.run([CLI, "render", *command_arguments(state["frame"]["command"]), "-q",
                             "-o", output], capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, (state["frame"]["command"], result.stderr)
    with open(output, "rb") as f:
        return decode_png(f.read())


def test_lens_sensor_aspect_and_exposure(view, workdir):
    # A lens system sets its own focal length: the one set before is given back to it.
    view.move(dict(RESET, lens="double-gauss-50mm", sensor="36x24", size=[96, 64], iso=400,
                   shutter_s=0.01, physical_exposure=True, f_number=4))
    state = view.wait_frame()
    frame = state["frame"]
    assert (frame["width"], frame["height"]) == (96, 64)
    for words in ["--lens double-gauss-50mm", "--sensor 36x24", "--width 96 --height 64",
                  "--iso 400", "--shutter 0:0.01", "--exposure-mode physical"]:
        assert words in frame["command"], (words, frame["command"])
    assert frame["camera"]["resolved"]["projection"] == "lens-system"
    assert render_copied_command(state, workdir, "lens.png") == decode_png(view.frame_png()[1])
    # Back to the thin lens and the size the view started with.
    view.move(dict(RESET, lens="thin"))
    frame = view.wait_frame()["frame"]
    assert (frame["width"], frame["height"]) == (WIDTH, HEIGHT)
    assert "--lens" not in frame["command"]


def test_camera_exports(view):
    view.wait_frame()
    for name, expected in [("opencv-yaml", "camera_matrix"), ("opencv-json", "camera_matrix"),
                           ("nerf", "transform_matrix"), ("colmap", "PINHOLE")]:
        status, _, body = view.request("GET", "/api/export?format=" + name)
        assert status == 200, (name, body)
        assert expected in json.loads(body)["text"], (name, body[:300])
    assert view.request("GET", "/api/export?format=../../etc/passwd")[0] == 400


def test_save_writes_the_frame_shown(view, workdir):
    view.wait_frame()
    status, _, body = view.request("POST", "/api/save")
    assert status == 200, body
    path = json.loads(body)["path"]
    assert path == os.path.join(workdir, "saved.png")
    with open(path, "rb") as f:
        saved = f.read()
    assert decode_png(saved) == decode_png(view.frame_png()[1])
    # The file names the command that renders the frame whole.
    assert b"obscura render cornell-box" in saved
    assert "-o" not in command_arguments(view.state()["frame"]["command"])


def test_click_to_focus(view):
    view.move(dict(RESET, position=[0.278, 0.273, -0.8], target=[0.278, 0.273, 0.2], up=[0, 1, 0]))
    view.wait_frame(final=False)
    status, _, body = view.request("POST", "/api/focus",
                                   body=json.dumps({"x": WIDTH / 2, "y": HEIGHT * 0.3}))
    assert status == 200, body
    depth = json.loads(body)["depth_m"]
    assert abs(depth - BACK_WALL_DEPTH_M) < 0.01 * BACK_WALL_DEPTH_M, depth
    state = view.wait_frame()
    resolved = state["frame"]["camera"]["resolved"]
    assert resolved["depth_of_field"] and resolved["focus_distance_m"] == depth
    # Outside the frame there is nothing to focus on.
    assert view.request("POST", "/api/focus", body='{"x": -5, "y": 3}')[0] == 404


def test_malformed_requests_are_refused(view):
    for body in ["", "nonsense", "[]", '{"position": [1, 2]}', '{"position": "1,2,3"}',
                 '{"focal_length_mm": -3}', '{"f_number": 1e400}', '{"exposure_ev": 1000}',
                 '{"position": [NaN, 0, 0]}', '{"scene": "/etc/passwd"}', '{"unknown": 1}',
                 '{"focus_distance_m": "far"}', '{"position": [1e300, 0, 0]}',
                 '{"lens": "/etc/passwd"}', '{"lens": 3}', '{"sensor": "36x1000"}',
                 '{"sensor": "36x24; rm -rf"}', '{"size": [10, 10]}', '{"size": [640.5, 360]}',
                 '{"size": [100000, 100]}', '{"iso": 0}', '{"shutter_s": 1000}',
                 '{"physical_exposure": "yes"}']:
        status, _, answer = view.request("POST", "/api/camera", body=body)
        assert status == 400, (body, status, answer)
        assert "error" in json.loads(answer)
    for body in ["", "{}", '{"x": "a", "y": 1}', "[1, 2]"]:
        assert view.request("POST", "/api/focus", body=body)[0] == 400, body
    assert view.request("GET", "/api/depth?x=zz&y=1")[0] == 400
    # A body larger than the server takes.
    assert view.request("POST", "/api/camera", body="{" + " " * 100000 + "}")[0] == 413
    # Not HTTP at all, a request cut short, a header far too long: the connection ends, the
    # server goes on.
    for raw in [b"GARBAGE\r\n\r\n", b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n",
                b"GET /?token=" + b"x" * 20000 + b" HTTP/1.1\r\n\r\n",
                b"POST /api/camera HTTP/1.1\r\nContent-Length: 99999999999\r\n\r\n{"]:
        with socket.create_connection(("127.0.0.1", view.port), timeout=10) as s:
            s.sendall(raw)
            s.shutdown(socket.SHUT_WR)
            try:
                s.recv(4096)
            except OSError:
                pass
    assert view.request("GET", "/api/state")[0] == 200


def test_clients_leaving_mid_stream(view):
    request = ("GET /api/events?token=%s HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n"
               % (view.token, view.port)).encode()
    for _ in range(20):
        with socket.create_connection(("127.0.0.1", view.port), timeout=10) as s:
            s.sendall(request)
            # The status line, then gone; streams whose clients just left may still hold their
            # places for a second, so a refusal (503) is an answer too.
            head = s.recv(64)
            assert b"200" in head or b"503" in head, head
    # A frame download cut short.
    for _ in range(10):
        with socket.create_connection(("127.0.0.1", view.port), timeout=10) as s:
            s.sendall(("GET /api/frame?token=%s HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n"
                       % (view.token, view.port)).encode())
            s.recv(16)
    # More streams at once than the server keeps: the extra ones are told so.
    streams, refused = [], 0
    for _ in range(10):
        s = socket.create_connection(("127.0.0.1", view.port), timeout=10)
        s.sendall(request)
        head = s.recv(64)
        refused += b"503" in head
        streams.append(s)
    for s in streams:
        s.close()
    assert refused > 0
    assert view.request("GET", "/api/state")[0] == 200
    # Streams closed, new ones are taken again (the server noticed the others leave).
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        with socket.create_connection(("127.0.0.1", view.port), timeout=10) as s:
            s.sendall(request)
            if b"200" in s.recv(64):
                break
        time.sleep(0.5)
    else:
        raise AssertionError("event streams are still refused after their clients left")


def test_many_clients_at_once(view):
    statuses = []
    lock = threading.Lock()

    def client():
        for path in ["/api/state", "/api/frame", "/view.js"]:
            status = view.request("GET", path, timeout=120)[0]
            with lock:
                statuses.append(status)

    threads = [threading.Thread(target=client) for _ in range(100)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(300)
    assert len(statuses) == 300 and set(statuses) == {200}, set(statuses)


def test_memory_stays_bounded(view):
    if os.environ.get("OBSCURA_SANITIZED") == "1":
        # AddressSanitizer keeps freed blocks in a quarantine of up to 256 MiB to catch use after
        # free, so resident memory grows by design there; the Release run measures the server.
        print("  not measured under AddressSanitizer (its quarantine holds freed memory)")
        return
    def round_of_moves(n):
        for i in range(n):
            view.move({"position": [0.278 + 0.01 * (i % 7), 0.273, -0.8], "target": [0.278, 0.273, 0.2]})
            view.wait_frame(final=False)
            view.frame_png()
            view.frame_png("depth")
        view.wait_frame()

    round_of_moves(15)
    first = view.rss_kib()
    round_of_moves(30)
    second = view.rss_kib()
    print("  resident memory: %d KiB after 15 moves, %d KiB after 45" % (first, second))
    assert second < first * 1.25 + 32 * 1024, (first, second)


def test_second_view_on_the_same_port(view):
    result = subprocess.run([CLI, "view", "--port", str(view.port), *base_args()],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode != 0
    assert "in use" in result.stderr and str(view.port) in result.stderr, result.stderr


def test_request_rate_is_bounded():
    view = ViewServer(CLI, base_args("--max-requests-per-second", "20"))
    try:
        statuses = [view.request("GET", "/api/state")[0] for _ in range(60)]
        assert 429 in statuses and statuses.count(200) <= 40, statuses
        time.sleep(1.1)
        assert view.request("GET", "/api/state")[0] == 200
        # The view's own options are not offered to `obscura render`.
        assert "--max-requests-per-second" not in json.dumps(view.state())
    finally:
        assert view.stop() == 0


def edge_width(row, edge, low, high):
    """The 10–90 % rise of an edge from `low` to `high` around pixel `edge`, in pixels."""
    def crossing(level):
        for x in range(edge - 25, edge + 25):
            a, b = row[x], row[x + 1]
            if (a - level) * (b - level) <= 0 and a != b:
                return x + (level - a) / (b - a)
        raise AssertionError("no crossing of %s near %d" % (level, edge))
    return abs(crossing(low + 0.9 * (high - low)) - crossing(low + 0.1 * (high - low)))


def test_the_f_number_sets_the_blur():
    # The rasterizer (depth of field from 32 accumulated lens positions, no noise), focused on the
    # back wall: an edge nearer the camera is blurred by a circle of confusion whose diameter is
    # the aperture's, f / N (thin lens): halving N doubles its width.
    view = ViewServer(CLI, ["cornell-box", "--width", "640", "--height", "360", "--renderer",
                            "raster"])
    try:
        def middle_row(camera):
            view.wait_frame(generation=view.move(camera))
            w, h, c, pixels = decode_png(view.frame_png()[1])
            y = int(h * 0.45)
            return [sum(pixels[(y * w + x) * c + k] for k in range(3)) / 3 for x in range(w)]

        sharp = middle_row({"f_number": None, "focus_distance_m": None})
        # The strongest edge between two lit surfaces (not the box's rim against the dark).
        edge = max((x for x in range(40, len(sharp) - 40) if min(sharp[x], sharp[x + 1]) > 20),
                   key=lambda x: abs(sharp[x + 1] - sharp[x]))
        low, high = sorted([sum(sharp[edge - 20:edge - 10]) / 10, sum(sharp[edge + 11:edge + 21]) / 10])
        widths = {}
        for n in [1.4, 0.7]:
            widths[n] = edge_width(middle_row({"f_number": n, "focus_distance_m": BACK_WALL_DEPTH_M}),
                                   edge, low, high)
        ratio = widths[0.7] / widths[1.4]
        print("  edge at x=%d: 10-90%% width %.2f px at f/1.4, %.2f px at f/0.7 (ratio %.2f)"
              % (edge, widths[1.4], widths[0.7], ratio))
        assert widths[1.4] > 1.5 and 1.5 < ratio < 2.5, widths
    finally:
        assert view.stop() == 0


def test_scene_file_edits(workdir):
    scene = os.path.join(workdir, "box.json")
    with open(os.path.join(SOURCE, "scenes", "cornell-box.json")) as f:
        text = f.read().replace('"assets/', '"' + os.path.join(SOURCE, "scenes", "assets") + "/")
    with open(scene, "w") as f:
        f.write(text)
    view = ViewServer(CLI, [scene, "--width", "64", "--height", "64", "--spp", "1"])
    try:
        first = view.wait_frame()["frame"]
        with open(scene, "w") as f:
            f.write(text.replace("39.307648", "60"))
        deadline = time.monotonic() + 120
        while view.state()["frame"]["generation"] == first["generation"]:
            assert time.monotonic() < deadline, "the edit was not loaded"
            time.sleep(0.1)
        state = view.wait_frame()
        assert state["message"] == ""
        assert state["frame"]["camera"]["resolved"]["fov_degrees"][1] > 59
        with open(scene, "w") as f:
            f.write('{"objects": [ this is not JSON')
        deadline = time.monotonic() + 120
        while not view.state()["message"]:
            assert time.monotonic() < deadline, "the broken edit was not reported"
            time.sleep(0.1)
        message = view.state()["message"]
        assert "did not load" in message and "box.json" in message, message
        assert view.alive() and view.frame_png()[1][:4] == b"\x89PNG"
        with open(scene, "w") as f:
            f.write(text)
        deadline = time.monotonic() + 120
        while view.state()["message"]:
            assert time.monotonic() < deadline, "the repaired scene was not loaded"
            time.sleep(0.1)
        assert view.alive()
    finally:
        assert view.stop() == 0, "".join(view.stderr_lines)


def main():
    probe = subprocess.run([CLI, "view", "--help"], capture_output=True, text=True)
    if probe.returncode != 0:
        print("skipped: this obscura has no view command")
        return 77
    workdir = tempfile.mkdtemp(prefix="obscura-view-test-")
    view = ViewServer(CLI, base_args("-o", os.path.join(workdir, "saved.png")))
    passed = failed = 0
    try:
        tests = [(name, fn) for name, fn in globals().items() if name.startswith("test_")]
        for name, fn in tests:
            args = []
            for parameter in fn.__code__.co_varnames[:fn.__code__.co_argcount]:
                args.append(view if parameter == "view" else workdir)
            try:
                fn(*args)
                assert view.alive(), "the server died"
                print("PASS", name)
                passed += 1
            except Exception as e:  # report every test, then fail
                import traceback
                traceback.print_exc()
                print("FAIL", name, e)
                failed += 1
    finally:
        status = view.stop()
        shutil.rmtree(workdir, ignore_errors=True)
    if status != 0:
        print("FAIL the server ended with status", status, "".join(view.stderr_lines))
        failed += 1
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
