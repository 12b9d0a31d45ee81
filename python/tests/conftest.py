"""Fixtures of the Python suite: the command-line program of the same build (installed
beside the package by pip, or HILLSTAB_PROGRAM), and a runner writing scenes into a
temporary directory."""
import os
import shutil
import subprocess
import sys

import pytest


def program_path():
    path = os.environ.get("HILLSTAB_PROGRAM")
    if path:
        return path
    # pip puts the program into the environment's scripts directory, beside python
    candidate = os.path.join(os.path.dirname(sys.executable), "hillstab")
    if os.path.exists(candidate):
        return candidate
    return shutil.which("hillstab")


@pytest.fixture(scope="session")
def program():
    path = program_path()
    if not path:
        pytest.fail("the hillstab program of this build is not installed (pip install puts it beside python)")
    return path


class Runner:
    """Runs scene texts with the command-line program in a directory."""

    def __init__(self, program, directory):
        self.program = program
        self.directory = directory

    def scene(self, name, text):
        path = os.path.join(self.directory, name + ".nml")
        with open(path, "w") as handle:
            handle.write(text)
        return path

    def run(self, name, text, threads=2, expect=0):
        """Run the scene `text` as <name>.nml (output prefix <name>); the completed process."""
        path = self.scene(name, text)
        env = dict(os.environ, OMP_NUM_THREADS=str(threads))
        done = subprocess.run([self.program, "--quiet", path], cwd=self.directory, env=env,
                              capture_output=True, text=True)
        assert done.returncode == expect, done.stderr
        return done

    def path(self, file):
        return os.path.join(self.directory, file)


@pytest.fixture
def cli(program, tmp_path):
    return Runner(program, str(tmp_path))
