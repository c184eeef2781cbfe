#pragma once
// Include tinygltf through this header only: the class layout and its default image callbacks
// depend on these macros, so every translation unit must see the same ones. Images are
// decoded by our OpenImageIO callback (loader.cpp) instead of tinygltf's bundled stb_image.
#ifndef TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE
#endif
#ifndef TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#endif
#include <tiny_gltf.h>
