"""PEP 517 build backend of the Python module `gearloss` (pyproject.toml, docs/python.md).

Standard library only, so that ``pip install --no-build-isolation .`` works offline in any venv
(a plain one has no `wheel` package, which setuptools of Debian 12 needs to build a wheel). The
compiled part is built by CMake, the same build as the command line's (target
gearloss_python: app/python/CMakeLists.txt), for the interpreter that runs the build; the wheel
holds the package's Python files, the extension, and the shipped data (configs/cycles and
configs/bearings) under gearloss/data, where the installed package finds them.

Environment: GEARLOSS_PIP_BUILD_DIR (CMake build folder, default build/pip in the source tree;
kept between installs, so a second install only relinks), GEARLOSS_CMAKE_ARGS (more -D options),
CMAKE_BUILD_PARALLEL_LEVEL (compile jobs, default all cores). ccache is used when installed.
"""
import base64
import hashlib
import io
import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import zipfile
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[3]
PACKAGE = SOURCE / "app" / "python" / "gearloss"
DATA = {"cycles": SOURCE / "configs" / "cycles", "bearings": SOURCE / "configs" / "bearings"}


def _project():
    """[project] of pyproject.toml, with the version of CMakeLists.txt's project()."""
    try:
        import tomllib
    except ImportError:  # Python < 3.11
        try:
            import tomli as tomllib
        except ImportError:
            raise RuntimeError("building gearloss needs Python 3.11 (tomllib) or the package tomli") from None
    with open(SOURCE / "pyproject.toml", "rb") as f:
        project = dict(tomllib.load(f)["project"])
    cmake = (SOURCE / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(\s*gearloss\s+VERSION\s+([0-9.]+)", cmake)
    if not match:
        raise RuntimeError("CMakeLists.txt: no 'project(gearloss VERSION x.y.z'")
    project["version"] = match.group(1)
    return project


def _metadata(project):
    lines = ["Metadata-Version: 2.1", f"Name: {project['name']}", f"Version: {project['version']}",
             f"Summary: {project['description']}", f"License: {project['license']['text']}",
             f"Requires-Python: {project['requires-python']}"]
    lines += [f"Requires-Dist: {d}" for d in project.get("dependencies", [])]
    return "\n".join(lines) + "\n"


def _dist_info(project):
    return f"{project['name']}-{project['version']}.dist-info"


def _tag():
    """cp311-cp311-linux_x86_64: the extension is built for this interpreter and platform."""
    if sys.implementation.name != "cpython":
        raise RuntimeError("gearloss's extension is built for CPython")
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{python}{sys.abiflags}-{platform}"


def _build_extension(config_settings):
    """Builds the target gearloss_python with CMake; returns the path of the extension."""
    if shutil.which("cmake") is None:
        raise RuntimeError("building gearloss needs cmake (Debian: apt-get install cmake; scripts/install-deps.sh)")
    settings = config_settings or {}
    build = Path(settings.get("build-dir") or os.environ.get("GEARLOSS_PIP_BUILD_DIR") or SOURCE / "build" / "pip")
    configure = ["cmake", "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF",
                 "-DGEARLOSS_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}"]
    if shutil.which("ccache"):
        configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
    configure += shlex.split(os.environ.get("GEARLOSS_CMAKE_ARGS", ""))
    jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
    print("gearloss: " + " ".join(shlex.quote(a) for a in configure), flush=True)
    subprocess.run(configure, check=True)
    built = build / "python" / "gearloss" / ("_gearloss" + sysconfig.get_config_var("EXT_SUFFIX"))
    if built.exists():
        built.unlink()  # a leftover of another interpreter's build must not pass for this one's
    subprocess.run(["cmake", "--build", str(build), "--target", "gearloss_python", "-j", jobs], check=True)
    if not built.exists():
        raise RuntimeError(f"CMake built no {built}: is pybind11 found (pybind11-dev, python3-dev; see the "
                           "configure output above, 'gearloss: Python module ...')?")
    return built


class _Wheel:
    def __init__(self, path):
        self.zip = zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED)
        self.record = []

    def add(self, name, data):
        if isinstance(data, str):
            data = data.encode("utf-8")
        info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
        info.external_attr = 0o644 << 16
        info.compress_type = zipfile.ZIP_DEFLATED
        self.zip.writestr(info, data)
        digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
        self.record.append(f"{name},sha256={digest},{len(data)}")

    def close(self, record_name):
        self.record.append(f"{record_name},,")
        info = zipfile.ZipInfo(record_name, date_time=(1980, 1, 1, 0, 0, 0))
        info.external_attr = 0o644 << 16
        self.zip.writestr(info, "\n".join(self.record) + "\n")
        self.zip.close()


# PEP 517 hooks

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    project = _project()
    info = Path(metadata_directory) / _dist_info(project)
    info.mkdir(parents=True, exist_ok=True)
    (info / "METADATA").write_text(_metadata(project), encoding="utf-8")
    return info.name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    project = _project()
    extension = _build_extension(config_settings)
    tag = _tag()
    name = f"{project['name']}-{project['version']}-{tag}.whl"
    wheel = _Wheel(Path(wheel_directory) / name)
    for f in sorted(PACKAGE.glob("*.py")):
        wheel.add(f"gearloss/{f.name}", f.read_bytes())
    # The installed package's data is its own folder gearloss/data (see gearloss/__init__.py).
    wheel.add("gearloss/_data_dir.py", "# Written by the build backend: the shipped data is the package's "
                                       "gearloss/data (GEARLOSS_DATA_DIR wins).\nDATA_DIR = None\n")
    wheel.add(f"gearloss/{extension.name}", extension.read_bytes())
    for folder, source in DATA.items():
        for f in sorted(p for p in source.rglob("*") if p.is_file()):
            wheel.add(f"gearloss/data/{folder}/{f.relative_to(source).as_posix()}", f.read_bytes())
    info = _dist_info(project)
    wheel.add(f"{info}/METADATA", _metadata(project))
    wheel.add(f"{info}/WHEEL", f"Wheel-Version: 1.0\nGenerator: gearloss_build\nRoot-Is-Purelib: false\nTag: {tag}\n")
    wheel.add(f"{info}/LICENSE", (SOURCE / "LICENSE").read_bytes())
    wheel.close(f"{info}/RECORD")
    return name


def build_sdist(sdist_directory, config_settings=None):
    """The source tree as git tracks it (the build folders left out), with PKG-INFO."""
    project = _project()
    base = f"{project['name']}-{project['version']}"
    try:
        listed = subprocess.run(["git", "-C", str(SOURCE), "ls-files", "-z"], check=True, capture_output=True).stdout
        files = [f for f in listed.decode().split("\0") if f and (SOURCE / f).is_file()]
    except (OSError, subprocess.CalledProcessError):
        files = [str(p.relative_to(SOURCE)) for p in SOURCE.rglob("*")
                 if p.is_file() and not p.relative_to(SOURCE).parts[0].startswith(("build", ".git"))]
    name = base + ".tar.gz"
    with tarfile.open(Path(sdist_directory) / name, "w:gz") as tar:
        for f in sorted(files):
            tar.add(SOURCE / f, arcname=f"{base}/{f}", recursive=False)
        data = _metadata(project).encode()
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        info.size = len(data)
        tar.addfile(info, io.BytesIO(data))
    return name
