// G-buffer raster: world-space positions (no model matrix; WorldGeometry is flattened) through
// the camera's infinite reversed-Z view-projection.
layout(location = 0) in vec3 aPosition;

uniform mat4 uViewProjection;

void main() { gl_Position = uViewProjection * vec4(aPosition, 1.0); }
