"""Writes the wheel (PEP 427): the package folder, and the .dist-info with METADATA, WHEEL and RECORD."""

import base64
import hashlib
import pathlib
import sys
import sysconfig
import zipfile

GENERATOR = "vibroimpact_build"


def tag():
    """python-abi-platform of the running CPython, e.g. cp311-cp311-linux_x86_64 (an extension module)."""
    if sys.implementation.name != "cpython":
        raise RuntimeError(f"vibroimpact build backend: CPython only (the module is a CPython extension), not {sys.implementation.name}")
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    # SOABI is cpython-311-x86_64-linux-gnu, with a "d" after the version for a debug interpreter.
    abi = "cp" + sysconfig.get_config_var("SOABI").split("-")[1]
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{abi}-{platform}"


def _dist_name(meta):
    return f"{meta.name.replace('-', '_')}-{meta.version}"


def _metadata(meta):
    lines = ["Metadata-Version: 2.1", f"Name: {meta.name}", f"Version: {meta.version}"]
    if meta.summary:
        lines.append(f"Summary: {meta.summary}")
    if meta.license:
        lines.append(f"License: {meta.license}")
    if meta.requires_python:
        lines.append(f"Requires-Python: {meta.requires_python}")
    lines += [f"Requires-Dist: {d}" for d in meta.dependencies]
    return "\n".join(lines) + "\n"


def _wheel_info():
    return f"Wheel-Version: 1.0\nGenerator: {GENERATOR}\nRoot-Is-Purelib: false\nTag: {tag()}\n"


def write_dist_info(directory, meta):
    """Writes <name>-<version>.dist-info/METADATA under directory; returns the folder's name."""
    name = f"{_dist_name(meta)}.dist-info"
    (directory / name).mkdir(parents=True, exist_ok=True)
    (directory / name / "METADATA").write_text(_metadata(meta))
    return name


def _record_line(path, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{path},sha256={digest},{len(data)}"


def package_entries(package):
    """(name in the wheel, bytes, executable) of every file the build put in the package folder,
    but Python's byte-code caches."""
    for path in sorted(package.rglob("*")):
        if path.is_file() and "__pycache__" not in path.parts and path.suffix != ".pyc":
            arcname = f"{package.name}/{path.relative_to(package).as_posix()}"
            yield arcname, path.read_bytes(), path.suffix == ".so"


def editable_entries(package):
    """The one file of an editable wheel: a .pth that puts the build's package folder's parent on
    sys.path, so the installed module is the build folder's, rebuilt in place."""
    yield f"_{package.name}_editable.pth", f"{package.parent}\n".encode(), False


def write_wheel(directory, meta, entries, license_file):
    """Writes a wheel of `entries` (package_entries or editable_entries) into directory; returns its name."""
    dist_info = f"{_dist_name(meta)}.dist-info"
    wheel_name = f"{_dist_name(meta)}-{tag()}.whl"
    directory.mkdir(parents=True, exist_ok=True)
    record = []
    with zipfile.ZipFile(directory / wheel_name, "w", compression=zipfile.ZIP_DEFLATED) as whl:
        def add(arcname, data, executable=False):
            info = zipfile.ZipInfo(arcname, date_time=(1980, 1, 1, 0, 0, 0))
            info.external_attr = (0o755 if executable else 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            whl.writestr(info, data)
            record.append(_record_line(arcname, data))

        for arcname, data, executable in entries:
            add(arcname, data, executable)
        add(f"{dist_info}/METADATA", _metadata(meta).encode())
        add(f"{dist_info}/WHEEL", _wheel_info().encode())
        if license_file.is_file():
            add(f"{dist_info}/LICENSE", license_file.read_bytes())
        record.append(f"{dist_info}/RECORD,,")
        info = zipfile.ZipInfo(f"{dist_info}/RECORD", date_time=(1980, 1, 1, 0, 0, 0))
        info.external_attr = 0o644 << 16
        whl.writestr(info, "\n".join(record) + "\n", compress_type=zipfile.ZIP_DEFLATED)
    return wheel_name
