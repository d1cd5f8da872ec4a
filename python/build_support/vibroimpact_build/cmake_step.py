"""Configures the project with CMake for the running interpreter and builds the target _vibroimpact."""

import os
import pathlib
import shutil
import subprocess
import sys
import sysconfig


def build_dir(source_dir):
    """Where CMake builds: $VI_PIP_BUILD_DIR, else build-pip-<interpreter> in the source tree.

    The default sits beside build/ in the source tree: ccache (CCACHE_BASEDIR is the source tree)
    then finds the objects of a build/ folder, whose relative paths are the same.
    """
    chosen = os.environ.get("VI_PIP_BUILD_DIR")
    if chosen:
        return pathlib.Path(chosen).resolve()
    return source_dir / f"build-pip-{sys.implementation.cache_tag}"


def _jobs():
    # cmake --build reads CMAKE_BUILD_PARALLEL_LEVEL itself; otherwise every CPU this process may use.
    if os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL"):
        return []
    count = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    return ["-j", str(count)]


def _run(command):
    print("vibroimpact build:", " ".join(command), file=sys.stderr, flush=True)
    subprocess.run(command, check=True)


_ADVICE = ("make the venv with --system-site-packages and run pip install --no-build-isolation . "
           "(bash scripts/install-deps python installs them)")


def check_importable(name, debian_package):
    """Raises RuntimeError, saying how to fix it, when this interpreter cannot import `name`.

    pip's build isolation, or a venv without the system's site packages, hides Debian's packages.
    """
    try:
        __import__(name)
    except ImportError as e:
        raise RuntimeError(f"vibroimpact build: {sys.executable} cannot import {name} ({e}); "
                           f"Debian: {debian_package}; {_ADVICE}") from e


def check_numpy():
    """check_importable for numpy: CMake needs its headers, and CMake's own message about it is
    buried in pybind11's."""
    check_importable("numpy", "python3-numpy")


def build_module(source_dir, build):
    """Builds the module into `build`; returns the package folder (build/python/vibroimpact)."""
    check_numpy()
    cmake = shutil.which("cmake")
    if not cmake:
        raise RuntimeError("vibroimpact build: cmake not found (Debian: cmake; bash scripts/install-deps python)")
    configure = [cmake, "-S", str(source_dir), "-B", str(build),
                 # The project's Release optimisation; only the module and the library it links.
                 "-DCMAKE_BUILD_TYPE=Release", "-DVI_BUILD_TESTS=OFF", "-DVI_BUILD_BENCH=OFF",
                 "-DVI_BUILD_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}"]
    # A new folder gets Ninja when installed, as scripts/configure-build does.
    if not (build / "CMakeCache.txt").exists() and shutil.which("ninja"):
        configure += ["-G", "Ninja"]
    _run(configure)
    _run([cmake, "--build", str(build), "--target", "_vibroimpact", *_jobs()])
    package = build / "python" / "vibroimpact"
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    if not (package / f"_vibroimpact{suffix}").is_file():
        raise RuntimeError(f"vibroimpact build: {package} holds no _vibroimpact{suffix} for {sys.executable}")
    return package
