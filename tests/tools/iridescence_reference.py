#!/usr/bin/env python3
"""Reference values of the KHR_materials_iridescence thin-film Fresnel, for tests/unit/test_pbr.cpp
(PbrFilm.MatchesThePythonReference). Written from the extension spec's implementation notes
(Belcour & Barla 2017 in the spec's approximate form), in double precision, independently of
shaders/common/pbr.glsl: Schlick at both interfaces, phase shifts 0 or pi, optical path difference
2 n_film d cos(theta2), the Airy sum to m = 2 with the spec's Gaussian XYZ fits in Fourier space,
XYZ -> linear sRGB. Usage: python3 tests/tools/iridescence_reference.py
"""
import math


def schlick(f0, c):
    return f0 + (1.0 - f0) * (1.0 - c) ** 5


def ior_to_f0(n_t, n_i):
    return ((n_t - n_i) / (n_t + n_i)) ** 2


def f0_to_ior(f0):
    s = math.sqrt(min(max(f0 + 1e-4, 0.0), 0.9999))
    return (1.0 + s) / (1.0 - s)


def sensitivity(opd_nm, shift):
    """Linear sRGB of one Airy order: XYZ Gaussians at 2 pi opd (Fourier), XYZ -> Rec. 709."""
    phase = 2.0 * math.pi * opd_nm * 1e-9
    val = (5.4856e-13, 4.4201e-13, 5.2481e-13)
    pos = (1.6810e6, 1.7953e6, 2.2084e6)
    var = (4.3278e9, 9.3046e9, 6.6121e9)
    xyz = [val[k] * math.sqrt(2 * math.pi * var[k]) * math.cos(pos[k] * phase + shift[k])
           * math.exp(-phase * phase * var[k]) for k in range(3)]
    xyz[0] += (9.7470e-14 * math.sqrt(2 * math.pi * 4.5282e9) * math.cos(2.2399e6 * phase + shift[0])
               * math.exp(-4.5282e9 * phase * phase))
    xyz = [x / 1.0685e-7 for x in xyz]
    m = ((3.2404542, -1.5371385, -0.4985314),
         (-0.9692660, 1.8760108, 0.0415560),
         (0.0556434, -0.2040259, 1.0572252))
    return [sum(m[r][k] * xyz[k] for k in range(3)) for r in range(3)]


def film_fresnel(film_ior, base_f0, thickness_nm, cos1):
    n1, n2 = 1.0, film_ior
    cos2 = math.sqrt(1.0 - (n1 / n2) ** 2 * (1.0 - cos1 * cos1))
    r12 = schlick(ior_to_f0(n2, n1), cos1)
    t121 = 1.0 - r12
    phi12 = math.pi if n2 < n1 else 0.0
    phi21 = math.pi - phi12
    opd = 2.0 * n2 * thickness_nm * cos2
    out = []
    per_channel = []
    for f0 in base_f0:
        n3 = f0_to_ior(f0)
        r23 = schlick(ior_to_f0(n3, n2), cos2)
        phi23 = math.pi if n3 < n2 else 0.0
        r123sq = min(max(r12 * r23, 1e-5), 0.9999)
        rs = t121 * t121 * r23 / (1.0 - r123sq)
        per_channel.append((r12 + rs, rs - t121, math.sqrt(r123sq), phi21 + phi23))
    total = [c0 for c0, _, _, _ in per_channel]
    for m in (1, 2):
        s = [sensitivity(m * opd, [m * ch[3] for ch in per_channel])]
        for k, (_, cm, r123, _) in enumerate(per_channel):
            total[k] += cm * r123 ** m * 2.0 * s[0][k]
    return [min(max(x, 0.0), 1.0) for x in total]  # pbr.glsl clamps a reflectance to [0, 1]


CASES = [  # film IOR, base F0, thickness (nm), cos(theta1)
    (1.8, (0.04, 0.04, 0.04), 300.0, 0.8),   # a dielectric (IOR 1.5) below a denser film
    (1.33, (0.9, 0.6, 0.3), 400.0, 1.0),     # a coloured metal at normal incidence
    (1.33, (0.9, 0.6, 0.3), 250.0, 0.35),    # the same at a glancing angle, thinner
]

if __name__ == "__main__":
    for ior, f0, d, c in CASES:
        rgb = film_fresnel(ior, f0, d, c)
        print(f"{{{ior}f, vec3({f0[0]}f, {f0[1]}f, {f0[2]}f), {d}f, {c}f, "
              f"vec3({rgb[0]:.7g}f, {rgb[1]:.7g}f, {rgb[2]:.7g}f)}},")
