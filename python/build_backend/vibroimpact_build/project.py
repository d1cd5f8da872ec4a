"""The distribution's metadata: pyproject.toml's [project] table, and the version from CMakeLists.txt."""

import re
import sys
from dataclasses import dataclass

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Debian 12 has Python 3.11
    try:
        import tomli as tomllib
    except ImportError as e:
        raise RuntimeError("vibroimpact build backend: Python before 3.11 needs the package tomli (Debian: python3-tomli)") from e


@dataclass
class Project:
    name: str
    version: str
    summary: str
    license: str
    requires_python: str
    dependencies: list


# project(vibroimpact VERSION 1.2.3 ...): the one place the version is written.
_VERSION = re.compile(r"^\s*project\s*\(\s*vibroimpact\s+VERSION\s+([0-9]+(?:\.[0-9]+)*)\b", re.MULTILINE | re.IGNORECASE)


def cmake_version(cmakelists_text):
    """The VERSION of project(vibroimpact ...) in a CMakeLists.txt text; ValueError when there is none."""
    match = _VERSION.search(cmakelists_text)
    if not match:
        raise ValueError("CMakeLists.txt: no project(vibroimpact VERSION x.y.z)")
    return match.group(1)


def read(source_dir):
    """The Project of the source tree at source_dir (a pathlib.Path)."""
    with open(source_dir / "pyproject.toml", "rb") as f:
        table = tomllib.load(f)["project"]
    if table.get("dynamic") != ["version"]:
        raise ValueError("pyproject.toml: [project] dynamic must be [\"version\"] (the version is CMake's)")
    return Project(
        name=table["name"],
        version=cmake_version((source_dir / "CMakeLists.txt").read_text()),
        summary=table.get("description", ""),
        license=table.get("license", {}).get("text", ""),
        requires_python=table.get("requires-python", ""),
        dependencies=list(table.get("dependencies", [])),
    )
