# Dependencies come from Debian's packages; none is vendored or downloaded.
find_package(PkgConfig REQUIRED)

# Bullet in double precision: bullet-float64.pc carries -DBT_USE_DOUBLE_PRECISION together with
# the *-float64 libraries, so the flags we compile with are exactly those of the library we link.
# (CMake's own FindBullet returns the single-precision libraries without the define.)
pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet-float64)

find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(yaml-cpp REQUIRED)
find_package(CLI11 REQUIRED)
find_package(fmt REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(Threads REQUIRED)

# Optional components: ON by default when found; each one's absence leaves a working headless build.

# The drawing layer (FRICTIONLAB_WITH_RENDER): the renderer, overlays and text, PNG frames, the
# rig view. It draws through a GL back end, each a switch of its own below.
find_package(PNG QUIET)
find_path(FRICTIONLAB_STB_INCLUDE_DIR stb/stb_truetype.h)
find_path(FRICTIONLAB_GL_INCLUDE_DIR GL/glcorearb.h)
find_file(FRICTIONLAB_DEFAULT_FONT DejaVuSans.ttf PATHS /usr/share/fonts/truetype/dejavu
          NO_DEFAULT_PATH)
set(render_found OFF)
if(PNG_FOUND AND FRICTIONLAB_STB_INCLUDE_DIR AND FRICTIONLAB_GL_INCLUDE_DIR AND FRICTIONLAB_DEFAULT_FONT)
  set(render_found ON)
endif()
option(FRICTIONLAB_WITH_RENDER "The drawing layer: renderer, overlays, text, PNG, the rig view"
       ${render_found})
if(FRICTIONLAB_WITH_RENDER AND NOT PNG_FOUND)
  message(FATAL_ERROR "FRICTIONLAB_WITH_RENDER=ON needs libpng (apt-get install libpng-dev)")
endif()
if(FRICTIONLAB_WITH_RENDER AND NOT FRICTIONLAB_STB_INCLUDE_DIR)
  message(FATAL_ERROR "FRICTIONLAB_WITH_RENDER=ON needs stb_truetype (apt-get install libstb-dev)")
endif()
if(FRICTIONLAB_WITH_RENDER AND NOT FRICTIONLAB_GL_INCLUDE_DIR)
  message(FATAL_ERROR "FRICTIONLAB_WITH_RENDER=ON needs GL/glcorearb.h (apt-get install libgl-dev)")
endif()
if(FRICTIONLAB_WITH_RENDER AND NOT FRICTIONLAB_DEFAULT_FONT)
  message(FATAL_ERROR "FRICTIONLAB_WITH_RENDER=ON needs DejaVu Sans (apt-get install fonts-dejavu-core)")
endif()

# GL back ends. OSMesa renders in software (llvmpipe) with no display or GPU; EGL renders with
# no display either, on Mesa's surfaceless platform (llvmpipe here) or a GPU's EGL device.
pkg_check_modules(OSMESA QUIET IMPORTED_TARGET osmesa)
set(osmesa_default OFF)
if(OSMESA_FOUND AND FRICTIONLAB_WITH_RENDER)
  set(osmesa_default ON)
endif()
option(FRICTIONLAB_WITH_OSMESA "The OSMesa GL back end (needs FRICTIONLAB_WITH_RENDER)"
       ${osmesa_default})
if(FRICTIONLAB_WITH_OSMESA AND NOT FRICTIONLAB_WITH_RENDER)
  message(FATAL_ERROR "FRICTIONLAB_WITH_OSMESA=ON needs FRICTIONLAB_WITH_RENDER=ON (a back end "
                      "without the drawing layer draws nothing)")
endif()
if(FRICTIONLAB_WITH_OSMESA AND NOT OSMESA_FOUND)
  message(FATAL_ERROR "FRICTIONLAB_WITH_OSMESA=ON but osmesa.pc was not found (apt-get install libosmesa6-dev)")
endif()

pkg_check_modules(EGL QUIET IMPORTED_TARGET egl)
set(egl_default OFF)
if(EGL_FOUND AND FRICTIONLAB_WITH_RENDER)
  set(egl_default ON)
endif()
option(FRICTIONLAB_WITH_EGL "The EGL GL back end (needs FRICTIONLAB_WITH_RENDER)" ${egl_default})
if(FRICTIONLAB_WITH_EGL AND NOT FRICTIONLAB_WITH_RENDER)
  message(FATAL_ERROR "FRICTIONLAB_WITH_EGL=ON needs FRICTIONLAB_WITH_RENDER=ON (a back end "
                      "without the drawing layer draws nothing)")
endif()
if(FRICTIONLAB_WITH_EGL AND NOT EGL_FOUND)
  message(FATAL_ERROR "FRICTIONLAB_WITH_EGL=ON but egl.pc was not found (apt-get install libegl-dev)")
endif()

# Videos (MP4, WebM, GIF) through libav; libavfilter makes the GIF's palette.
pkg_check_modules(LIBAV QUIET IMPORTED_TARGET libavcodec libavformat libavfilter libavutil
                  libswscale)
option(FRICTIONLAB_WITH_VIDEO "MP4, WebM and GIF video through libav" ${LIBAV_FOUND})
if(FRICTIONLAB_WITH_VIDEO AND NOT LIBAV_FOUND)
  message(FATAL_ERROR "FRICTIONLAB_WITH_VIDEO=ON but libav* were not found (apt-get install libavcodec-dev libavformat-dev libavfilter-dev libswscale-dev)")
endif()

# phyphox's zip export through minizip (zlib's contrib, Debian's libminizip-dev).
pkg_check_modules(MINIZIP QUIET IMPORTED_TARGET minizip)
option(FRICTIONLAB_WITH_ZIP "phyphox's zip export through minizip" ${MINIZIP_FOUND})
if(FRICTIONLAB_WITH_ZIP AND NOT MINIZIP_FOUND)
  message(FATAL_ERROR "FRICTIONLAB_WITH_ZIP=ON but minizip was not found (apt-get install libminizip-dev)")
endif()

find_package(assimp QUIET)
option(FRICTIONLAB_WITH_ASSETS "LEGO meshes through assimp" ${assimp_FOUND})
if(FRICTIONLAB_WITH_ASSETS AND NOT assimp_FOUND)
  message(FATAL_ERROR "FRICTIONLAB_WITH_ASSETS=ON but assimp was not found (apt-get install libassimp-dev)")
endif()

find_package(MPI QUIET COMPONENTS C)
option(FRICTIONLAB_WITH_MPI "Sweeps across MPI ranks" ${MPI_C_FOUND})
if(FRICTIONLAB_WITH_MPI AND NOT MPI_C_FOUND)
  message(FATAL_ERROR "FRICTIONLAB_WITH_MPI=ON but MPI was not found (apt-get install libopenmpi-dev openmpi-bin)")
endif()

pkg_check_modules(HTTPLIB QUIET IMPORTED_TARGET cpp-httplib)
option(FRICTIONLAB_WITH_SERVE "frictionlab serve: the lab in a browser, through cpp-httplib" ${HTTPLIB_FOUND})
if(FRICTIONLAB_WITH_SERVE AND NOT HTTPLIB_FOUND)
  message(FATAL_ERROR "FRICTIONLAB_WITH_SERVE=ON but cpp-httplib was not found (apt-get install libcpp-httplib-dev)")
endif()

find_package(Python3 QUIET COMPONENTS Interpreter)

if(FRICTIONLAB_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(FRICTIONLAB_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
