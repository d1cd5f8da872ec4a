"""What setup.py adds to setuptools for `pip install .`: the project's CMake builds the module.

setuptools (setuptools.build_meta, pyproject.toml) writes the wheel, its metadata and the editable
install; these modules read the version from CMakeLists.txt (project), configure and build the
target _vibroimpact with CMake (cmake_step), and hand the result to setuptools' commands (commands).
"""
