# The lab from Python (FRICTIONLAB_WITH_PYTHON): `import frictionlab`, a pybind11 module over the
# same static libraries the command line uses (src/python). ON by default when pybind11 and
# Python 3's development files are found (apt-get install pybind11-dev python3-dev).
#
# The module is built for Debian's interpreter, /usr/bin/python3 (where python3-numpy installs),
# before any other python3 on the PATH, unless -DPython3_EXECUTABLE=... names another.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 3.7 QUIET COMPONENTS Interpreter Development.Module)
set(python_found OFF)
if(Python3_Development.Module_FOUND)
  # With Python3 found first, pybind11 uses CMake's FindPython3 (the same interpreter).
  find_package(pybind11 2.6 CONFIG QUIET)
  if(pybind11_FOUND)
    set(python_found ON)
  endif()
endif()

# Not with the sanitizers: a module built with AddressSanitizer loads only into a python3 started
# with libasan preloaded.
set(python_default ${python_found})
if(FRICTIONLAB_SANITIZE)
  set(python_default OFF)
endif()
option(FRICTIONLAB_WITH_PYTHON "The Python module (import frictionlab), through pybind11"
       ${python_default})
if(FRICTIONLAB_WITH_PYTHON AND NOT python_found)
  message(FATAL_ERROR "FRICTIONLAB_WITH_PYTHON=ON needs pybind11 and Python 3's development files "
                      "(apt-get install pybind11-dev python3-dev)")
endif()
if(NOT python_found)
  message(STATUS "frictionlab: no Python module (pybind11 or Python 3's development files not "
                 "found: apt-get install pybind11-dev python3-dev)")
endif()
if(FRICTIONLAB_WITH_PYTHON AND FRICTIONLAB_SANITIZE)
  message(FATAL_ERROR "FRICTIONLAB_WITH_PYTHON=ON with FRICTIONLAB_SANITIZE=ON: a module built "
                      "with AddressSanitizer loads only into a python3 started with libasan "
                      "preloaded; leave the sanitizer build without it")
endif()

# fl_position_independent(target...): compiles every static library the targets link, directly or
# through others, as position-independent code, so that they can be linked into a shared module.
# The command line links the same libraries: on x86-64 this changes neither its results (the same
# instructions for floating point; -ffp-contract=off holds) nor measurably its speed (the
# libraries' own calls bind locally, -fno-semantic-interposition, as in an executable).
function(fl_position_independent)
  set(pending ${ARGN})
  set(seen "")
  while(pending)
    list(POP_FRONT pending target)
    if(NOT TARGET ${target} OR target IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${target})
    get_target_property(imported ${target} IMPORTED)
    if(imported)
      continue()
    endif()
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "STATIC_LIBRARY")
      set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
      target_compile_options(${target} PRIVATE -fno-semantic-interposition)
    endif()
    foreach(property LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
      get_target_property(links ${target} ${property})
      if(links)
        foreach(link ${links})
          # $<LINK_ONLY:x> and other generator expressions around a target's name.
          string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
          if(NOT link MATCHES "^\\$<")
            list(APPEND pending ${link})
          endif()
        endforeach()
      endif()
    endforeach()
  endwhile()
endfunction()
