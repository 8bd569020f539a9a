"""Build of the Python package through CMake (pyproject.toml holds the metadata; README.md "Python and C API").

    pip install --no-build-isolation --no-deps .

The extension conforma._core is built by CMake from this repository (python/CMakeLists.txt, target
conforma_python, with the layer libraries it links; no tests, no benchmarks), for the interpreter running pip; the
CMake build also assembles the package folder <cmake-build>/python/conforma (pure-Python files, stubs, share/ with
the scenarios and standard profiles), which is copied into the wheel as it is. Environment:
  CONFORMA_PIP_BUILD_DIR   CMake build folder, kept between installs (incremental); default: a temporary folder
                           that is removed afterwards
  CONFORMA_CMAKE_ARGS      extra CMake configure arguments (split like a shell line), e.g. -DCONFORMA_SHARED_DATA=...
  CMAKE_BUILD_PARALLEL_LEVEL  parallel compile jobs (default: the number of CPUs)
ccache is used when it is on PATH (CMAKE_CXX_COMPILER_LAUNCHER, unless CONFORMA_CMAKE_ARGS sets one).
"""
import atexit
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))
# setuptools' own build and egg-info folders: a temporary folder, never the source tree's build/ (the usual CMake
# build folder) or a stray conforma.egg-info beside the sources
_SETUPTOOLS_BUILD = tempfile.mkdtemp(prefix="conforma-setuptools-")
atexit.register(shutil.rmtree, _SETUPTOOLS_BUILD, True)


class CMakeBuild(build_ext):
    """build_ext for the one extension conforma._core: configure and build the CMake target conforma_python."""

    def build_extension(self, ext):
        build_dir = os.environ.get("CONFORMA_PIP_BUILD_DIR", "")
        if build_dir:
            build_dir = os.path.abspath(build_dir)
            os.makedirs(build_dir, exist_ok=True)
        else:
            build_dir = tempfile.mkdtemp(prefix="conforma-cmake-")
            atexit.register(shutil.rmtree, build_dir, True)
        extra = shlex.split(os.environ.get("CONFORMA_CMAKE_ARGS", ""))
        configure = ["cmake", "-S", HERE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                     "-DCONFORMA_BUILD_TESTS=OFF", "-DCONFORMA_BUILD_BENCHMARKS=OFF", "-DCONFORMA_BUILD_PYTHON=ON",
                     f"-DPython3_EXECUTABLE={sys.executable}"]
        if shutil.which("ccache") and not any("COMPILER_LAUNCHER" in a for a in extra):
            configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
        try:  # pybind11 from Debian's python3-pybind11 (pybind11-dev's CMake config is found without help)
            import pybind11

            configure.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
        except ImportError:
            pass
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        self._run(configure + extra)
        self._run(["cmake", "--build", build_dir, "--target", "conforma_python", "-j", jobs])

        package = os.path.join(build_dir, "python", "conforma")
        built = [f for f in os.listdir(package) if f.startswith("_core.") and f.endswith(".so")]
        target = self.get_ext_fullpath(ext.name)
        if os.path.basename(target) not in built:
            raise RuntimeError(f"CMake built {built} in {package}, expected {os.path.basename(target)} (the "
                               f"module for {sys.executable}); was pybind11 configured for another Python?")
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copy2(os.path.join(package, os.path.basename(target)), target)
        share = os.path.join(os.path.dirname(target), "share")
        shutil.rmtree(share, ignore_errors=True)
        shutil.copytree(os.path.join(package, "share"), share)

    @staticmethod
    def _run(command):
        print("conforma setup.py:", " ".join(shlex.quote(c) for c in command), flush=True)
        subprocess.run(command, check=True)


setup(
    ext_modules=[Extension("conforma._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": os.path.join(_SETUPTOOLS_BUILD, "build")},
             "egg_info": {"egg_base": _SETUPTOOLS_BUILD}},
)
