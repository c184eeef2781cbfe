// POV-Ray 3.7 version of samples/scenes/whitted.json, hand-written for the timing comparison
// in tests/bench/povray_compare.sh (see docs/benchmarks.md, "Whitted reference vs POV-Ray 3.7").
// Render: povray -D +W640 +H480 +A0 -J +Q9 +FN +O/tmp/pov.png tests/bench/whitted.pov
//
// Equivalent, value for value: the camera, the geometry, the light position and its 1/d^2
// falloff, the sky colour, the recursion depth, one ray per pixel.
// NOT identical (POV-Ray cannot express these, or does them another way):
//  - Geometry: POV-Ray intersects exact quadrics (a sphere, a plane clipped to 20 x 20); Diptych
//    traces tessellated triangles (2 x 128 x 63 per sphere, 2 for the floor) through an Embree
//    BVH with interpolated normals. The silhouettes and highlights differ by sub-pixel amounts.
//  - Ambient: Diptych adds A_G = 0.05 grey to every surface regardless of its colour, and its
//    k_a C term is scaled by each light's radiance S_i and visibility V_i (a lit, shadowed
//    ambient). POV-Ray's ambient is always `ambient * pigment colour * ambient_light`, never
//    shadowed. We use ambient 0.05 with ambient_light 1 (so 0.05 C, not 0.05) and drop the
//    floor's k_a = 0.1 term (worth about 0.07 C where the floor is lit).
//  - Transparency: POV-Ray's pigment transmit T also scales the surface's own diffuse and
//    ambient by (1 - T); Diptych's glass has k_d = 0 and C = 0.02, so this is negligible here.
//  - Shadows: Diptych's glass sphere casts an opaque shadow (shadow rays are occlusion tests);
//    POV-Ray would let 90% of the light through a transmit 0.9 surface. To match, the glass
//    sphere has no_shadow and an invisible opaque twin casts the shadow instead (see below).
//  - Light units: POV-Ray's fade is 2 / (1 + (d / fade_distance)^fade_power), so with
//    fade_distance 1 and fade_power 2 it is 2 / (1 + d^2), not 1 / d^2. The colour is therefore
//    half the 80 cd: 40 / (1 + d^2) * 2 = 80 / (1 + d^2), within 1% of 80 / d^2 for the
//    distances in this scene (d from about 7 to 20).
//  - The sky: Diptych's `environment.color` is POV-Ray's `background` (what rays that miss
//    everything return, primary or secondary alike).
//  - Output: both write sRGB-encoded 8-bit PNGs of linear values clamped to [0, 1]
//    (assumed_gamma 1.0 here; Diptych's PNG tone map at exposure 0).
#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 1
  // Diptych's `depth: 5` counts the primary ray as level 1 (rt_distributed traces it at depth
  // 1 and stops at depth > 5), as POV-Ray's max_trace_level does.
  max_trace_level 5
  // POV-Ray prunes rays whose contribution falls below 1/255 by default; Diptych does not,
  // so the bailout is off to trace the same ray tree.
  adc_bailout 0
  // no radiosity {} and no photons {} blocks: direct light and perfect specular paths only.
}

// Diptych: position (0, 1.6, 6.5), target (0, 0.9, 0), vertical fov 40 degrees, 640 x 480.
// POV-Ray is left-handed; `right -x*4/3` makes this camera right-handed like Diptych's, so
// the coordinates are used unchanged. POV-Ray's `angle` is the horizontal fov:
// 2 atan(tan(40/2) * 4/3) = 51.774 degrees.
camera {
  perspective
  location <0, 1.6, 6.5>
  up y
  right -x * 4 / 3
  sky y
  angle 51.774
  look_at <0, 0.9, 0>
}

// Diptych: environment colour (0.35, 0.6, 0.9).
background { rgb <0.35, 0.6, 0.9> }

// Diptych: point light at (4, 8, 6), 80 cd, white, 1/d^2 (see the header for the factor 2).
light_source {
  <4, 8, 6>
  rgb 40
  fade_distance 1
  fade_power 2
}

// Checkerboard floor: a 20 x 20 plane at y = 0. Diptych's checker alternates every
// 1/20 of uv = 1 unit, colour a where floor(x) + floor(z) is even; POV-Ray's `checker` is
// 1-unit cells with the first colour where floor(x) + floor(y) + floor(z) is even (y = 0 here).
plane {
  y, 0
  clipped_by { box { <-10, -1, -10>, <10, 1, 10> } }
  pigment { checker rgb <0.9, 0.05, 0.05>, rgb <0.95, 0.85, 0.1> }
  finish { ambient 0.05 diffuse 0.9 specular 0 phong 0 reflection 0 }
}

// Mirror sphere: C 0.05, k_d 0.1, k_s 0.5, e 200, k_ps 0.9 (M_PS white).
// POV-Ray's phong is the lecture's k_s max(0, r.v)^e times the light colour.
sphere {
  <0.9, 1.3, -1.2>, 0.9
  pigment { rgb 0.05 }
  finish { ambient 0.05 diffuse 0.1 phong 0.5 phong_size 200 reflection { 0.9 } }
}

// Glass sphere: C 0.02, k_d 0, k_s 0.5, e 300, k_ps 0.1, k_t 0.9 (M_T white), ior 1.5.
// k_t maps to transmit (unfiltered, like M_T = white), k_ps to reflection.
sphere {
  <-0.5, 1.0, 1.0>, 0.8
  pigment { rgbt <0.02, 0.02, 0.02, 0.9> }
  finish { ambient 0.05 diffuse 0 phong 0.5 phong_size 300 reflection { 0.1 } }
  interior { ior 1.5 }
  no_shadow
}

// The glass sphere's shadow caster: seen by shadow rays only (no_image hides it from camera
// rays, no_reflection from mirror rays; refracted rays do not see it either: checked by
// rendering, the inside of the glass is not black). Slightly smaller so that it never
// coincides with the glass surface.
sphere {
  <-0.5, 1.0, 1.0>, 0.799
  pigment { rgb 0 }
  no_image
  no_reflection
}
