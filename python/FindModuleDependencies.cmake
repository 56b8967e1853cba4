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
# Where cmake --install puts the module, relative to the prefix: where this interpreter looks.
# Debian's python3 reads /usr/lib/python3/dist-packages (its deb_system scheme) and
# /usr/local/lib/python3.X/dist-packages, so PREFIX/lib/python3/dist-packages for the prefix /usr
# and PREFIX/lib/python3.X/dist-packages for any other (the default /usr/local; elsewhere with
# PYTHONPATH); another interpreter its own site-packages (posix_prefix). -DRMFX_INSTALL_PYTHONDIR=…
# sets another.
if(NOT DEFINED RMFX_INSTALL_PYTHONDIR)
  execute_process(
    COMMAND ${Python_EXECUTABLE} -c [=[
import sys, sysconfig
prefix = sys.argv[1]
if 'deb_system' in sysconfig.get_scheme_names():
    print('lib/python3/dist-packages' if prefix == '/usr' else 'lib/python%d.%d/dist-packages' % sys.version_info[:2], end='')
else:
    path = sysconfig.get_path('platlib', 'posix_prefix', vars={'base': '/PREFIX', 'platbase': '/PREFIX'})
    print(path[len('/PREFIX/'):], end='')
]=] ${CMAKE_INSTALL_PREFIX}
    OUTPUT_VARIABLE python_dir RESULT_VARIABLE python_dir_failed)
  if(python_dir_failed OR python_dir STREQUAL "")
    set(python_dir lib/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/site-packages)
  endif()
  set(RMFX_INSTALL_PYTHONDIR ${python_dir} CACHE STRING
      "Where cmake --install puts the Python module, relative to the install prefix")
endif()
message(STATUS "rmfx: the Python module is built for ${Python_EXECUTABLE} (Python ${Python_VERSION}, NumPy ${Python_NumPy_VERSION}, pybind11 ${pybind11_VERSION})")
