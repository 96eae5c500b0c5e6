# The libraries shadelab's modules link, as the web build (emscripten) provides them. Emscripten's sysroot has
# none of Debian's headers, and adding /usr/include to it would mix glibc's headers with its libc. So the
# header-only libraries the web build needs (glm, nlohmann-json, tinygltf, stb) are reached through a folder of
# links to exactly those headers in the build tree, and are given the same target names the native build gets
# from find_package, so the modules' CMakeLists stay as they are. tinygltf and stb are compiled from their
# headers in src/third_party/, as natively.
set(SHADELAB_WEB_INCLUDE ${PROJECT_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${SHADELAB_WEB_INCLUDE})
foreach(entry glm nlohmann tiny_gltf.h stb)
  if(NOT EXISTS /usr/include/${entry})
    message(FATAL_ERROR "web build: /usr/include/${entry} is missing; run scripts/install-deps.sh --with-web")
  endif()
  file(CREATE_LINK /usr/include/${entry} ${SHADELAB_WEB_INCLUDE}/${entry} SYMBOLIC)
endforeach()
# The GL enums gl/gl_api.h names (Mesa's header); its KHR/khrplatform.h is emscripten's own.
if(NOT EXISTS /usr/include/GL/glcorearb.h)
  message(FATAL_ERROR "web build: /usr/include/GL/glcorearb.h is missing; run scripts/install-deps.sh --with-web")
endif()
file(MAKE_DIRECTORY ${SHADELAB_WEB_INCLUDE}/GL)
file(CREATE_LINK /usr/include/GL/glcorearb.h ${SHADELAB_WEB_INCLUDE}/GL/glcorearb.h SYMBOLIC)

add_library(glm::glm INTERFACE IMPORTED)
target_include_directories(glm::glm SYSTEM INTERFACE ${SHADELAB_WEB_INCLUDE})
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE ${SHADELAB_WEB_INCLUDE})
set(SHADELAB_STB_INCLUDE ${SHADELAB_WEB_INCLUDE}/stb)  # for src/third_party/, as the native build's find_path
set(SHADELAB_TINYGLTF_INCLUDE ${SHADELAB_WEB_INCLUDE})
# No threads in the page: every tracer runs with one thread per Web Worker (parallelFor then runs inline).
add_library(Threads::Threads INTERFACE IMPORTED)
