"""`obscura render --display-server HOST:PORT`: a small listener speaking tev's display-server
protocol (create image, update image v3) receives the frame and its AOVs: channel names, sizes,
and pixel values equal to the PFM file the same render writes. Bounded: one connection, a
deadline on every read. Run by CTest with OBSCURA_CLI set."""

import os
import socket
import struct
import subprocess
import sys
import tempfile
import threading

CLI = os.environ["OBSCURA_CLI"]
WIDTH, HEIGHT = 150, 70  # more than one 128-pixel tile across


def read_string(data, pos):
    end = data.index(b"\0", pos)
    return data[pos:end].decode(), end + 1


def parse_messages(data):
    messages, pos = [], 0
    while pos < len(data):
        length = struct.unpack_from("<I", data, pos)[0]
        body, kind = data[pos + 5:pos + length], data[pos + 4]
        pos += length
        p = 0
        if kind == 4:
            grab = body[0]
            name, p = read_string(body, 1)
            width, height, count = struct.unpack_from("<iii", body, p)
            p += 12
            channels = []
            for _ in range(count):
                channel, p = read_string(body, p)
                channels.append(channel)
            messages.append({"type": "create", "grab": grab, "name": name, "width": width,
                             "height": height, "channels": channels})
        elif kind == 6:
            name, p = read_string(body, 1)
            count = struct.unpack_from("<i", body, p)[0]
            p += 4
            channels = []
            for _ in range(count):
                channel, p = read_string(body, p)
                channels.append(channel)
            x, y, w, h = struct.unpack_from("<iiii", body, p)
            p += 16
            offsets = struct.unpack_from("<%dq" % count, body, p)
            p += 8 * count
            strides = struct.unpack_from("<%dq" % count, body, p)
            p += 8 * count
            values = struct.unpack_from("<%df" % (w * h * count), body, p)
            assert p + 4 * w * h * count == len(body), "trailing bytes in an update"
            messages.append({"type": "update", "name": name, "channels": channels, "x": x, "y": y,
                             "w": w, "h": h, "offsets": offsets, "strides": strides,
                             "values": values})
        else:
            raise AssertionError("unexpected message type %d" % kind)
    return messages


def read_pfm(path):
    with open(path, "rb") as f:
        data = f.read()
    header, pos = [], 0
    while len(header) < 3:
        end = data.index(b"\n", pos)
        header.append(data[pos:end].decode().strip())
        pos = end + 1
    assert header[0] == "PF"
    width, height = map(int, header[1].split())
    scale = float(header[2])
    values = struct.unpack_from(("<" if scale < 0 else ">") + "%df" % (width * height * 3), data, pos)
    # PFM rows run bottom to top.
    return width, height, lambda x, y, c: values[((height - 1 - y) * width + x) * 3 + c]


def main():
    listener = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    listener.bind(("127.0.0.1", 0))
    listener.listen(1)
    listener.settimeout(300)
    port = listener.getsockname()[1]
    received = bytearray()

    def serve():
        connection, _ = listener.accept()
        connection.settimeout(300)
        with connection:
            while True:
                chunk = connection.recv(1 << 16)
                if not chunk:
                    break
                received.extend(chunk)

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    work = tempfile.mkdtemp(prefix="obscura-tev-test-")
    output = os.path.join(work, "frame.pfm")
    result = subprocess.run([CLI, "render", "cornell-box", "--width", str(WIDTH), "--height",
                             str(HEIGHT), "--spp", "2", "--aovs", "-q", "-o", output,
                             "--display-server", "127.0.0.1:%d" % port],
                            capture_output=True, text=True, timeout=600)
    thread.join(300)
    failures = []

    def check(condition, message):
        if not condition:
            failures.append(message)

    check(result.returncode == 0, "render failed: " + result.stderr)
    check("warning" not in result.stderr, "render warned: " + result.stderr)
    messages = parse_messages(bytes(received))
    create = messages[0]
    check(create["type"] == "create" and create["name"] == output, create)
    check((create["width"], create["height"]) == (WIDTH, HEIGHT), create)
    expected = ["R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y",
                "normal.Z", "depth.Z", "range", "id"]
    check(create["channels"] == expected, "channels %s" % create["channels"])
    updates = messages[1:]
    check(len(updates) == 2, "%d updates, expected 2 tiles" % len(updates))
    covered = sum(u["w"] * u["h"] for u in updates)
    check(covered == WIDTH * HEIGHT, "the tiles cover %d pixels" % covered)
    width, height, pixel = read_pfm(output)
    count = len(expected)
    mismatches = 0
    for u in updates:
        check(u["channels"] == expected and list(u["offsets"]) == list(range(count)) and
              list(u["strides"]) == [count] * count, "update layout")
        for j in range(u["h"]):
            for i in range(u["w"]):
                base = (j * u["w"] + i) * count
                for c in range(3):
                    if u["values"][base + c] != pixel(u["x"] + i, u["y"] + j, c):
                        mismatches += 1
    check(mismatches == 0, "%d RGB values differ from the PFM file" % mismatches)
    # The back wall, in the middle a third of the way down, is 1.3592 m deep along the axis.
    for u in updates:
        x, y = WIDTH // 2 - u["x"], HEIGHT // 3 - u["y"]
        if 0 <= x < u["w"] and 0 <= y < u["h"]:
            depth = u["values"][(y * u["w"] + x) * count + expected.index("depth.Z")]
            check(abs(depth - 1.3592) < 0.01, "depth %s at the back wall" % depth)
    # Nothing listening: the image is still written, with a warning.
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        free_port = probe.getsockname()[1]
    nobody = subprocess.run([CLI, "render", "cornell-box", "--width", "8", "--height", "8",
                             "--spp", "1", "-q", "-o", os.path.join(work, "alone.png"),
                             "--display-server", "127.0.0.1:%d" % free_port],
                            capture_output=True, text=True, timeout=600)
    check(nobody.returncode == 0 and "cannot connect" in nobody.stderr, nobody.stderr)
    check(os.path.exists(os.path.join(work, "alone.png")), "the image was not written")
    bad = subprocess.run([CLI, "render", "--display-server", "nonsense", "-o",
                          os.path.join(work, "bad.png")], capture_output=True, text=True)
    check(bad.returncode == 2 and "HOST:PORT" in bad.stderr, bad.stderr)
    for f in failures:
        print("FAIL", f)
    print("%d passed, %d failed" % (1 if not failures else 0, 1 if failures else 0))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
