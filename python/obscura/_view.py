"""``obscura.view``: the live view (docs/view.md) from Python — a notebook or a script starts
``obscura view`` and gets its page's address back."""

import os
import shutil
import subprocess
import threading


class View:
    """A running ``obscura view``: the page's address (``url``, with its token), ``port`` and
    ``token``. ``stop()`` ends the server; so does leaving a ``with`` block. In a notebook the
    object shows as a link to the page."""

    def __init__(self, process, url):
        self._process = process
        self.url = url
        self.port = int(url.split(":")[2].split("/")[0])
        self.token = url.rsplit("token=", 1)[1]

    def running(self):
        """Whether the server is still running."""
        return self._process.poll() is None

    def stop(self):
        """Stops the server (SIGTERM) and returns its exit status."""
        if self._process.poll() is None:
            self._process.terminate()
            try:
                self._process.wait(30)
            except subprocess.TimeoutExpired:
                self._process.kill()
                self._process.wait()
        return self._process.returncode

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()

    def __repr__(self):
        return f"obscura.View({self.url!r})"

    def _repr_html_(self):
        return f'<a href="{self.url}" target="_blank">Obscura live view: {self.url}</a>'


def _flags(options):
    """{"fstop": 2.8, "position": (0, 1, 2), "no_watch": True} → --fstop 2.8 --position 0,1,2 …"""
    args = []
    for key, value in options.items():
        if value is None or value is False:
            continue
        flag = "--" + key.replace("_", "-")
        if value is True:
            args.append(flag)
        elif isinstance(value, (list, tuple)):
            args += [flag, ",".join(repr(float(v)) if isinstance(v, float) else str(v)
                                    for v in value)]
        else:
            args += [flag, repr(value) if isinstance(value, float) else str(value)]
    return args


def view(scene=None, camera=None, *, port=0, open=False, cli=None, timeout=120.0, **options):
    """Starts ``obscura view`` on ``scene`` (a built-in scene's name or a scene file; None: the
    Cornell box) and returns a ``View`` once it serves, with the page's address in ``url``.

    ``camera``: a dict of the command line's camera options by name, underscores for dashes
    (``{"fstop": 2.8, "position": (0, 1, 3), "look_at": (0, 0.5, 0)}``); ``options``: any other
    option of ``obscura render`` the same way (``width=640, height=360, spp=64``). ``port``: 0
    for a free one; ``open``: ask the desktop to open the page. ``cli``: the ``obscura``
    executable (default: $OBSCURA_CLI, else ``obscura`` on PATH). Raises ``Error`` when the
    server does not start (the message is its own), ``FileNotFoundError`` without an executable.
    """
    from ._obscura import Error

    executable = cli or os.environ.get("OBSCURA_CLI") or shutil.which("obscura")
    if not executable:
        raise FileNotFoundError("obscura.view runs the `obscura` command: put it on PATH, set "
                                "OBSCURA_CLI or pass cli=")
    args = [executable, "view"] + ([str(scene)] if scene is not None else [])
    args += _flags(dict(camera or {})) + _flags(options) + ["--port", str(int(port))]
    if open:
        args.append("--open")
    process = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    first = []
    reader = threading.Thread(target=lambda: first.append(process.stdout.readline()), daemon=True)
    reader.start()
    reader.join(timeout)
    line = first[0].strip() if first else ""
    if not line.startswith("http://127.0.0.1:"):
        if process.poll() is None:
            process.kill()
        process.wait()
        raise Error(process.stderr.read().strip() or "obscura view did not start")
    # The server's messages go on to this process's stderr.
    threading.Thread(target=lambda: [os.sys.stderr.write(l) for l in process.stderr],
                     daemon=True).start()
    return View(process, line)
