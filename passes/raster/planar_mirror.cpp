#include "passes/raster/planar_mirror.h"

#include "engine/gl/forward_renderer.h"
#include "engine/gl/shader.h"
#include "engine/graph/render_world.h"
#include "engine/shading/shading.h"
#include "passes/raster/forward_texture_lod.h"
#include "passes/raster/fullscreen_resolve.h"

namespace diptych {

namespace {

struct MirrorCache {
  gl::Texture color, depth;  // the mirrored render, frame size
  FullscreenResolve resolve{gl::loadProgram({"fullscreen.vert", "planar_mirror.frag"})};
  bool found = false;
  std::vector<PlanarInstance> mirrors;
  void ensure(int width, int height) {
    if (color && color.width() == width && color.height() == height) return;
    color = gl::Texture::create2D(gl::TextureFormat::RGBA32F, width, height);
    depth = gl::Texture::create2D(gl::TextureFormat::D32F, width, height);
    color.setLabel("planar_mirror.color");
    depth.setLabel("planar_mirror.depth");
  }
};

}  // namespace

std::vector<PlanarInstance> findPlanarMirrors(const Scene& scene, const WorldGeometry& world) {
  return findPlanarInstances(world, [&](const WorldMesh& mesh) {
    return shading::materialHasReflection(scene.material(mesh.material));
  });
}

mat4 reflectionMatrix(const vec3& n, float d) {
  mat4 r(1.f);  // column-major: r[column][row]
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) r[col][row] -= 2.f * n[row] * n[col];
  for (int row = 0; row < 3; ++row) r[3][row] = -2.f * d * n[row];
  return r;
}

ParamSchema PlanarMirrorPass::schema() {
  return {forwardTextureLodParam()};
}

void PlanarMirrorPass::setup(PassBuilder& b) {
  io_ = slotIo(b, "reflection");
  textureLod_ = forwardTextureLod(b);
}

void PlanarMirrorPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const Camera& camera = c.frame().camera;
  const gl::Texture& hits = c.glTexture(io_.hits);
  const gl::Texture& out = c.glTexture(io_.signal);
  auto& cache = world.glCached<MirrorCache>();
  cache.ensure(out.width(), out.height());
  if (!cache.found)
    cache.mirrors = findPlanarMirrors(world.scene(), world.geometry()), cache.found = true;
  auto& renderer = world.glCached<gl::ForwardRenderer>();
  const gl::ForwardView eyeView = gl::cameraView(camera, float(out.width()) / float(out.height()));

  clearToZero(out);
  for (const PlanarInstance& mirror : cache.mirrors) {
    // Orient the plane toward the eye: the reflected rays travel on the eye's side.
    const float side = glm::dot(mirror.normal, camera.position) + mirror.offset;
    if (side == 0.f) continue;  // eye in the mirror's plane: the mirror is seen edge-on
    const vec3 n = side > 0.f ? mirror.normal : -mirror.normal;
    const float d = side > 0.f ? mirror.offset : -mirror.offset;
    const mat4 r = reflectionMatrix(n, d);
    // The symmetric camera: world point x appears where the eye sees its mirror image R x,
    // and the pixel ray of the mirrored view, mapped back by R, is the reflected ray.
    gl::ForwardView mirrored{eyeView.view * r, eyeView.projection,
                             vec3(r * vec4(camera.position, 1.f))};
    gl::ForwardOptions options;
    options.excludeInstance = mirror.instance;
    options.clipPlane = vec4(n, d);
    options.textureLod = textureLod_;
    renderer.render(world.forwardScene(), mirrored, cache.color, cache.depth, options);

    gl::glBindTextureUnit(0, hits.id());
    gl::glBindTextureUnit(1, cache.color.id());
    cache.resolve.program().set("uMirrorInstance", mirror.instance);
    cache.resolve.draw(world, out);
  }
}

}  // namespace diptych
