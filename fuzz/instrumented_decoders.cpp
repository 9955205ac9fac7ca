// The fuzz build only (fuzz/CMakeLists.txt): the implementations of the Debian packages' stb_image and
// tinyexr headers, compiled with the fuzzer's coverage and the sanitizers, in place of the
// uninstrumented libstb.a and libtinyexr.so that the normal build links. Nothing is copied: both are
// the system's headers.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

#define TINYEXR_IMPLEMENTATION
#include <tinyexr.h>
