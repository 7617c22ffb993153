# The browser's build (tools/site; emcmake cmake): the lab's core compiled to WebAssembly with
# Debian's Emscripten, as src/browser's module for the page's Web Worker. Its libraries come from
# where Debian keeps them: Bullet and yaml-cpp built for WebAssembly from Debian's source packages
# by tools/wasm-deps (FRICTIONLAB_WASM_DEPS, that script's prefix), the header-only ones (Eigen,
# fmt, nlohmann-json) from the host's /usr/include. Only the layers the lab's requests need are
# built: no drawing, video, MPI, Python, command line, tests or benchmarks.
set(FRICTIONLAB_WASM_DEPS "" CACHE PATH "tools/wasm-deps' prefix: Bullet and yaml-cpp for WebAssembly")
if(NOT EXISTS "${FRICTIONLAB_WASM_DEPS}/lib/libBulletDynamics-float64.a" OR
   NOT EXISTS "${FRICTIONLAB_WASM_DEPS}/lib/libminizip.a")
  message(FATAL_ERROR "the browser's build needs Bullet and yaml-cpp built for WebAssembly: run "
                      "tools/wasm-deps and give its prefix as -DFRICTIONLAB_WASM_DEPS=DIR (found "
                      "none in \"${FRICTIONLAB_WASM_DEPS}\")")
endif()

# Exceptions are the lab's errors: Emscripten leaves them off unless asked.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)

add_library(frictionlab_wasm_bullet INTERFACE)
target_include_directories(frictionlab_wasm_bullet SYSTEM INTERFACE ${FRICTIONLAB_WASM_DEPS}/include/bullet)
target_compile_definitions(frictionlab_wasm_bullet INTERFACE BT_USE_DOUBLE_PRECISION)
target_link_libraries(frictionlab_wasm_bullet INTERFACE
  ${FRICTIONLAB_WASM_DEPS}/lib/libBulletDynamics-float64.a
  ${FRICTIONLAB_WASM_DEPS}/lib/libBulletCollision-float64.a
  ${FRICTIONLAB_WASM_DEPS}/lib/libLinearMath-float64.a)
add_library(PkgConfig::BULLET ALIAS frictionlab_wasm_bullet)

add_library(frictionlab_wasm_yaml INTERFACE)
target_include_directories(frictionlab_wasm_yaml SYSTEM INTERFACE ${FRICTIONLAB_WASM_DEPS}/include)
target_link_libraries(frictionlab_wasm_yaml INTERFACE ${FRICTIONLAB_WASM_DEPS}/lib/libyaml-cpp.a)
add_library(yaml-cpp ALIAS frictionlab_wasm_yaml)

# The host's header-only libraries, each through a folder of its own: -I/usr/include would bring
# glibc's headers in place of Emscripten's libc.
set(host_headers ${CMAKE_BINARY_DIR}/host-headers)
file(MAKE_DIRECTORY ${host_headers})
foreach(dir fmt nlohmann)
  if(NOT EXISTS /usr/include/${dir})
    message(FATAL_ERROR "the browser's build needs /usr/include/${dir} (apt-get install libfmt-dev "
                        "nlohmann-json3-dev)")
  endif()
  file(CREATE_LINK /usr/include/${dir} ${host_headers}/${dir} SYMBOLIC)
endforeach()
add_library(frictionlab_wasm_eigen INTERFACE)
target_include_directories(frictionlab_wasm_eigen SYSTEM INTERFACE /usr/include/eigen3)
add_library(Eigen3::Eigen ALIAS frictionlab_wasm_eigen)
add_library(frictionlab_wasm_fmt INTERFACE)
target_include_directories(frictionlab_wasm_fmt SYSTEM INTERFACE ${host_headers})
target_compile_definitions(frictionlab_wasm_fmt INTERFACE FMT_HEADER_ONLY)
add_library(fmt::fmt ALIAS frictionlab_wasm_fmt)
add_library(frictionlab_wasm_json INTERFACE)
target_include_directories(frictionlab_wasm_json SYSTEM INTERFACE ${host_headers})
add_library(nlohmann_json::nlohmann_json ALIAS frictionlab_wasm_json)
# phyphox's zip export: minizip and zlib, from Debian's zlib source package.
add_library(frictionlab_wasm_minizip INTERFACE)
target_include_directories(frictionlab_wasm_minizip SYSTEM INTERFACE
                           ${FRICTIONLAB_WASM_DEPS}/include/minizip ${FRICTIONLAB_WASM_DEPS}/include)
target_link_libraries(frictionlab_wasm_minizip INTERFACE ${FRICTIONLAB_WASM_DEPS}/lib/libminizip.a
                      ${FRICTIONLAB_WASM_DEPS}/lib/libz.a)
add_library(PkgConfig::MINIZIP ALIAS frictionlab_wasm_minizip)

# One thread: the worker is the lab's thread (a pool's threads would need SharedArrayBuffer).
add_library(frictionlab_wasm_threads INTERFACE)
add_library(Threads::Threads ALIAS frictionlab_wasm_threads)

foreach(component RENDER OSMESA EGL VIDEO ASSETS MPI PYTHON SERVE WEB)
  set(FRICTIONLAB_WITH_${component} OFF)
endforeach()
set(FRICTIONLAB_WITH_ZIP ON)
set(FRICTIONLAB_BUILD_TESTS OFF)
set(FRICTIONLAB_BUILD_BENCH OFF)
set(FRICTIONLAB_SKIP_PARTS render video decoder)
