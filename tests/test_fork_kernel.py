"""Forked kernels (autograder/sandbox/child/fork_kernel.py) behave like ordinary ones, and lessons stay apart.

Oracles: a kernel forked from the warm server runs code and has numpy already
imported; what one kernel changes (a global, an attribute set on the numpy
module) is invisible in the next; jupyter_client's interrupt stops a loop;
killing the stand-in process (what jupyter_client does on shutdown) ends the
kernel too, and closing the server's stdin ends the server.
"""

import os
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from jupyter_client import KernelManager
from jupyter_client.kernelspec import KernelSpec, KernelSpecManager

from autograder.lessons.paths import PACKAGE

FORK_KERNEL = PACKAGE / "sandbox" / "child" / "fork_kernel.py"


@pytest.fixture
def server(tmp_path):
    socket_path = str(tmp_path / ".kernels")
    process = subprocess.Popen(
        [sys.executable, str(FORK_KERNEL), "serve", socket_path],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        cwd=tmp_path,
        env=dict(os.environ, MPLBACKEND="agg"),
    )
    assert process.stdout.readline().strip() == b"ready"
    yield socket_path, process
    process.stdin.close()
    process.wait(timeout=10)


def _kernel(socket_path, cwd):
    argv = [sys.executable, str(FORK_KERNEL), "connect", socket_path, "{connection_file}"]

    class Specs(KernelSpecManager):
        def get_kernel_spec(self, kernel_name):
            return KernelSpec(argv=argv, display_name="forked", language="python")

    manager = KernelManager(kernel_name="forked", kernel_spec_manager=Specs())
    manager.start_kernel(cwd=str(cwd))
    client = manager.client()
    client.start_channels()
    client.wait_for_ready(timeout=60)
    return manager, client


def _run(client, code, timeout=30):
    """(printed text, error name or None) of one cell, waiting for its reply as nbval does."""
    printed, error = [], []

    def collect(message):
        if message["msg_type"] == "stream":
            printed.append(message["content"]["text"])
        elif message["msg_type"] == "error":
            error.append(message["content"]["ename"])

    client.execute_interactive(code, timeout=timeout, output_hook=collect)
    return "".join(printed), (error or [None])[0]


def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return True


def test_forked_kernels_run_code_and_share_nothing(server, tmp_path):
    socket_path, _ = server
    first, first_client = _kernel(socket_path, tmp_path)
    try:
        printed, error = _run(
            first_client,
            "import sys, os, numpy\nLEAK = 1\nnumpy.LEAKED = 1\nprint('numpy' in sys.modules, os.getcwd())",
        )
        assert error is None and printed.split() == ["True", str(tmp_path)]
    finally:
        first_client.stop_channels()
        first.shutdown_kernel(now=True)
    second, second_client = _kernel(socket_path, tmp_path)
    try:
        printed, error = _run(second_client, "import numpy\nprint('LEAK' in globals(), hasattr(numpy, 'LEAKED'))")
        assert (printed.split(), error) == (["False", "False"], None)
    finally:
        second_client.stop_channels()
        second.shutdown_kernel(now=True)


def test_interrupt_and_kill_reach_the_forked_kernel(server, tmp_path):
    socket_path, process = server
    manager, client = _kernel(socket_path, tmp_path)
    try:
        pid = int(_run(client, "import os\nprint(os.getpid())")[0])
        threading.Timer(1.0, manager.interrupt_kernel).start()
        assert _run(client, "while True:\n    pass\n")[1] == "KeyboardInterrupt"
        assert _run(client, "print(6 * 7)")[0].strip() == "42"  # the same kernel goes on
    finally:
        client.stop_channels()
        manager.shutdown_kernel(now=True)  # SIGKILL to the stand-in: the server kills the kernel
    deadline = time.monotonic() + 10
    while _alive(pid) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not _alive(pid), "the forked kernel outlived its stand-in"
    assert process.poll() is None, "the server stopped with its kernel"


def test_the_server_leaves_when_its_runner_does(tmp_path):
    socket_path = str(tmp_path / ".kernels")
    process = subprocess.Popen(
        [sys.executable, str(FORK_KERNEL), "serve", socket_path],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        cwd=tmp_path,
    )
    assert process.stdout.readline().strip() == b"ready"
    process.stdin.close()
    assert process.wait(timeout=10) == 0
    assert Path(socket_path).exists()
