"""setuptools' part of `pip install .` (pyproject.toml, docs/install.md): the package's Python file
comes from python/vibroimpact/, its extension _vibroimpact from the project's CMake build
(python/build_support/vibroimpact_build), the version from CMakeLists.txt."""

import pathlib
import sys

from setuptools import Extension, setup

SOURCE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(SOURCE / "python" / "build_support"))
from vibroimpact_build import cmake_step, commands, project  # noqa: E402

BUILD = cmake_step.build_dir(SOURCE)
# setuptools' own files (its build folders, the egg-info) go into the CMake build folder: the
# source tree's build/ is the project's CMake build, and nothing is left in the tree.
BUILD.mkdir(parents=True, exist_ok=True)

setup(
    version=project.version(SOURCE),
    packages=[commands.PACKAGE],
    package_dir={commands.PACKAGE: "python/vibroimpact"},
    # The type stub and its marker (PEP 561) go into the wheel beside the Python files.
    package_data={commands.PACKAGE: ["*.pyi", "py.typed"]},
    # No sources: commands.build_ext takes the file CMake built. Declared, it makes the wheel a
    # platform wheel for this interpreter (cp311-cp311-linux_x86_64).
    ext_modules=[Extension(f"{commands.PACKAGE}._vibroimpact", sources=[])],
    cmdclass=commands.command_classes(SOURCE, BUILD),
    options={"build": {"build_base": str(BUILD / "setuptools")}, "egg_info": {"egg_base": str(BUILD)}},
)
