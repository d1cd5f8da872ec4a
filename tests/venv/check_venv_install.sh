#!/usr/bin/env bash
# `pip install .` into a fresh venv, as docs/install.md says, then the installed module runs an
# example case and agrees with the build's command; then `pip install -e .` imports the build folder's. Run by CTest (Python.VenvInstall):
#   bash check_venv_install.sh PYTHON SOURCE_DIR WORK_DIR PIP_BUILD_DIR VI_EXE VERSION BUILD_TYPE PYTHON_PART
# PYTHON_PART is the configure step's word on the Python module ("built", or why not). Exits 77
# (CTest: skipped) with the reason when the module cannot be built here or python3-venv is missing.
# PIP_BUILD_DIR is where the backend's CMake builds (VI_PIP_BUILD_DIR); made afresh each run, so the
# module is rebuilt (through ccache) every time, and removed after a pass.
set -euo pipefail
python="$1" source_dir="$2" work="$3" pip_build="$4" vi_exe="$5" version="$6" build_type="$7" python_part="$8"

if [ "$python_part" != built ]; then
  echo "SKIPPED: the Python module is not built in this configuration: $python_part"
  exit 77
fi
if ! "$python" -c "import ensurepip, venv" 2>/dev/null; then
  echo "SKIPPED: $python has no venv with pip (Debian: python3-venv; bash scripts/install-deps python)"
  exit 77
fi

rm -rf "$work" "$pip_build"
mkdir -p "$work"
"$python" -m venv --system-site-packages "$work/v"

# pip_install ARGS...: pip in the source tree, offline, writing nothing outside the two folders (no
# index, no wheel cache); fails with pip's log.
pip_install() {
  (cd "$source_dir" &&
    env -u PYTHONPATH PIP_NO_INDEX=1 PIP_NO_CACHE_DIR=1 PIP_DISABLE_PIP_VERSION_CHECK=1 \
      VI_PIP_BUILD_DIR="$pip_build" CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}" \
      "$work/v/bin/pip" install --no-build-isolation "$@" >"$work/pip.log" 2>&1) || {
    cat "$work/pip.log"
    echo "FAIL: pip install --no-build-isolation $* failed (log above)"
    exit 1
  }
}
touch "$work/started"
start=$(date +%s.%N)
pip_install .
echo "pip install: $(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }') s"

# The build's command on the same case, for the installed module to agree with.
case_file="$source_dir/examples/paper/free_impact_tip.toml"
"$vi_exe" simulate "$case_file" --out "$work/cli" >/dev/null

cd "$work"
env -u PYTHONPATH MPLBACKEND=Agg "$work/v/bin/python" "$source_dir/tests/venv/installed_module.py" \
  "$version" "$case_file" "$work/cli/summary.json" "$build_type"
env -u PYTHONPATH MPLBACKEND=Agg "$work/v/bin/python" "$source_dir/examples/python/sweep_plot.py" \
  "$case_file" --points 3 --out "$work/sweep.png"
[ "$(head -c 4 "$work/sweep.png" | od -An -c | tr -d ' ')" = "211PNG" ] || { echo "FAIL: sweep_plot.py wrote no PNG"; exit 1; }

# Editable: the module is the build folder's (built above, so nothing is compiled again).
"$work/v/bin/pip" uninstall -y -q vibroimpact
pip_install -e .
where=$(env -u PYTHONPATH "$work/v/bin/python" -c "import vibroimpact; print(vibroimpact.__file__)")
[ "$where" = "$pip_build/python/vibroimpact/__init__.py" ] || { echo "FAIL: pip install -e . imports $where"; exit 1; }
echo "pip install -e .: the module is $where"
# No packaging tool's leftovers in the source tree: setuptools writes its egg-info and build folders
# (bdist.*, lib.*) into the CMake build folder, never beside setup.py or into build/.
leftovers=$(find "$source_dir" -maxdepth 3 \( -name '*.egg-info' -o -name 'bdist.*' -o -name 'lib.*-*' \) \
  -newer "$work/started" -not -path "$work/*" -not -path "$pip_build/*")
[ -z "$leftovers" ] || { echo "FAIL: pip wrote into the source tree: $leftovers"; exit 1; }
rm -rf "$pip_build"
echo "Python.VenvInstall: passed"
