// The implementation of Debian's tinygltf header, compiled here rather than linked from
// libtinygltf.so: that library decodes images with stb_image (whose JPEG decoder reads out of bounds
// on corrupt files, see image/jpeg.cpp), and compiled with the project the parser is also under the
// sanitizers and the fuzzer's coverage.
#define TINYGLTF_IMPLEMENTATION
#include "glint/geometry/mesh_io/tinygltf.hpp"
