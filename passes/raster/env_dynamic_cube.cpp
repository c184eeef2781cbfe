#include "passes/raster/env_dynamic_cube.h"

#include <optional>
#include <vector>

#include "engine/gl/forward_renderer.h"
#include "engine/gl/shader.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/render_world.h"
#include "engine/scene/camera_math.h"
#include "engine/shading/shading.h"
#include "passes/raster/forward_texture_lod.h"
#include "passes/raster/fullscreen_resolve.h"
#include "passes/raster/gbuffer_surface.h"
#include "passes/raster/screen_rect.h"

namespace diptych {

namespace {

struct CubeCache {
  gl::Texture cube, depth;
  // Built on first use, with the scene's defines; [1] reads the G-buffer's stored surface.
  std::optional<FullscreenResolve> resolve[2];
  void ensure(int size) {
    if (cube && cube.width() == size) return;
    cube = gl::Texture::createCube(gl::TextureFormat::RGBA32F, size);
    depth = gl::Texture::create2D(gl::TextureFormat::D32F, size, size);
    cube.setLabel("env_dynamic_cube.cube");
    depth.setLabel("env_dynamic_cube.depth");
  }
};

}  // namespace

ParamSchema EnvDynamicCubePass::schema() {
  return {ParamSpec::integer("resolution", 256, 1, 8192, "texels per side of each cube face"),
          forwardTextureLodParam()};
}

void EnvDynamicCubePass::setup(PassBuilder& b) {
  resolution_ = b.params().integer("resolution");
  textureLod_ = forwardTextureLod(b);
  io_ = slotIo(b, "reflection");
  surface_ = readSurface(b, io_.hits);
}

void EnvDynamicCubePass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const Scene& scene = world.scene();
  const gl::Texture& hits = c.glTexture(io_.hits);
  const gl::Texture& out = c.glTexture(io_.signal);
  auto& cache = world.glCached<CubeCache>();
  cache.ensure(resolution_);
  std::optional<FullscreenResolve>& resolve = cache.resolve[surface_ != kNoResource ? 1 : 0];
  if (!resolve)
    resolve.emplace(
        gl::loadProgram({"fullscreen.vert", "env_dynamic_cube.frag"},
                        gl::withDefines(world.glShading().defines, surfaceDefines(surface_))));
  auto& renderer = world.glCached<gl::ForwardRenderer>();
  // Reversed-Z keeps precision at any near distance; a near plane at a small fraction of the
  // scene size only clips what touches the centre (the excluded object surrounds it anyway).
  const Aabb bounds = world.geometry().bounds;
  const float znear = 1e-4f * std::max(glm::length(bounds.hi - bounds.lo), 1e-30f);

  clearToZero(out);
  const Camera& camera = c.frame().camera;
  const mat4 viewProj =
      reversedZProjection(camera, float(out.width()) / float(out.height())) * viewMatrix(camera);
  const std::vector<Aabb>& boxes = meshBounds(world);
  int faceRenders = 0;  // counter for tests: off-screen meshes render none
  for (std::size_t m = 0; m < boxes.size(); ++m) {
    const WorldMesh& mesh = world.geometry().meshes[m];
    if (mesh.indices.empty() || !shading::materialHasReflection(scene.material(mesh.material)))
      continue;
    const Aabb& box = boxes[m];
    // Only pixels inside the mesh's window rectangle can show it: the resolve runs there, and a
    // mesh whose rectangle is empty (wholly off screen) shows in no pixel, so its six face
    // renders are skipped (the image is the same: the resolve would write nothing).
    const PixelRect rect = windowRect(box, viewProj, out.width(), out.height());
    if (rect.empty()) continue;
    gl::ForwardOptions options;
    options.excludeInstance = mesh.instance;
    options.textureLod = textureLod_;
    for (int face = 0; face < 6; ++face) {
      renderer.render(world.forwardScene(), gl::cubeFaceView(box.center(), face, znear), cache.cube,
                      cache.depth, options, face);
      ++faceRenders;
    }
    gl::glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    gl::glBindTextureUnit(0, hits.id());
    gl::glBindTextureUnit(1, cache.cube.id());
    bindSurface(c, surface_);
    resolve->program().set("uInstance", mesh.instance);
    resolve->program().set("uEye", c.frame().camera.position);
    resolve->draw(world, out, {.scissor = rect.scissor()});
  }
  c.count("cube_face_renders", double(faceRenders));
}

}  // namespace diptych
