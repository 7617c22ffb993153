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
pkg_check_modules(OSMESA QUIET IMPORTED_TARGET osmesa)
option(FRICTIONLAB_WITH_RENDER "Off-screen rendering through OSMesa" ${OSMESA_FOUND})
if(FRICTIONLAB_WITH_RENDER AND NOT OSMESA_FOUND)
  message(FATAL_ERROR "FRICTIONLAB_WITH_RENDER=ON but osmesa.pc was not found (apt-get install libosmesa6-dev)")
endif()

pkg_check_modules(LIBAV QUIET IMPORTED_TARGET libavcodec libavformat libavutil libswscale)
option(FRICTIONLAB_WITH_VIDEO "MP4 video through libavcodec/libavformat/libswscale" ${LIBAV_FOUND})
if(FRICTIONLAB_WITH_VIDEO AND NOT LIBAV_FOUND)
  message(FATAL_ERROR "FRICTIONLAB_WITH_VIDEO=ON but libav* were not found (apt-get install libavcodec-dev libavformat-dev libswscale-dev)")
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

find_package(PNG QUIET)
find_package(Python3 QUIET COMPONENTS Interpreter)

if(FRICTIONLAB_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(FRICTIONLAB_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
