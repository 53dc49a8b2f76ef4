#!/usr/bin/env python3
"""Makes the pictures of docs/color.md with the `obscura` CLI (the colour science is all
Obscura's; this script only lays out test images and calls the CLI).

    python3 docs/figures/make_color_figures.py [path/to/obscura]

Test images are written as PFM (linear Rec.709 floats) into a temporary directory and
developed with `obscura image convert`; the wavelength and blackbody strips come from
`obscura color wavelength/temperature --json`. Output: docs/images/*.png.
"""
import json
import math
import os
import struct
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
OBSCURA = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "obscura")
IMAGES = os.path.join(ROOT, "docs", "images")


def srgb_decode(e):
    """IEC 61966-2-1, only to turn the CLI's encoded swatch colours back into linear light."""
    return e / 12.92 if e <= 0.04045 else ((e + 0.055) / 1.055) ** 2.4


def write_pfm(path, width, height, pixel):
    """pixel(x, y) -> (r, g, b) linear; PFM stores rows bottom to top."""
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (width, height))
        for y in reversed(range(height)):
            row = []
            for x in range(width):
                row.extend(pixel(x, y))
            f.write(struct.pack("<%df" % len(row), *row))


def obscura(*args):
    return subprocess.run([OBSCURA, *args], check=True, capture_output=True, text=True).stdout


def develop(pfm, name, *options):
    obscura("image", "convert", pfm, os.path.join(IMAGES, name), "--quiet", *options)


def main():
    os.makedirs(IMAGES, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix="obscura-figures-")

    # 1. Quantization: a dark-to-light ramp, even in encoded (perceptual) steps.
    ramp = os.path.join(tmp, "ramp.pfm")
    write_pfm(ramp, 768, 40, lambda x, y: [srgb_decode(x / 767)] * 3)
    for bits in (3, 4, 5, 6, 8):
        develop(ramp, "quantize_%dbit.png" % bits, "--bits", str(bits))
    # 2. Dithering at 4 bits (16 levels): banding, then ordered and blue-noise dither.
    for dither in ("none", "bayer", "blue-noise"):
        develop(ramp, "dither_4bit_%s.png" % dither, "--bits", "4", "--dither", dither)

    # 3. Tone mapping: bands of colour, exposure rising left to right over 12 stops.
    hues = [(1, 1, 1), (1, 0.05, 0.02), (1, 0.45, 0.05), (0.3, 1, 0.1), (0.05, 0.6, 1), (0.1, 0.1, 1)]
    hdr = os.path.join(tmp, "hdr.pfm")
    write_pfm(hdr, 768, 6 * 24, lambda x, y: [c * 2 ** (x / 767 * 12 - 7) for c in hues[y // 24]])
    for op in ("clamp", "reinhard", "aces", "hable"):
        develop(hdr, "tonemap_%s.png" % op, "--tonemap", op, "--reinhard-white", "16")

    # 4. Spectral colours, 380-780 nm: the displayable sRGB colour of each wavelength
    #    (brightest channel scaled to 1, chroma reduced in OKLCh until it fits).
    strip = []
    for nm in range(380, 781, 2):
        strip.append(json.loads(obscura("color", "wavelength", str(nm), "--json"))["displayable_srgb"])
    wl = os.path.join(tmp, "wavelengths.pfm")
    write_pfm(wl, len(strip) * 4, 48, lambda x, y: [srgb_decode(c) for c in strip[x // 4]])
    develop(wl, "wavelength_strip.png")

    # 5. Blackbody colours, 1000-12000 K.
    temps = list(range(1000, 12001, 250))
    swatches = [json.loads(obscura("color", "temperature", str(k), "--json"))["displayable_srgb"]
                for k in temps]
    bb = os.path.join(tmp, "blackbody.pfm")
    write_pfm(bb, len(swatches) * 16, 48, lambda x, y: [srgb_decode(c) for c in swatches[x // 16]])
    develop(bb, "blackbody_strip.png")

    # 6. Gamut: saturated Rec.2020 colours on an sRGB display, clipped vs compressed.
    r2020 = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 1, 1), (1, 0, 1), (1, 1, 0), (0.2, 0.8, 0.5)]
    lin709 = []
    for rgb in r2020:
        out = obscura("color", "convert", "--from", "rec2020-linear", "--to", "srgb-linear", *map(str, rgb))
        lin709.append([float(v) for v in out.splitlines()[0].split()])
    gamut = os.path.join(tmp, "gamut.pfm")
    write_pfm(gamut, len(lin709) * 48, 48, lambda x, y: lin709[x // 48])
    for mapping in ("clip", "compress"):
        develop(gamut, "gamut_%s.png" % mapping, "--gamut", mapping, "--tonemap", "none")
    print("figures written to", IMAGES)


if __name__ == "__main__":
    main()
