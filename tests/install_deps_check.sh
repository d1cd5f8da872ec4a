#!/usr/bin/env bash
# Checks scripts/install-deps without installing anything: dpkg-query, id, sudo and apt-get are
# replaced by stubs on PATH that report what the script asked for. Run by CTest
# (InstallDeps.JobsPackagesAndNoRoot): bash tests/install_deps_check.sh SOURCE_DIR WORK_DIR
set -euo pipefail
script="$1/scripts/install-deps"
work="$2"
rm -rf "$work"
mkdir -p "$work/bin"
log="$work/calls.log"

# Installed packages: $STUB_INSTALLED, space-separated, or "all".
cat >"$work/bin/dpkg-query" <<'STUB'
#!/usr/bin/env bash
pkg="${!#}"
if [ "$STUB_INSTALLED" = all ] || [[ " $STUB_INSTALLED " == *" $pkg "* ]]; then
  printf 'install ok installed'
else
  exit 1
fi
STUB
cat >"$work/bin/id" <<'STUB'
#!/usr/bin/env bash
echo "$STUB_UID"
STUB
# sudo: refuses (as when it would ask for a password) unless STUB_SUDO=ok; then runs its command.
cat >"$work/bin/sudo" <<'STUB'
#!/usr/bin/env bash
echo "sudo $*" >>"$STUB_LOG"
[ "$STUB_SUDO" = ok ] || exit 1
[ "$1" = -n ] && shift
"$@"
STUB
cat >"$work/bin/apt-get" <<'STUB'
#!/usr/bin/env bash
echo "apt-get $* (DEBIAN_FRONTEND=${DEBIAN_FRONTEND:-})" >>"$STUB_LOG"
STUB
chmod +x "$work/bin/"*

failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
# run NAME EXPECTED_CODE [ARGS...]: runs the script with the stubs; its stdout+stderr in $out.
run() {
  local name="$1" expected="$2"
  shift 2
  : >"$log"
  local code=0
  out=$(PATH="$work/bin:$PATH" STUB_LOG="$log" bash "$script" "$@" 2>&1) || code=$?
  calls=$(cat "$log")
  if [ "$code" -ne "$expected" ]; then fail "$name: exit code $code, expected $expected; output: $out"; fi
}
has() { [[ "$1" == *"$2"* ]]; }

export STUB_INSTALLED=all STUB_UID=0 STUB_SUDO=no

run "--print test" 0 --print test
for p in cmake libceres-dev gnuplot-nox openmpi-bin pybind11-dev libgtest-dev chromium; do
  has "$out" "$p" || fail "--print test does not list $p"
done
for p in python3-nbclient python3-ipykernel jupyter-nbconvert python3-pandas python3-meshio; do
  has "$out" "$p" || fail "--print test does not list $p (the notebooks' test, Table.to_pandas, the VTU read back)"
done
[ -z "$calls" ] || fail "--print called: $calls"

run "--print run" 0 --print run
has "$out" gnuplot-nox || fail "--print run does not list gnuplot-nox"
has "$out" libeigen3-dev || fail "--print run does not list libeigen3-dev"
for p in libgtest-dev openmpi-bin pybind11-dev chromium; do
  has "$out" "$p" && fail "--print run lists $p, which only other jobs need"
done
[ "$(printf '%s\n' "$out" | sort | uniq -d)" = "" ] || fail "--print run test lists a package twice"

run "--print mpi python" 0 --print mpi python
has "$out" openmpi-bin && has "$out" python3-numpy || fail "--print mpi python misses a job's packages"
has "$out" python3-venv || fail "--print mpi python does not list python3-venv (pip install . into a venv)"
for p in python3-setuptools python3-wheel; do
  has "$out" "$p" || fail "--print mpi python does not list $p (setuptools writes the wheel of pip install .)"
done

run "unknown job" 2 --print bogus
has "$out" "unknown job 'bogus'" || fail "unknown job: no clear message: $out"

run "all present" 0 test
[ -z "$out" ] || fail "all present: printed '$out'"
[ -z "$calls" ] || fail "all present: called $calls"

export STUB_INSTALLED="build-essential cmake pkg-config ninja-build ccache libeigen3-dev libspectra-dev libsundials-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libnlopt-dev libceres-dev libboost-dev"
STUB_UID=1000 run "no root, no sudo" 2 run
has "$out" "apt-get install -y --no-install-recommends gnuplot-nox fonts-dejavu-core" ||
  fail "no root: does not print the apt-get command: $out"
has "$calls" "apt-get" && fail "no root: ran apt-get: $calls"

STUB_UID=1000 STUB_SUDO=ok run "no root, sudo" 0 run
has "$calls" "sudo -n env DEBIAN_FRONTEND=noninteractive apt-get install" || fail "sudo: not used: $calls"
has "$calls" "install -y -qq --no-install-recommends gnuplot-nox fonts-dejavu-core (DEBIAN_FRONTEND=noninteractive)" ||
  fail "sudo: apt-get not asked for exactly the missing packages: $calls"

run "root" 0 mpi
has "$out" "for mpi, missing: openmpi-bin libopenmpi-dev" || fail "root: does not say what it installs: $out"
has "$calls" "apt-get install -y -qq --no-install-recommends openmpi-bin libopenmpi-dev (DEBIAN_FRONTEND=noninteractive)" ||
  fail "root: apt-get not asked for exactly the missing packages: $calls"
has "$calls" "sudo" && fail "root: used sudo: $calls"

if [ "$failures" -ne 0 ]; then exit 1; fi
echo "install-deps: all checks passed"
