# Compiler flags every frictionlab target shares, through the interface target fl_flags.
add_library(fl_flags INTERFACE)
target_compile_options(fl_flags INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
  -Wunused -Woverloaded-virtual -Wnull-dereference -Wdouble-promotion -Wformat=2
  # Bit-identical results across builds: no fused multiply-add contraction.
  -ffp-contract=off)
# GCC 12 reports -Wrestrict inside libstdc++'s std::string concatenation at -O3, a known false
# positive (GCC bug 105329, fixed in GCC 13).
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(fl_flags INTERFACE -Wno-restrict)
endif()
if(FRICTIONLAB_WERROR)
  target_compile_options(fl_flags INTERFACE -Werror)
endif()
if(FRICTIONLAB_SANITIZE)
  target_compile_options(fl_flags INTERFACE -fsanitize=address,undefined -fno-sanitize-recover=all
                                            -fno-omit-frame-pointer)
  target_link_options(fl_flags INTERFACE -fsanitize=address,undefined)
endif()
