// Shadow-map depth render: world-space positions (WorldGeometry is flattened, no model matrix)
// through one light layer's reversed-Z view-projection (passes/raster/shadow_map_frusta.h).
layout(location = 0) in vec3 aPosition;

uniform mat4 uViewProjection;

#ifdef DIPTYCH_ALPHA_MASK
#include "gl/scene_buffers.glsl"
// Alpha-tested casters: the texture uv of this vertex. glDrawElements makes gl_VertexID the
// index read from the element buffer, which already points into the shared vertex arrays.
out vec2 vUv;
#endif

void main() {
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
#ifdef DIPTYCH_ALPHA_MASK
  vUv = sceneUv(uint(gl_VertexID));
#endif
}
