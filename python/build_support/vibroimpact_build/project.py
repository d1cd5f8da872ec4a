"""The distribution's version: project(vibroimpact VERSION ...) in CMakeLists.txt."""

import re

# project(vibroimpact VERSION 1.2.3 ...): the one place the version is written.
_VERSION = re.compile(r"^\s*project\s*\(\s*vibroimpact\s+VERSION\s+([0-9]+(?:\.[0-9]+)*)\b", re.MULTILINE | re.IGNORECASE)


def cmake_version(cmakelists_text):
    """The VERSION of project(vibroimpact ...) in a CMakeLists.txt text; ValueError when there is none."""
    match = _VERSION.search(cmakelists_text)
    if not match:
        raise ValueError("CMakeLists.txt: no project(vibroimpact VERSION x.y.z)")
    return match.group(1)


def version(source_dir):
    """The version of the source tree at source_dir (a pathlib.Path)."""
    return cmake_version((source_dir / "CMakeLists.txt").read_text())
