"""`pip install .` without CMake (setup.py, python/build_support): its version, build folder, the
check before setuptools, and the wheels setuptools writes around a stand-in for the CMake build.

The real build and install, with CMake, run in the CTest test Python.VenvInstall.
"""

import re
import sys
import sysconfig
import zipfile

import pytest

from conftest import SOURCE_DIR

sys.path.insert(0, str(SOURCE_DIR / "python/build_support"))
from vibroimpact_build import backend, cmake_step, project  # noqa: E402

SUFFIX = sysconfig.get_config_var("EXT_SUFFIX")


def test_the_version_is_cmakes_project_version():
    cmakelists = (SOURCE_DIR / "CMakeLists.txt").read_text()
    written = re.findall(r"project\(vibroimpact VERSION ([0-9.]+)", cmakelists)
    assert len(written) == 1
    assert project.version(SOURCE_DIR) == written[0]
    assert project.cmake_version("cmake_minimum_required(VERSION 3.25)\nproject(vibroimpact VERSION 2.10.3 LANGUAGES CXX)\n") == "2.10.3"
    with pytest.raises(ValueError, match="no project"):
        project.cmake_version("cmake_minimum_required(VERSION 3.25)\nproject(other VERSION 1.0)\n")


def test_the_build_folder_sits_beside_build_unless_the_environment_says(monkeypatch, tmp_path):
    monkeypatch.delenv("VI_PIP_BUILD_DIR", raising=False)
    assert cmake_step.build_dir(SOURCE_DIR) == SOURCE_DIR / f"build-pip-{sys.implementation.cache_tag}"
    monkeypatch.setenv("VI_PIP_BUILD_DIR", str(tmp_path / "b"))
    assert cmake_step.build_dir(SOURCE_DIR) == tmp_path / "b"


def test_jobs_come_from_the_environment_or_the_cpus(monkeypatch):
    monkeypatch.setenv("CMAKE_BUILD_PARALLEL_LEVEL", "3")
    assert cmake_step._jobs() == []  # cmake --build reads it itself
    monkeypatch.delenv("CMAKE_BUILD_PARALLEL_LEVEL")
    flag, count = cmake_step._jobs()
    assert flag == "-j" and int(count) >= 1


def test_a_build_that_cannot_see_numpy_says_how_to_fix_it(monkeypatch, tmp_path):
    monkeypatch.setitem(sys.modules, "numpy", None)  # import numpy now raises ImportError
    with pytest.raises(RuntimeError, match="numpy .* --system-site-packages .* --no-build-isolation"):
        cmake_step.build_module(SOURCE_DIR, tmp_path / "never-made")
    assert not (tmp_path / "never-made").exists()
    for hook in (backend.get_requires_for_build_wheel, backend.get_requires_for_build_editable):
        with pytest.raises(RuntimeError, match="python3-numpy"):
            hook()


def test_a_build_that_cannot_see_wheel_names_the_debian_package(monkeypatch):
    monkeypatch.setitem(sys.modules, "wheel", None)
    with pytest.raises(RuntimeError, match="cannot import wheel .*python3-wheel.* --no-build-isolation"):
        backend.get_requires_for_build_wheel()


@pytest.fixture
def stand_in_build(monkeypatch, tmp_path):
    """The hooks run in the source tree with VI_PIP_BUILD_DIR in tmp_path, and CMake replaced by a
    package folder holding a made-up extension. Checks afterwards that the source tree gained no
    setuptools files (egg-info, build folders)."""
    package = tmp_path / "cmake/python/vibroimpact"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text("from ._vibroimpact import *\n")
    (package / f"_vibroimpact{SUFFIX}").write_bytes(b"\x7fELF not really")
    calls = []

    def build_module(source, build):
        calls.append((source, build))
        return package

    monkeypatch.setattr(cmake_step, "build_module", build_module)
    monkeypatch.setenv("VI_PIP_BUILD_DIR", str(tmp_path / "cmake"))
    monkeypatch.chdir(SOURCE_DIR)  # PEP 517 runs the hooks in the source tree
    before = set(SOURCE_DIR.glob("**/*.egg-info")) | set(SOURCE_DIR.glob("build*/bdist.*"))
    yield package, calls
    assert set(SOURCE_DIR.glob("**/*.egg-info")) | set(SOURCE_DIR.glob("build*/bdist.*")) == before


def test_the_metadata_has_cmakes_version_and_numpy(stand_in_build, tmp_path):
    (tmp_path / "meta").mkdir()  # pip makes it
    name = backend.prepare_metadata_for_build_wheel(str(tmp_path / "meta"))
    version = project.version(SOURCE_DIR)
    assert name == f"vibroimpact-{version}.dist-info"
    metadata = (tmp_path / "meta" / name / "METADATA").read_text()
    assert f"\nVersion: {version}\n" in metadata and "\nRequires-Dist: numpy\n" in metadata
    assert stand_in_build[1] == []  # the metadata needs no build


def test_the_wheel_holds_the_source_package_and_the_cmake_built_extension(stand_in_build, tmp_path):
    package, calls = stand_in_build
    name = backend.build_wheel(str(tmp_path / "dist"))
    version = project.version(SOURCE_DIR)
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    assert re.fullmatch(rf"vibroimpact-{version}-{python}-{python}-linux_\w+\.whl", name)
    assert calls == [(SOURCE_DIR, tmp_path / "cmake")]
    with zipfile.ZipFile(tmp_path / "dist" / name) as whl:
        modules = {n for n in whl.namelist() if n.startswith("vibroimpact/")}
        sources = [f for f in (SOURCE_DIR / "python/vibroimpact").iterdir() if f.suffix in (".py", ".pyi") or f.name == "py.typed"]
        assert {"__init__.py", "__init__.pyi", "py.typed"} <= {f.name for f in sources}
        assert modules == {f"vibroimpact/{f.name}" for f in sources} | {f"vibroimpact/_vibroimpact{SUFFIX}"}
        for f in sources:
            assert whl.read(f"vibroimpact/{f.name}") == f.read_bytes(), f.name
        assert whl.read(f"vibroimpact/_vibroimpact{SUFFIX}") == b"\x7fELF not really"
        wheel_info = whl.read(f"vibroimpact-{version}.dist-info/WHEEL").decode()
        assert "Root-Is-Purelib: false\n" in wheel_info and f"Tag: {python}-{python}-linux_" in wheel_info


def test_the_editable_wheel_imports_the_cmake_build_folders_package(stand_in_build, tmp_path):
    package, calls = stand_in_build
    name = backend.build_editable(str(tmp_path / "dist"))
    assert len(calls) == 1  # CMake runs once though setuptools asks twice
    with zipfile.ZipFile(tmp_path / "dist" / name) as whl:
        assert not any(n.startswith("vibroimpact/") for n in whl.namelist())  # no copy of the package
        finders = [n for n in whl.namelist() if n.endswith("_finder.py")]
        assert len(finders) == 1
        assert repr(str(package)) in whl.read(finders[0]).decode()  # setuptools' path for 'vibroimpact'
