// Depth only: the rasterizer writes the (polygon-offset) depth; no colour target is attached.
// Alpha-masked casters with colour textures would discard here (docs/shadow-maps.md, TODO).
void main() {}
