"""The Python module installed the Python way (docs/python.md, ctest python_install): fresh venvs
in a temporary folder, `pip install --no-build-isolation` of the source tree offline (no index),
then the module's tests run by each venv's own python, from outside the source tree and without
PYTHONPATH, so that they import the installed package and its installed data.

1. A venv with --system-site-packages (the system's numpy and pandas satisfy the declared
   dependencies): tests/python/test_module.py and test_commands.py.
2. A plain venv (no numpy, no pandas): an install that resolves the dependencies fails offline
   naming numpy; with --no-deps it installs, test_commands.py passes (load, check, point,
   compare, spread, sweeps, cycle need neither) and grid() raises an ImportError that says
   what to do.

usage: install_check.py SOURCE_DIR GEARLOSS_BIN   (env GEARLOSS_PIP_BUILD_DIR: CMake's folder)
"""
import os
import subprocess
import sys
import tempfile
import time

SOURCE, BIN = sys.argv[1], sys.argv[2]
TESTS = os.path.join(SOURCE, "tests", "python")

env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "GEARLOSS_DATA_DIR", "PYTHONHOME")}
env.update(PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1", PIP_NO_INPUT="1",
           GEARLOSS_BIN=BIN, GEARLOSS_SOURCE_DIR=SOURCE)


def run(*args, check=True, **kw):
    print("+", " ".join(args), flush=True)
    r = subprocess.run(args, env=kw.pop("env", env), **kw)
    if check and r.returncode != 0:
        sys.exit(f"install_check: failed ({r.returncode}): {' '.join(args)}")
    return r


def install(venv, *options):
    t0 = time.monotonic()
    run(os.path.join(venv, "bin", "pip"), "install", "--no-build-isolation", *options, SOURCE, cwd=tmp)
    print(f"install_check: pip install {' '.join(options)} took {time.monotonic() - t0:.1f} s", flush=True)


def tests(venv, *files):
    e = dict(env, GEARLOSS_EXPECT_PREFIX=venv)
    for f in files:
        run(os.path.join(venv, "bin", "python"), os.path.join(TESTS, f), cwd=tmp, env=e)


with tempfile.TemporaryDirectory(prefix="gearloss-install-") as tmp:
    system = os.path.join(tmp, "system-site")
    run(sys.executable, "-m", "venv", "--system-site-packages", system)
    install(system)
    tests(system, "test_module.py", "test_commands.py")

    plain = os.path.join(tmp, "plain")
    run(sys.executable, "-m", "venv", plain)
    python = os.path.join(plain, "bin", "python")
    if run(python, "-c", "import numpy", check=False, stderr=subprocess.DEVNULL).returncode == 0:
        sys.exit("install_check: a plain venv imports numpy: this check needs one without")
    r = run(os.path.join(plain, "bin", "pip"), "install", "--no-build-isolation", SOURCE, cwd=tmp, check=False,
            capture_output=True, text=True)
    if r.returncode == 0 or "numpy" not in r.stdout + r.stderr:
        sys.exit("install_check: offline without numpy, an install with dependencies should fail naming numpy:\n"
                 + r.stdout + r.stderr)
    install(plain, "--no-deps")
    tests(plain, "test_commands.py")
    snippet = ("import gearloss, os\n"
               "case = gearloss.load(os.path.join(os.environ['GEARLOSS_SOURCE_DIR'], 'configs', 'transfer-box.yaml'))\n"
               "assert case.point(800, 250)['status'] == 'ok'\n"
               "try:\n    case.grid()\nexcept ImportError as e:\n    assert 'numpy' in str(e), e\n    print(e)\n"
               "else:\n    raise AssertionError('grid without numpy did not raise ImportError')\n")
    run(python, "-c", snippet, cwd=tmp)
print("install_check: ok")
