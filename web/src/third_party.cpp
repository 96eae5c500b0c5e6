// The one translation unit that compiles tinygltf and stb from Debian's headers into the web build: natively
// they come from Debian's libtinygltf and libstb, which emscripten cannot link.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
