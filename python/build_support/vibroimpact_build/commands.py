"""setuptools commands that take the extension from the project's CMake build instead of compiling it."""

import os
import pathlib

from setuptools.command.build_ext import build_ext as _build_ext
from setuptools.command.editable_wheel import editable_wheel as _editable_wheel

from . import cmake_step

PACKAGE = "vibroimpact"


def command_classes(source_dir, build_dir):
    """setup()'s cmdclass: build_ext and editable_wheel over one CMake build of source_dir in build_dir."""
    built = []

    def cmake_package():
        # An editable install asks twice (before its metadata and in build_ext); CMake runs once.
        if not built:
            built.append(cmake_step.build_module(source_dir, build_dir))
        return built[0]

    class build_ext(_build_ext):
        """Puts the CMake-built extension where setuptools packs it into the wheel."""

        def run(self):
            package = cmake_package()
            for ext in self.extensions:
                made = package / os.path.basename(self.get_ext_filename(ext.name))
                target = pathlib.Path(self.get_ext_fullpath(ext.name))
                # In an editable install the package folder is the CMake build's: nothing to copy.
                if target.resolve() != made.resolve():
                    self.mkpath(str(target.parent))
                    self.copy_file(str(made), str(target))

    class editable_wheel(_editable_wheel):
        """`pip install -e .` imports the package from the CMake build folder, which
        `cmake --build <that folder> --target _vibroimpact` updates in place (CMake copies
        __init__.py there too)."""

        def run(self):
            # Before setuptools' own run, whose errors come wrapped in a note about PEP 660:
            # the numpy check's advice stays the first thing pip shows.
            # setuptools takes package folders relative to the source tree only.
            self.distribution.package_dir[PACKAGE] = os.path.relpath(cmake_package(), source_dir)
            super().run()

    return {"build_ext": build_ext, "editable_wheel": editable_wheel}
