"""Colour on arrays: the public colour vectors (tests/data/color/vectors-public.json, computed by
colorjs.io, an independent implementation), develop() against the sRGB formula, bad input."""

import json
from collections import defaultdict

import numpy as np
import pytest

import obscura
from conftest import SOURCE_DIR

VECTORS = json.loads((SOURCE_DIR / "tests/data/color/vectors-public.json").read_text())["records"]


def within_tolerance(actual, record):
    """The file's rule: |actual - expected| <= abs[i] + rel * |expected|; abs None = not
    compared; hues (in degrees) circularly."""
    tol = record["tolerance"]
    for i, (a, e) in enumerate(zip(actual, record["expected"])):
        if tol["abs"][i] is None or e is None:
            continue
        diff = abs(a - e)
        if "lch" in record["output_space"] and i == 2:
            diff = min(diff, 360 - diff)
        if diff > tol["abs"][i] + tol["rel"] * abs(e):
            return False
    return True


def convert_groups():
    groups = defaultdict(list)
    for r in VECTORS:
        if r["op"] == "convert" and obscura_knows(r["input_space"]) and obscura_knows(r["output_space"]):
            groups[(r["input_space"], r["output_space"])].append(r)
    return groups


def obscura_knows(space):
    return space in obscura.color_spaces()


GROUPS = convert_groups()


def test_the_vectors_cover_many_space_pairs():
    assert len(GROUPS) >= 40


@pytest.mark.parametrize("pair", sorted(GROUPS), ids=lambda p: f"{p[0]}>{p[1]}")
def test_array_conversion_reproduces_the_public_vectors(pair):
    records = GROUPS[pair]
    values = np.array([r["input"] for r in records], dtype=np.float64)
    converted = obscura.convert(values, *pair)
    assert converted.shape == (len(records), len(records[0]["expected"]))
    failures = [r["id"] for r, row in zip(records, converted) if not within_tolerance(row, r)]
    assert not failures
    # The same in float32, and any leading shape: one row per record, in a (1, N, 3) image. The
    # float32 path computes in double from the float32 inputs and rounds only the result.
    single = values.astype(np.float32)
    as_image = obscura.convert(single[None], *pair)
    assert as_image.dtype == np.float32 and as_image.shape == (1,) + converted.shape
    np.testing.assert_array_equal(as_image[0],
                                  obscura.convert(single.astype(np.float64), *pair).astype(np.float32))


def spectral(input_space, output_space):
    return [r for r in VECTORS if r["op"] == "spectral" and r["input_space"] == input_space
            and r["output_space"] == output_space]


def test_wavelength_and_blackbody_colours_reproduce_the_vectors():
    records = spectral("wavelength-nm", "xyz-cmf-1931")
    assert records
    xyz = obscura.wavelength_xyz(np.array([r["input"][0] for r in records], dtype=np.float64))
    assert all(within_tolerance(row, r) for row, r in zip(xyz, records))
    records = spectral("wavelength-nm", "lms-stockman-sharpe-2deg")
    lms = obscura.wavelength_lms(np.array([r["input"][0] for r in records], dtype=np.float64))
    assert all(within_tolerance(row, r) for row, r in zip(lms, records))
    records = spectral("blackbody-kelvin", "xy-1931")
    assert records
    xy = obscura.chromaticity(obscura.blackbody_xyz(
        np.array([r["input"][0] for r in records], dtype=np.float64)))
    assert all(within_tolerance(row, r) for row, r in zip(xy, records))
    assert obscura.wavelength_xyz(555.0).shape == (3,)


def srgb_encode(v):
    return np.where(v <= 0.0031308, 12.92 * v, 1.055 * np.power(v, 1 / 2.4) - 0.055)


def test_develop_encodes_srgb_as_the_formula():
    levels = np.linspace(0, 1, 64, dtype=np.float32)
    image = np.repeat(levels[None, :, None], 3, axis=2)  # (1, 64, 3)
    codes = obscura.develop(image)  # defaults: clamp, sRGB, 8 bits, no dither
    assert codes.dtype == np.uint8 and codes.shape == (1, 64, 3)
    expected = np.floor(srgb_encode(levels.astype(np.float64)) * 255 + 0.5)
    np.testing.assert_array_equal(codes[0, :, 0], expected)
    sixteen = obscura.develop(image, bits=16)
    assert sixteen.dtype == np.uint16
    np.testing.assert_array_equal(sixteen[0, :, 1],
                                  np.floor(srgb_encode(levels.astype(np.float64)) * 65535 + 0.5))
    # one stop of exposure doubles the linear value before encoding
    np.testing.assert_array_equal(obscura.develop(image * 0.5, exposure=1.0), codes)


@pytest.mark.parametrize(
    "call, error",
    [
        (lambda: obscura.convert(np.zeros((4, 3), dtype=np.int32), "srgb", "oklab"), TypeError),
        (lambda: obscura.convert(np.zeros((4, 4)), "srgb", "oklab"), ValueError),
        (lambda: obscura.convert(np.zeros((4, 6))[:, ::2], "srgb", "oklab"), ValueError),
        (lambda: obscura.convert(np.array([[np.nan, 0, 0]]), "srgb", "oklab"), ValueError),
        (lambda: obscura.convert(np.zeros((4, 3)), "srgb", "okhsv"), ValueError),
        (lambda: obscura.convert({"r": 1}, "srgb", "oklab"), TypeError),
        (lambda: obscura.develop(np.zeros((4, 4, 3), dtype=np.float32), tonemap="filmic"), ValueError),
        (lambda: obscura.develop(np.zeros((4, 4, 3), dtype=np.float32), bits=17), ValueError),
        (lambda: obscura.develop(np.zeros((4, 4, 2), dtype=np.float32)), ValueError),
        (lambda: obscura.develop(np.zeros((4, 4, 3), dtype=np.float32), gain=2), TypeError),
        (lambda: obscura.wavelength_xyz(-5.0), ValueError),
    ],
)
def test_bad_colour_input_raises(call, error):
    with pytest.raises(error):
        call()
