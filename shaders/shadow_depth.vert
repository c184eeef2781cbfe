// Shadow-map depth render: world-space positions (WorldGeometry is flattened, no model matrix)
// through one light layer's reversed-Z view-projection (passes/raster/shadow_map_frusta.h).
layout(location = 0) in vec3 aPosition;

uniform mat4 uViewProjection;

void main() { gl_Position = uViewProjection * vec4(aPosition, 1.0); }
