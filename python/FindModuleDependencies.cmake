# Whether the Python module (python/, `import rmfx`) can be built: pybind11 (CMake config) and an
# interpreter with NumPy and its development files. Sets RMFX_PYTHON_FOUND; says why not otherwise.
# Read before the runtime is added: the runtime's static libraries then build position-independent,
# as the module (a shared object) links them.
set(RMFX_PYTHON_FOUND OFF)
if(RMFX_BUILD_FUZZERS)
  message(STATUS "rmfx: the Python module is not built with sanitizers (the interpreter would need their runtime preloaded)")
  return()
endif()
# Debian's interpreter, where python3-numpy, python3-pytest and pybind11-dev install, before any
# other on PATH (a pyenv shim, say); -DPython_EXECUTABLE=… picks another.
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The interpreter the Python module is built for")
endif()
set(PYBIND11_FINDPYTHON ON)
find_package(Python COMPONENTS Interpreter Development.Module NumPy QUIET)
if(NOT Python_FOUND OR NOT Python_NumPy_FOUND)
  message(STATUS "rmfx: the Python module is not built: no Python interpreter with NumPy and its development files "
                 "(scripts/setup.sh installs python3-numpy and pybind11-dev)")
  return()
endif()
find_package(pybind11 CONFIG QUIET)
if(NOT pybind11_FOUND)
  message(STATUS "rmfx: the Python module is not built: pybind11 not found (scripts/setup.sh installs pybind11-dev)")
  return()
endif()
set(RMFX_PYTHON_FOUND ON)
message(STATUS "rmfx: the Python module is built for ${Python_EXECUTABLE} (Python ${Python_VERSION}, NumPy ${Python_NumPy_VERSION}, pybind11 ${pybind11_VERSION})")
