# The Python module `darkroom` (python/, docs/python.md): pybind11 over the
# same core, data and workflows libraries as the runner and the editor.
#
# DARKROOM_WITH_PYTHON (ON by default). It is part of what CI tests, so with
# tests enabled a missing piece stops configuration and names the Debian
# package; without tests a warning says what is left out. The interpreter is
# the one CMake finds first; point -DPython3_EXECUTABLE=... at another (a
# pyenv or conda interpreter lacks Debian's python3-numpy). scripts/build.sh
# passes Debian's /usr/bin/python3, for which install-deps.sh installs.
option(DARKROOM_WITH_PYTHON "Build the Python module (pybind11, NumPy)" ON)

function(_darkroom_python_missing)
  string(CONCAT what ${ARGV})
  if(DARKROOM_BUILD_TESTS)
    message(FATAL_ERROR "${what}")
  else()
    message(WARNING "${what}. Built without the Python module.")
  endif()
endfunction()

if(DARKROOM_WITH_PYTHON)
  find_package(Python3 3.9 QUIET COMPONENTS Interpreter Development.Module NumPy)
  # pybind11's own package is read only once Python is known (below): with
  # no Python found it would search for one its own way and fail obscurely.
  find_path(DARKROOM_PYBIND11_HEADER pybind11/pybind11.h)
  set(_python_missing "")
  if(NOT Python3_Interpreter_FOUND)
    list(APPEND _python_missing "python3")
  endif()
  if(NOT Python3_Development.Module_FOUND)
    list(APPEND _python_missing "python3-dev")
  endif()
  if(NOT Python3_NumPy_FOUND)
    list(APPEND _python_missing "python3-numpy")
  endif()
  if(NOT DARKROOM_PYBIND11_HEADER)
    list(APPEND _python_missing "pybind11-dev")
  endif()
  if(DARKROOM_BUILD_TESTS AND Python3_Interpreter_FOUND)
    execute_process(COMMAND ${Python3_EXECUTABLE} -c "import pytest" RESULT_VARIABLE _no_pytest
                    OUTPUT_QUIET ERROR_QUIET)
    if(_no_pytest)
      list(APPEND _python_missing "python3-pytest")
    endif()
    # h5py writes and reads the .h5 databases of the pycinema tests (python/tests/test_pycinema_h5.py).
    execute_process(COMMAND ${Python3_EXECUTABLE} -c "import h5py" RESULT_VARIABLE _no_h5py
                    OUTPUT_QUIET ERROR_QUIET)
    if(_no_h5py)
      list(APPEND _python_missing "python3-h5py")
    endif()
  endif()
  if(_python_missing)
    list(JOIN _python_missing " " _packages)
    # (No semicolons in the text: CMake would read them as list separators.)
    _darkroom_python_missing(
      "The Python module needs the Debian packages ${_packages} for the interpreter "
      "${Python3_EXECUTABLE}. Install them with apt-get install ${_packages} (or run "
      "scripts/install-deps.sh as root). -DPython3_EXECUTABLE=/usr/bin/python3 picks Debian's "
      "interpreter, -DDARKROOM_WITH_PYTHON=OFF builds without the module")
    set(DARKROOM_WITH_PYTHON OFF)
  else()
    set(PYBIND11_FINDPYTHON ON)
    find_package(pybind11 2.6 REQUIRED CONFIG)
  endif()
endif()
