"""Offscreen frames drawn in a child process, so that the caller's process loads no OpenGL library.

Mesa's EGL, the CPU renderer (llvmpipe), loads its driver with ``RTLD_GLOBAL``, and with it
Mesa's own LLVM (``libLLVM-15.so.1`` on Debian 12). A library loaded after it that carries
another LLVM and exports its symbols unversioned, such as PyTorch's triton (``import
triton``, which ``torch.compile`` makes), then has its LLVM calls bound to Mesa's copy: its
static constructors run LLVM 15's code on its own LLVM's objects and the process dies of a
segmentation fault. (Loaded the other way round, each keeps its own: Mesa's symbols are
versioned.) So :func:`sailmujoco.video.record`, ``render_mode="rgb_array"`` of the Gymnasium
environments and the film of ``sailmujoco sitl`` draw through :class:`ChildRenderer`: a
:class:`~sailmujoco.video.scene.SceneRenderer` in a fresh interpreter of the same Python (the
caller's ``sys.path``, environment and working folder), started with ``subprocess``, not
``multiprocessing``, so that a script without an ``if __name__ == "__main__"`` guard, or a
daemonic worker (Stable-Baselines3's ``SubprocVecEnv``, a Dask worker), can use it.

The caller sends each :class:`~sailmujoco.video.scene.Snapshot` (a few hundred bytes) over a
socket pair and gets the frame's pixels back, the same pixels as the same renderer draws in
the caller's process, since it is the same renderer fed the same snapshots in the same order.
The child ignores Ctrl-C (the caller decides), ends when it is closed, when the caller's end of
the socket closes (the caller died), or at the caller's exit; it is always waited for, so no
zombie stays. Its errors come back as one line: :class:`~sailmujoco.video.gl.RenderingUnavailable`
with the fixes, a bad argument's ``ValueError`` or ``TypeError`` as raised there, anything
else as a ``RuntimeError`` naming the process and the error.
"""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import weakref
from multiprocessing.connection import Connection

import numpy as np

from .gl import RenderingUnavailable, check_rendering

_BOOT = ("import sys, json; sys.path[:] = json.loads(sys.argv[2]); "
         "from sailmujoco.video.child import serve; serve(int(sys.argv[1]))")
_PASSED = {"RenderingUnavailable": RenderingUnavailable, "ValueError": ValueError, "TypeError": TypeError}
_WAIT_S = 10.0  # s, how long a closing child may take before it is killed


class ChildRenderer:
    """A :class:`~sailmujoco.video.scene.SceneRenderer` in a child process.

    Made with no scene: the child starts, loads the GL platform and makes a context (so a
    machine that cannot render says so here, before a run is loaded); :meth:`open` then builds
    the scene, :meth:`render` draws it. Close it (or use it as a context manager); one never
    closed is closed when it is garbage-collected or at exit.

    Raises
    ------
    RenderingUnavailable
        No OpenGL platform loads in the child (the message names the fixes).
    """

    def __init__(self):
        ours, theirs = socket.socketpair()
        with theirs:
            command = [sys.executable, "-c", _BOOT, str(theirs.fileno()), json.dumps(sys.path)]
            process = subprocess.Popen(command, pass_fds=(theirs.fileno(),), stdin=subprocess.DEVNULL)
        self._process, self._conn, self._owner = process, Connection(ours.detach()), os.getpid()
        self._finalizer = weakref.finalize(self, _stop, process, self._conn, self._owner)
        self.pid = process.pid
        self.width = self.height = None
        try:
            self._call(None)  # the child's first word: ready, or why not
        except BaseException:
            self.close()
            raise

    def open(self, *args, **kwargs) -> ChildRenderer:
        """Build the scene in the child (closing the one it had), as ``SceneRenderer(*args, **kwargs)``.

        Parameters
        ----------
        *args
            :class:`~sailmujoco.video.scene.SceneRenderer`'s positional arguments (``params``,
            ``width``, ``height``, ``camera``).
        **kwargs
            Its keyword arguments (``offscreen`` excepted: the child draws offscreen).

        Returns
        -------
        ChildRenderer
            Itself, with ``width`` and ``height`` the frame's size.
        """
        self.width = self.height = None
        self.width, self.height = self._call(("open", args, kwargs))
        return self

    def render(self, snap, note: str | None = None, camera=None) -> np.ndarray:
        """One RGB frame (height, width, 3) uint8, as :meth:`SceneRenderer.render
        <sailmujoco.video.scene.SceneRenderer.render>` draws it.

        Parameters
        ----------
        snap : Snapshot
            The state drawn.
        note : str, optional
            A red note.
        camera : tuple, optional
            A free camera's (look-at point, distance, azimuth deg, elevation deg).
        """
        if self.width is None:
            raise RuntimeError("ChildRenderer.render() needs open() first")
        return self._call(("render", snap, note, camera), pixels=True)

    def close(self) -> None:
        """Close the scene and end the child process (waited for)."""
        self._finalizer()

    def __enter__(self) -> ChildRenderer:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def _call(self, message, pixels: bool = False):
        """Send ``message`` (None: send nothing) and return the child's answer (with ``pixels``,
        the frame whose shape it gives, received after it), raising its error."""
        if not self._finalizer.alive:
            raise RuntimeError("this ChildRenderer is closed")
        if os.getpid() != self._owner:
            raise RuntimeError("this ChildRenderer belongs to the process that made it, not to one forked "
                               "from it: make the environment or the renderer in this process")
        try:
            if message is not None:
                self._conn.send(message)
            answer = self._conn.recv()
            if pixels and answer[0] == "ok":
                frame = np.empty(answer[1], np.uint8)
                self._conn.recv_bytes_into(frame.reshape(-1))
                return frame
        except (EOFError, OSError):
            self._finalizer()
            raise RuntimeError(f"the renderer's process (pid {self.pid}) {_ended(self._process)}") from None
        except BaseException:  # Ctrl-C between a question and its answer: the child is out of step
            self._finalizer()
            raise
        if answer[0] == "error":
            name, text = answer[1], answer[2]
            if name in _PASSED:
                raise _PASSED[name](text)
            raise RuntimeError(f"the renderer's process failed: {name}: {text}")
        return answer[1]


def _ended(process: subprocess.Popen) -> str:
    """How the child ended: "ended with exit status N" or "was killed by SIGNAME"."""
    try:
        code = process.wait(_WAIT_S)
    except subprocess.TimeoutExpired:
        return "stopped answering"
    if code < 0:
        return f"was killed by {signal.Signals(-code).name}"
    return f"ended with exit status {code}"


def _stop(process: subprocess.Popen, conn: Connection, owner: int) -> None:
    """End the child: ask it to close, wait for it, kill it if it does not end; then reap it.
    Nothing in a process forked from the ``owner`` process (the child is the owner's)."""
    if os.getpid() != owner:
        return
    try:
        conn.send(("close",))
        if conn.poll(_WAIT_S):
            conn.recv_bytes()  # its answer, or one it owed before (a Ctrl-C came between)
    except (EOFError, OSError):
        pass
    conn.close()
    try:
        process.wait(_WAIT_S)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()


# ----------------------------------------------------------------------------- the child's side
def serve(fd: int) -> None:
    """The child's loop: answer the messages that arrive on the socket ``fd`` until closed.

    Parameters
    ----------
    fd : int
        The child's end of the socket pair.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    conn = Connection(fd)
    scene = None
    try:
        conn.send(_attempt(check_rendering)[1])
        while (message := conn.recv())[0] != "close":
            if message[0] == "open":
                if scene is not None:
                    scene.close()
                scene = None
                scene, answer = _attempt(_open, *message[1:])
                conn.send(answer)
            else:
                frame, answer = _attempt(_draw, scene, *message[1:])
                conn.send(answer)
                if frame is not None:
                    conn.send_bytes(frame.reshape(-1))
        conn.send(("ok", None))
    except (EOFError, OSError):  # the caller is gone
        pass
    finally:
        if scene is not None:
            scene.close()
        conn.close()


def _open(args: tuple, kwargs: dict):
    from .scene import SceneRenderer

    return SceneRenderer(*args, **kwargs)


def _draw(scene, snap, note, camera):
    if scene is None:
        raise RuntimeError("no scene is open")
    return scene.render(snap, note, camera)


def _attempt(fn, *args):
    """``fn(*args)``'s (result, answer): the answer is ("ok", what the caller needs: None, a
    scene's (width, height), a frame's shape) or, where ``fn`` raised, ("error", its type's name,
    its message), with the result None."""
    try:
        result = fn(*args)
    except Exception as err:
        return None, ("error", type(err).__name__, str(err))
    if result is None:
        return None, ("ok", None)
    if isinstance(result, np.ndarray):
        frame = np.ascontiguousarray(result, np.uint8)
        return frame, ("ok", frame.shape)
    return result, ("ok", (result.width, result.height))
