#pragma once
// The split sum's second factor for the glTF model (Karis 2013, "Real Shading in Unreal Engine 4",
// IntegrateBRDF): the directional albedo of pbr.glsl's specular lobe (GGX D, Smith
// height-correlated V, Schlick F) is E(n.v, roughness) = f0 A + B with
//   A = integral of (1 - F_c) f_s n.l dl,  B = integral of F_c f_s n.l dl,  F_c = (1 - v.h)^5,
// f_s = D V. This file integrates A and B by importance sampling OUR pbr.glsl functions and
// formats the table that shaders/common/env_brdf_table.glsl holds (generated, checked by
// tests/unit/test_env_brdf.cpp, read by pbrEnvironmentBrdf in GLSL and C++ alike).
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace diptych::shading {

// Table layout: kEnvBrdfSize x kEnvBrdfSize nodes, (A, B) interleaved, row j = roughness j/(N-1),
// column i = n.v (i/(N-1))^2 (the square puts nodes where E changes fastest, at grazing).
inline constexpr int kEnvBrdfSize = 32;
// Hammersley points per node (Karis 2013 uses 1024; at grazing n.v that leaves ~1e-2 of noise, so
// 64x more; docs/materials-secondary.md gives the resulting error). Changing it changes the
// committed table: regenerate it.
inline constexpr int kEnvBrdfSamples = 65536;

// (A, B) at one (n.v, roughness) from `samples` Hammersley points over the GGX half vector
// (Walter et al. 2007, eq. 35), evaluating pbrAlpha, pbrV and pbrSchlickWeight of pbr.glsl.
// n.v is floored at 1e-4 as every caller of pbrEnvironmentBrdf floors it.
glm::vec2 integrateEnvironmentBrdf(float nv, float roughness, int samples);

// The node's n.v (column i) and roughness (row j) of the table.
float envBrdfNodeNv(int i);
float envBrdfNodeRoughness(int j);

// The whole table, 2 * kEnvBrdfSize^2 floats (A, B per node, rows of roughness).
std::vector<float> environmentBrdfTable(int samples = kEnvBrdfSamples);

// The text of shaders/common/env_brdf_table.glsl for `table` (valid GLSL 4.50 and C++).
std::string environmentBrdfTableSource(const std::vector<float>& table, int samples);

}  // namespace diptych::shading
