// What the scene uses, as compile-time constants (engine/gl/shader_features.cpp, docs/gl.md
// "Scene shader permutations"). A program compiled for a scene gets DIPTYCH_SCENE_FEATURES and
// the values below; one compiled without them (tests of the model on random inputs) keeps every
// path. Why: llvmpipe runs both sides of a branch under a lane mask, uniform or not, so a
// run-time test of "has this material a texture" costs every texture path at every pixel.
// With a constant the compiler folds the branch away; the image is unchanged (the removed code
// could not be taken for this scene).
#ifndef DIPTYCH_SCENE_FEATURES_GLSL
#define DIPTYCH_SCENE_FEATURES_GLSL
#ifndef DIPTYCH_SCENE_FEATURES
#define DIPTYCH_SCENE_TEXTURES 1     // some material samples a colour/emission/MR/AO texture
#define DIPTYCH_SCENE_NORMAL_MAPS 1  // some material has a normal texture
#define DIPTYCH_SCENE_BUMP 1         // some material has a bump map (texture or procedural)
#define DIPTYCH_SCENE_CHECKER 1      // some material has the procedural checker
#define DIPTYCH_SCENE_REMAP 1        // some material is re-mapped per texel (remapsPerTexel)
#define DIPTYCH_SCENE_MODEL -1       // SHADING_MODEL_* of every material, -1 when mixed
#define DIPTYCH_SCENE_IRIDESCENCE 1  // some glTF-model material has a thin film
#define DIPTYCH_SCENE_LIGHT_TYPE -1  // LIGHT_* of every light, -1 when mixed or none
#endif
#endif
