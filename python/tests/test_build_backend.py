"""The pip build backend (python/build_backend) without building: its version, build folder and wheel.

The whole backend, building and installing, runs in the CTest test Python.VenvInstall.
"""

import base64
import hashlib
import importlib
import re
import sys
import sysconfig
import zipfile

import pytest

from conftest import SOURCE_DIR

sys.path.insert(0, str(SOURCE_DIR / "python/build_backend"))
backend = importlib.import_module("vibroimpact_build")
from vibroimpact_build import cmake_step, project, wheel_file  # noqa: E402


def test_the_version_is_cmakes_project_version():
    cmakelists = (SOURCE_DIR / "CMakeLists.txt").read_text()
    written = re.findall(r"project\(vibroimpact VERSION ([0-9.]+)", cmakelists)
    assert len(written) == 1
    assert project.read(SOURCE_DIR).version == written[0]
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


def test_the_wheel_holds_the_package_folder_with_a_true_record(tmp_path):
    package = tmp_path / "build/python/vibroimpact"
    (package / "__pycache__").mkdir(parents=True)
    (package / "__init__.py").write_text("x = 1\n")
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    (package / f"_vibroimpact{suffix}").write_bytes(b"\x7fELF not really")
    (package / "__pycache__/__init__.cpython-311.pyc").write_bytes(b"cache")
    meta = project.read(SOURCE_DIR)
    name = wheel_file.write_wheel(tmp_path / "dist", meta, wheel_file.package_entries(package), SOURCE_DIR / "LICENSE")
    assert name == f"vibroimpact-{meta.version}-{wheel_file.tag()}.whl"
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    assert wheel_file.tag().startswith(f"{python}-{python}-")

    with zipfile.ZipFile(tmp_path / "dist" / name) as whl:
        names = set(whl.namelist())
        info = f"vibroimpact-{meta.version}.dist-info"
        assert names == {"vibroimpact/__init__.py", f"vibroimpact/_vibroimpact{suffix}", f"{info}/METADATA",
                         f"{info}/WHEEL", f"{info}/LICENSE", f"{info}/RECORD"}
        metadata = whl.read(f"{info}/METADATA").decode()
        assert f"Version: {meta.version}\n" in metadata and "Requires-Dist: numpy\n" in metadata
        assert f"Tag: {wheel_file.tag()}\n" in whl.read(f"{info}/WHEEL").decode()
        record = [line.split(",") for line in whl.read(f"{info}/RECORD").decode().splitlines()]
        assert sorted(r[0] for r in record) == sorted(names)
        for path, digest, size in record:
            if path.endswith("RECORD"):
                assert digest == size == ""
                continue
            data = whl.read(path)
            expected = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            assert (digest, int(size)) == (f"sha256={expected}", len(data)), path


def test_metadata_before_the_build_is_the_wheels_and_needs_the_source_tree(monkeypatch, tmp_path):
    monkeypatch.chdir(SOURCE_DIR)  # PEP 517 runs the hooks in the source tree
    name = backend.prepare_metadata_for_build_wheel(str(tmp_path))
    meta = project.read(SOURCE_DIR)
    assert name == f"vibroimpact-{meta.version}.dist-info"
    assert (tmp_path / name / "METADATA").read_text() == wheel_file._metadata(meta)
    assert backend.get_requires_for_build_wheel() == []
    monkeypatch.chdir(tmp_path)
    with pytest.raises(RuntimeError, match="no CMakeLists.txt"):
        backend.build_wheel(str(tmp_path / "dist"))


def test_a_build_that_cannot_see_numpy_says_how_to_fix_it(monkeypatch, tmp_path):
    monkeypatch.setitem(sys.modules, "numpy", None)  # import numpy now raises ImportError
    with pytest.raises(RuntimeError, match="--system-site-packages .* --no-build-isolation"):
        cmake_step.build_module(SOURCE_DIR, tmp_path / "never-made")
    assert not (tmp_path / "never-made").exists()


def test_the_editable_wheel_holds_only_a_pth_to_the_build_folder(tmp_path):
    package = tmp_path / "build/python/vibroimpact"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text("x = 1\n")
    meta = project.read(SOURCE_DIR)
    name = wheel_file.write_wheel(tmp_path / "dist", meta, wheel_file.editable_entries(package), SOURCE_DIR / "LICENSE")
    with zipfile.ZipFile(tmp_path / "dist" / name) as whl:
        pth = [n for n in whl.namelist() if not n.startswith("vibroimpact-")]
        assert pth == ["_vibroimpact_editable.pth"]
        assert whl.read(pth[0]).decode() == f"{tmp_path / 'build/python'}\n"
