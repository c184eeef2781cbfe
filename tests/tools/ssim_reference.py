#!/usr/bin/python3
"""Checks `diptych diff --metrics ssim` against scikit-image's structural_similarity.

Generates structured image pairs (gradients, shapes, noise, blur; several non-square sizes;
LDR and HDR), writes them as PNG (8-bit sRGB) and EXR (float, through PFM and oiiotool), runs
`diptych diff A B --metrics ssim --json` on each pair and compares with

    skimage.metrics.structural_similarity(a, b, gaussian_weights=True, sigma=1.5,
        use_sample_covariance=False, data_range=R, channel_axis=-1)

on the same linear values (PNG decoded with the sRGB transfer function, as diptych does), with
the same explicit data range R. Exits 1 when any pair differs by more than the tolerance.

Usage: ssim_reference.py --diptych PATH --work DIR [--tolerance 1e-4]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

import numpy as np
from PIL import Image
from scipy import ndimage
from skimage.metrics import structural_similarity


def picture(rng, h, w, channels, peak):
    """Reference picture: gradients, discs, rectangles, stripes, a little texture."""
    y, x = np.mgrid[0:h, 0:w].astype(np.float64)
    u, v = x / (w - 1), y / (h - 1)
    img = np.stack([0.15 + 0.7 * u, 0.1 + 0.6 * v, 0.6 - 0.4 * u * v], axis=-1)
    for _ in range(6):
        cx, cy, r = rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0.05, 0.25)
        mask = (u - cx) ** 2 + ((v - cy) * h / w) ** 2 < r * r
        img[mask] = rng.uniform(0, 1, 3)
    for _ in range(4):
        x0, y0 = rng.integers(0, w - 8), rng.integers(0, h - 8)
        img[y0:y0 + rng.integers(4, h // 2), x0:x0 + rng.integers(4, w // 2)] = rng.uniform(0, 1, 3)
    img[((x.astype(int) // 3) % 2 == 0) & (v < 0.1)] *= 0.3  # thin bars along the top
    img += rng.normal(0, 0.02, img.shape)
    img = np.clip(img, 0, 1) * peak
    if peak > 1:  # a few bright highlights, like specular peaks in a render
        for _ in range(3):
            py, px = rng.integers(0, h - 3), rng.integers(0, w - 3)
            img[py:py + 3, px:px + 3] = peak * rng.uniform(3, 8)
    return img[..., :channels] if channels < 3 else img


def distorted(rng, ref, blur, noise, peak):
    """The test image: blurred, noisy, with a shifted patch (a raster approximation's errors)."""
    img = ndimage.gaussian_filter(ref, sigma=(blur, blur, 0)) if blur > 0 else ref.copy()
    img = img + rng.normal(0, noise * peak, img.shape)
    h, w = img.shape[:2]
    img[h // 3:h // 2, w // 4:w // 2] = np.roll(img[h // 3:h // 2, w // 4:w // 2], 3, axis=1)
    return np.clip(img, 0, None) if peak > 1 else np.clip(img, 0, 1)


def srgb_to_linear(c):
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def write_png(path, img):
    """8-bit sRGB PNG; returns the linear values diptych reads back."""
    encoded = np.round(np.clip(img, 0, 1) * 255).astype(np.uint8)
    Image.fromarray(encoded[..., 0] if encoded.shape[-1] == 1 else encoded).save(path)
    return srgb_to_linear(encoded.astype(np.float64) / 255.0)


def write_exr(path, img, oiiotool):
    """Float EXR (PFM written here, converted losslessly by oiiotool); returns float32 values."""
    data = img.astype("<f4")
    pfm = path + ".pfm"
    with open(pfm, "wb") as f:
        kind = b"PF" if data.shape[-1] == 3 else b"Pf"
        f.write(kind + b"\n%d %d\n-1.0\n" % (data.shape[1], data.shape[0]))
        f.write(np.ascontiguousarray(data[::-1]).tobytes())  # PFM stores the bottom row first
    subprocess.run([oiiotool, pfm, "-d", "float", "-o", path], check=True)
    return data.astype(np.float64)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--diptych", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--tolerance", type=float, default=1e-4)
    parser.add_argument("--samples", help="samples/ folder: adds real pairs, renders of the "
                        "sample scenes by the hybrid and the raster recipe")
    args = parser.parse_args()
    oiiotool = shutil.which("oiiotool")
    if not oiiotool:
        sys.exit("ssim_reference: oiiotool (Debian openimageio-tools) is needed to write EXR")
    os.makedirs(args.work, exist_ok=True)
    rng = np.random.default_rng(20240611)

    # (name, height, width, channels, format, peak, blur sigma, noise sigma)
    cases = [
        ("ldr-96x64", 64, 96, 3, "png", 1.0, 1.0, 0.02),
        ("ldr-131x77", 77, 131, 3, "png", 1.0, 0.0, 0.08),
        ("ldr-grey-70x150", 150, 70, 1, "png", 1.0, 2.0, 0.03),
        ("exr-200x120", 120, 200, 3, "exr", 1.0, 1.5, 0.01),
        ("hdr-160x90", 90, 160, 3, "exr", 4.0, 0.7, 0.02),
        ("hdr-53x211", 211, 53, 3, "exr", 16.0, 3.0, 0.005),
    ]
    # Real pairs: the same scene rendered by the raster and by the hybrid recipe (8-bit sRGB
    # PNG, read back and decoded to linear exactly as diptych decodes it).
    real = []
    if args.samples:
        for scene in ("whitted", "cornell-point"):
            paths = []
            for recipe in ("raster", "hybrid"):
                out = os.path.join(args.work, f"real-{scene}-{recipe}.png")
                subprocess.run([args.diptych, "render", os.path.join(args.samples, "scenes", scene + ".json"),
                                "--recipe", os.path.join(args.samples, "graphs", recipe + ".json"),
                                "--size", "160x120", "--frames", "1", "--warmup", "0", "--out", out],
                               check=True, capture_output=True)
                paths.append(out)
            real.append((f"real-{scene}", paths))

    def read_png(path):
        data = np.asarray(Image.open(path).convert("RGB")).astype(np.float64) / 255.0
        return srgb_to_linear(data)

    failures = 0
    print(f"{'case':18} {'data_range':>12} {'diptych':>12} {'skimage':>12} {'|diff|':>10}")
    for name, h, w, ch, fmt, peak, blur, noise in cases + [(n, 0, 0, 3, "real", 0, 0, 0) for n, _ in real]:
        if fmt == "real":
            paths = dict(real)[name]
            a, b = read_png(paths[0]), read_png(paths[1])
        else:
            ref = picture(rng, h, w, ch, peak)
            test = distorted(rng, ref, blur, noise, peak)
            ext = "." + fmt
            paths = [os.path.join(args.work, f"{name}-{k}{ext}") for k in ("test", "ref")]
            write = (lambda p, i: write_png(p, i)) if fmt == "png" else (
                lambda p, i: write_exr(p, i, oiiotool))
            a, b = write(paths[0], test), write(paths[1], ref)
        data_range = float(b.max() - b.min())
        expected = structural_similarity(
            a if ch > 1 else a[..., 0], b if ch > 1 else b[..., 0], gaussian_weights=True,
            sigma=1.5, use_sample_covariance=False, data_range=data_range,
            channel_axis=-1 if ch > 1 else None)
        run = subprocess.run([args.diptych, "diff", paths[0], paths[1], "--metrics", "ssim",
                              "--json", "--ssim-data-range", repr(data_range)],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(f"{name}: diptych failed ({run.returncode}): {run.stderr.strip()}")
            failures += 1
            continue
        got = json.loads(run.stdout)["metrics"]["ssim"]
        # Without an explicit range diptych uses max - min of the reference: check that too.
        default = subprocess.run([args.diptych, "diff", paths[0], paths[1], "--metrics", "ssim",
                                  "--json"], capture_output=True, text=True, check=True)
        default_range = json.loads(default.stdout)["parameters"]["ssim_data_range"]
        diff = abs(got - expected)
        ok = diff <= args.tolerance and abs(default_range - data_range) <= 1e-6 * max(1, data_range)
        failures += not ok
        print(f"{name:18} {data_range:12.6g} {got:12.8f} {expected:12.8f} {diff:10.2e}"
              f"{'' if ok else '  MISMATCH (default range %g)' % default_range}")
    if failures:
        print(f"ssim_reference: {failures} case(s) disagree beyond {args.tolerance}")
        return 1
    print(f"ssim_reference: all {len(cases) + len(real)} cases agree within {args.tolerance}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
