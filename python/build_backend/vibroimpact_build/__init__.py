"""The build backend of `pip install .` (pyproject.toml): the project's CMake builds the module.

PEP 517 hooks for a wheel. The wheel holds the package folder that the CMake target _vibroimpact
makes in the build tree (python/vibroimpact/: __init__.py and the extension), the same files that
PYTHONPATH=build/python imports, built for the interpreter that runs pip (docs/install.md).
An editable install (`pip install -e .`) puts the build folder's package on sys.path instead.
There is no source distribution: pip installs from the source tree.
"""

import pathlib

from . import cmake_step, project, wheel_file


def _source_dir():
    # PEP 517 runs the hooks in the source tree.
    source = pathlib.Path.cwd()
    if not (source / "CMakeLists.txt").is_file():
        raise RuntimeError(f"vibroimpact build backend: {source} holds no CMakeLists.txt; run pip on the source tree")
    return source


def get_requires_for_build_wheel(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    meta = project.read(_source_dir())
    return wheel_file.write_dist_info(pathlib.Path(metadata_directory), meta)


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    source = _source_dir()
    meta = project.read(source)
    package = cmake_step.build_module(source, cmake_step.build_dir(source))
    return wheel_file.write_wheel(pathlib.Path(wheel_directory), meta, wheel_file.package_entries(package),
                                  source / "LICENSE")


# PEP 660, `pip install -e .`: the module stays in the CMake build folder, which a .pth puts on
# sys.path; `cmake --build <that folder> --target _vibroimpact` updates it in place.
def get_requires_for_build_editable(config_settings=None):
    return []


def prepare_metadata_for_build_editable(metadata_directory, config_settings=None):
    return prepare_metadata_for_build_wheel(metadata_directory, config_settings)


def build_editable(wheel_directory, config_settings=None, metadata_directory=None):
    source = _source_dir()
    meta = project.read(source)
    package = cmake_step.build_module(source, cmake_step.build_dir(source))
    return wheel_file.write_wheel(pathlib.Path(wheel_directory), meta, wheel_file.editable_entries(package),
                                  source / "LICENSE")
