"""Jupyter kernels forked from one warm process, inside the sandbox (copied there).

Starting a kernel costs about a CPU-second before the first cell runs: a new
interpreter imports ipykernel, then the notebook imports numpy, scipy and
matplotlib. nbval starts one kernel per lesson, so a student with eight
lessons pays that eight times. Here one *warm* process (the fork server)
imports all of that once; each kernel is a fresh ``fork()`` of it, so every
lesson still starts from the same clean state and no lesson's globals can
reach another's (the server never runs notebook code).

Two roles, one file:

- ``python fork_kernel.py serve SOCKET`` (started by ``nbval_runner.py``):
  import, listen on the Unix socket ``SOCKET``, print ``ready``; for each
  request fork a child that becomes an ipykernel with the given connection
  file, working folder and environment. It exits when its parent closes its
  stdin.
- ``python fork_kernel.py connect SOCKET CONNECTION_FILE``: the kernel
  command that jupyter_client starts (see :func:`kernel_argv`). It asks the
  server for a kernel and stands in for it: SIGINT and SIGTERM are passed on,
  it exits when the kernel does, and when it is killed the server kills the
  kernel, so jupyter_client's interrupt, shutdown and kill work as with an
  ordinary kernel.

Examples
--------
>>> kernel_argv("/tmp/.kernels")  # doctest: +SKIP
['/usr/bin/python3', '/sandbox/fork_kernel.py', 'connect', '/tmp/.kernels', '{connection_file}']
"""

from __future__ import annotations

import json
import os
import select
import signal
import socket
import sys

WARM_MODULES = (
    "numpy",
    "scipy.linalg",
    "scipy.spatial.transform",
    "matplotlib",
    "matplotlib.pyplot",
    "ipykernel.kernelapp",
    "ipykernel.ipkernel",
    "IPython.core.interactiveshell",
)


def kernel_argv(socket_path: str) -> list[str]:
    """The kernelspec ``argv`` that gets a kernel from the fork server at ``socket_path``."""
    return [sys.executable, os.path.abspath(__file__), "connect", socket_path, "{connection_file}"]


# ---------------------------------------------------------------- the server
def _warm_up():
    os.environ.setdefault("MPLBACKEND", "agg")
    for name in WARM_MODULES:
        try:
            __import__(name)
        except Exception:  # noqa: BLE001 - a module that fails to import here fails in the kernel, as usual
            pass


def _become_kernel(request):
    """In the forked child: adopt the client's folder and environment, then run ipykernel until it ends."""
    devnull = os.open(os.devnull, os.O_RDWR)  # as nbval's own kernels: no inherited pipes to the runner
    for fd in (0, 1, 2):
        os.dup2(devnull, fd)
    os.environ.clear()
    os.environ.update(request["env"])
    os.chdir(request["cwd"])
    sys.path[0] = request["cwd"]  # as `python -m ipykernel_launcher` would have it (not this script's folder)
    from ipykernel.kernelapp import IPKernelApp

    try:
        IPKernelApp.launch_instance(argv=["-f", request["connection_file"]])
    finally:
        os._exit(0)


def _read_request(connection):
    data = b""
    while not data.endswith(b"\n"):
        chunk = connection.recv(65536)
        if not chunk:
            return None
        data += chunk
        if len(data) > 1 << 20:
            return None
    return json.loads(data)


def serve(socket_path: str) -> None:
    """Warm up, then fork a kernel per request until stdin closes.

    The server keeps each client's connection: when the kernel exits it closes
    it (the client then exits too), and when the client goes away (killed by
    jupyter_client) it kills the kernel, even one stuck in C code.
    """
    _warm_up()
    wake_read, wake_write = os.pipe()
    os.set_blocking(wake_write, False)
    signal.set_wakeup_fd(wake_write)
    signal.signal(signal.SIGCHLD, lambda number, frame: None)
    server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    if os.path.exists(socket_path):
        os.unlink(socket_path)
    old_mask = os.umask(0o077)
    server.bind(socket_path)
    os.umask(old_mask)
    server.listen(16)
    print("ready", flush=True)
    os.dup2(os.open(os.devnull, os.O_WRONLY), 1)
    kernels = {}  # connection -> kernel pid
    while True:
        try:
            ready, _, _ = select.select([server, sys.stdin, wake_read, *kernels], [], [])
        except InterruptedError:
            continue
        if sys.stdin in ready and not os.read(sys.stdin.fileno(), 1):
            for pid in kernels.values():
                _kill(pid)
            os._exit(0)  # the runner has finished
        if wake_read in ready:
            os.read(wake_read, 512)
            for pid in _reap():
                for connection in [c for c, kernel in kernels.items() if kernel == pid]:
                    connection.close()
                    del kernels[connection]
        for connection in [c for c in ready if c in kernels]:
            if not connection.recv(64):  # the client is gone
                _kill(kernels.pop(connection))
                connection.close()
        if server in ready:
            connection, _ = server.accept()
            try:
                request = _read_request(connection)
            except (OSError, ValueError):
                request = None
            if not isinstance(request, dict):
                connection.close()
                continue
            pid = os.fork()
            if pid == 0:
                signal.set_wakeup_fd(-1)
                signal.signal(signal.SIGCHLD, signal.SIG_DFL)
                for fd in (wake_read, wake_write):
                    os.close(fd)
                for other in (server, connection, *kernels):
                    other.close()
                _become_kernel(request)
            connection.sendall(f"{pid}\n".encode())
            kernels[connection] = pid


def _reap():
    """The pids of every child that has exited since the last call (and are now reaped)."""
    done = []
    while True:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return done
        if pid == 0:
            return done
        done.append(pid)


def _kill(pid):
    try:
        os.kill(pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


# ---------------------------------------------------------------- the client
def connect(socket_path: str, connection_file: str) -> None:
    """Ask the server for a kernel; pass signals on; exit with it."""
    client = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    client.connect(socket_path)
    request = {"connection_file": os.path.abspath(connection_file), "cwd": os.getcwd(), "env": dict(os.environ)}
    client.sendall((json.dumps(request) + "\n").encode())
    answer = b""
    while not answer.endswith(b"\n"):
        chunk = client.recv(64)
        if not chunk:
            sys.exit(1)
        answer += chunk
    pid = int(answer)
    for signum in (signal.SIGINT, signal.SIGTERM, signal.SIGQUIT, signal.SIGHUP):
        signal.signal(signum, lambda number, frame: os.kill(pid, number))
    while True:  # EOF once the kernel has exited (the server then closes the other end)
        try:
            if not client.recv(64):
                break
        except InterruptedError:
            continue
    sys.exit(0)


if __name__ == "__main__":
    if sys.argv[1:2] == ["serve"]:
        serve(sys.argv[2])
    elif sys.argv[1:2] == ["connect"]:
        connect(sys.argv[2], sys.argv[3])
    else:
        sys.exit("usage: fork_kernel.py serve SOCKET | connect SOCKET CONNECTION_FILE")
