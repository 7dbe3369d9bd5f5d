# The Python module's tests (docs/python.md), run by ctest with Debian's /usr/bin/python3 and
# PYTHONPATH at the build tree's python/ (tests/CMakeLists.txt); TRIPACK_CLI is the program built
# beside the module, for comparisons with the command line.
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("TRIPACK_CLI")
    assert path and os.path.exists(path), "TRIPACK_CLI must name the tripack program"
    return path


def run_cli(cli, *args):
    """The command's exit code, stdout and the error line it printed (without 'tripack: error: ')."""
    r = subprocess.run([cli, *args], capture_output=True, text=True)
    errors = [l for l in r.stderr.splitlines() if l.startswith("tripack: error: ")]
    return r.returncode, r.stdout, errors[0][len("tripack: error: "):] if errors else None
