#!/usr/bin/env bash
# Python.VenvInstall's two reasons to skip: each exits 77 (CTest: skipped) with its reason, and
# neither makes a venv. Run by CTest (Python.VenvInstallSkipsWithReason):
#   bash check_skips.sh SOURCE_DIR WORK_DIR
set -euo pipefail
script="$1/tests/venv/check_venv_install.sh"
work="$2"
rm -rf "$work"
mkdir -p "$work"
# An interpreter without ensurepip, as Debian's python3 without python3-venv.
cat >"$work/python-without-venv" <<'STUB'
#!/usr/bin/env bash
[ "$1 $2" = "-c import ensurepip, venv" ] && { echo "ModuleNotFoundError: No module named 'ensurepip'" >&2; exit 1; }
echo "unexpected call: $*" >&2
exit 3
STUB
chmod +x "$work/python-without-venv"

failures=0
expect_skip() {
  local name="$1" message="$2" code=0 out
  shift 2
  out=$(bash "$script" "$@" 2>&1) || code=$?
  [ "$code" -eq 77 ] || { echo "FAIL: $name: exit code $code, expected 77: $out"; failures=$((failures + 1)); }
  [[ "$out" == *"$message"* ]] || { echo "FAIL: $name: no '$message' in: $out"; failures=$((failures + 1)); }
  [ ! -e "$work/venv" ] || { echo "FAIL: $name: made a venv"; failures=$((failures + 1)); }
}
expect_skip "module not built" "SKIPPED: the Python module is not built in this configuration: pybind11 not found" \
  python3 "$1" "$work/venv" "$work/pip-build" /bin/false 0.0.0 Release "pybind11 not found"
expect_skip "no python3-venv" "SKIPPED: $work/python-without-venv has no venv with pip (Debian: python3-venv" \
  "$work/python-without-venv" "$1" "$work/venv" "$work/pip-build" /bin/false 0.0.0 Release built
[ "$failures" -eq 0 ] || exit 1
echo "both skips exit 77 with their reason"
