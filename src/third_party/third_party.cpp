// The one translation unit that compiles tinygltf and stb, two header-only libraries, from Debian's headers
// (libtinygltf-dev, libstb-dev) into shadelab itself. The binary, the Python module and the web page then need
// neither Debian's libtinygltf nor its libstb where they run: a wheel installs on any Linux, and emscripten,
// which cannot link Debian's libraries, builds the same code.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
