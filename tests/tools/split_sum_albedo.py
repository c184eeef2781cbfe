#!/usr/bin/env python3
"""The split sum's second factor for the glTF model (docs/materials.md, "Rough reflections"):
A(n.v, r) and B(n.v, r) with E = f0 A + B the directional albedo of the GGX lobe with Smith
height-correlated visibility and Schlick Fresnel (shaders/common/pbr.glsl), by importance
sampling the GGX half vector (Karis 2013, IntegrateBRDF), printed beside the analytic fit that
pbrEnvironmentBrdf uses (Lazarov 2013, as given by Karis 2014). Pure Python, no dependencies:
    python3 tests/tools/split_sum_albedo.py
"""
import math


def integrate(nv, roughness, samples=4096):
    a = max(roughness * roughness, 1e-3)  # pbrAlpha
    a2 = a * a
    v = (math.sqrt(1 - nv * nv), 0.0, nv)
    sum_a = sum_b = 0.0
    for k in range(samples):
        u1 = (k + 0.5) / samples
        u2 = (k * 0.6180339887) % 1.0
        cos2 = (1 - u1) / (1 + (a2 - 1) * u1)  # GGX half vector, Walter et al. 2007 eq. 35
        ct, st, phi = math.sqrt(cos2), math.sqrt(max(0.0, 1 - cos2)), 2 * math.pi * u2
        h = (st * math.cos(phi), st * math.sin(phi), ct)
        vh = sum(x * y for x, y in zip(v, h))
        nl = 2 * vh * h[2] - v[2]
        if nl <= 0 or vh <= 0:
            continue
        gv = nl * math.sqrt(nv * nv * (1 - a2) + a2)
        gl = nv * math.sqrt(nl * nl * (1 - a2) + a2)
        weight = 4 * (0.5 / (gv + gl)) * nl * vh / ct  # f cos / pdf without F, pdf = D n.h / 4 v.h
        fc = (1 - vh) ** 5
        sum_a += weight * (1 - fc)
        sum_b += weight * fc
    return sum_a / samples, sum_b / samples


def karis_fit(nv, roughness):
    rx, ry = 1 - roughness, 0.0425 - 0.0275 * roughness
    a004 = min(rx * rx, 2 ** (-9.28 * nv)) * rx + ry
    return 1.04 - 1.04 * a004 - 0.572 * roughness, 1.04 * a004 - 0.04 + 0.022 * roughness


print("roughness  n.v   integrated A+B (A, B)    fit A+B (A, B)")
for r in (0.0, 0.2, 0.4, 0.6, 0.8, 1.0):
    for nv in (1.0, 0.5, 0.2):
        a, b = integrate(nv, r)
        fa, fb = karis_fit(nv, r)
        print(f"{r:9.1f} {nv:5.1f}   {a + b:.3f} ({a:.3f}, {b:.3f})     {fa + fb:.3f} ({fa:.3f}, {fb:.3f})")
