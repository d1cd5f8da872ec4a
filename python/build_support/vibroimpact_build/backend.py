"""The build backend pyproject.toml names: setuptools.build_meta, after a check of what it needs.

The build needs Debian's numpy (CMake wants its headers), setuptools and wheel, which pip shows it
only with --no-build-isolation, in a venv made with --system-site-packages. Without them setuptools
would fail first, with a message that names neither (pip: "No matching distribution found for
setuptools"; setuptools: "invalid command 'bdist_wheel'"); this check says how to fix it, before
setuptools is imported, so it works in pip's isolated build environment too.
"""

from . import cmake_step


def _setuptools():
    cmake_step.check_numpy()
    cmake_step.check_importable("setuptools", "python3-setuptools")
    cmake_step.check_importable("wheel", "python3-wheel")
    from setuptools import build_meta
    return build_meta


def get_requires_for_build_wheel(config_settings=None):
    # setuptools asks for wheel, which the check above found; nothing comes from an index.
    _setuptools()
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    return _setuptools().prepare_metadata_for_build_wheel(metadata_directory, config_settings)


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    return _setuptools().build_wheel(wheel_directory, config_settings, metadata_directory)


def get_requires_for_build_editable(config_settings=None):
    _setuptools()
    return []


def prepare_metadata_for_build_editable(metadata_directory, config_settings=None):
    return _setuptools().prepare_metadata_for_build_editable(metadata_directory, config_settings)


def build_editable(wheel_directory, config_settings=None, metadata_directory=None):
    return _setuptools().build_editable(wheel_directory, config_settings, metadata_directory)
