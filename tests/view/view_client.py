"""A client of `obscura view` for the tests: starts the server, speaks its HTTP API over loopback,
decodes the PNG frames it serves. Standard library only."""

import http.client
import json
import os
import re
import struct
import subprocess
import threading
import time
import urllib.parse
import zlib

URL_PATTERN = re.compile(r"^http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]{32})$")


class ViewServer:
    """`obscura view ARGS` running in the background; stop() ends it (SIGTERM)."""

    def __init__(self, cli, args, cwd=None, start_timeout=120):
        self.process = subprocess.Popen([cli, "view", *args], stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, text=True, cwd=cwd)
        self.stderr_lines = []
        threading.Thread(target=self._drain_stderr, daemon=True).start()
        line = self._read_line(start_timeout)
        match = URL_PATTERN.match(line.strip())
        if not match:
            self.stop()
            raise AssertionError("obscura view printed %r, not its address; stderr: %s"
                                 % (line, "".join(self.stderr_lines)))
        self.url = line.strip()
        self.port = int(match.group(1))
        self.token = match.group(2)

    def _drain_stderr(self):
        for line in self.process.stderr:
            self.stderr_lines.append(line)

    def _read_line(self, timeout):
        result = []
        reader = threading.Thread(target=lambda: result.append(self.process.stdout.readline()),
                                  daemon=True)
        reader.start()
        reader.join(timeout)
        return result[0] if result else ""

    def request(self, method, path, body=None, token=True, headers=None, timeout=60):
        """(status, headers, body bytes) of one request on a new connection."""
        if token:
            path += ("&" if "?" in path else "?") + "token=" + self.token
        connection = http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)
        try:
            connection.request(method, path, body=body, headers=headers or {})
            response = connection.getresponse()
            return response.status, dict(response.getheaders()), response.read()
        finally:
            connection.close()

    def state(self):
        status, _, body = self.request("GET", "/api/state")
        assert status == 200, (status, body)
        return json.loads(body)

    def move(self, camera):
        status, _, body = self.request("POST", "/api/camera", body=json.dumps(camera),
                                       headers={"Content-Type": "application/json"})
        assert status == 200, (status, body)
        return json.loads(body)["generation"]

    def wait_frame(self, final=True, generation=None, timeout=300):
        """The state once the latest frame is of the current camera (and final, if asked)."""
        start = time.monotonic()
        deadline = start + timeout
        while time.monotonic() < deadline:
            state = self.state()
            # A camera the scene cannot take is reported, not rendered: no use waiting.
            if state.get("message") and time.monotonic() > start + 5:
                raise AssertionError("the server says: " + state["message"])
            frame = state.get("frame")
            if frame and frame["generation"] == state["current_generation"] and \
                    (generation is None or frame["generation"] >= generation) and \
                    (frame["final"] or not final):
                return state
            time.sleep(0.05)
        raise AssertionError("no frame within %s s; last state %s" % (timeout, state))

    def frame_png(self, view="beauty"):
        status, headers, body = self.request("GET", "/api/frame?view=" + view)
        assert status == 200, (status, body[:200])
        return int(headers["X-Obscura-Event"]), body

    def rss_kib(self):
        with open("/proc/%d/status" % self.process.pid) as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
        return 0

    def alive(self):
        return self.process.poll() is None

    def stop(self):
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(30)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        return self.process.returncode


def decode_png(data):
    """(width, height, channels, pixel bytes) of an 8-bit grey, RGB or RGBA PNG."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
        elif kind == b"IEND":
            break
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and interlace == 0, "only 8-bit, non-interlaced PNGs"
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
    raw = zlib.decompress(idat)
    stride = width * channels
    out = bytearray(height * stride)
    previous = bytearray(stride)
    pos = 0
    for y in range(height):
        kind = raw[pos]
        line = bytearray(raw[pos + 1:pos + 1 + stride])
        pos += 1 + stride
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            corner = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc
                                      else corner)) & 255
        out[y * stride:(y + 1) * stride] = line
        previous = line
    return width, height, channels, bytes(out)


def command_arguments(command):
    """The arguments of the "obscura render …" line the page copies."""
    import shlex
    words = shlex.split(command)
    assert words[:2] == ["obscura", "render"], command
    return words[2:]
