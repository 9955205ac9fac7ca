// Debian's tinygltf header, configured as glint uses it: no image decoder and no image writer (glint
// reads images itself, tinygltf_implementation.cpp says why). Include this, never <tiny_gltf.h>
// directly: the configuration changes inline code, so every file must see the same.
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
