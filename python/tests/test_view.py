"""obscura.view: the live view started from Python (docs/view.md) serves its page with the
token, renders the camera it was given, and stops."""

import json
import urllib.error
import urllib.request

import pytest

import obscura
from conftest import cli_path


def get(url):
    with urllib.request.urlopen(url, timeout=60) as response:
        return response.status, response.read()


def test_view_serves_and_stops():
    if not cli_path():
        pytest.skip("the obscura CLI is not available (run through ctest)")
    with obscura.view("cornell-box", {"fstop": 4.0, "position": (0.3, 0.3, -0.7)},
                      width=48, height=32, spp=1, cli=cli_path()) as live:
        assert live.url.startswith("http://127.0.0.1:%d/?token=" % live.port)
        status, page = get(live.url)
        assert status == 200 and b"view.js" in page
        with pytest.raises(urllib.error.HTTPError) as refused:
            get("http://127.0.0.1:%d/api/state" % live.port)
        assert refused.value.code == 403
        for _ in range(600):
            state = json.loads(get("http://127.0.0.1:%d/api/state?token=%s"
                                   % (live.port, live.token))[1])
            if state.get("frame") and state["frame"]["final"]:
                break
            __import__("time").sleep(0.1)
        frame = state["frame"]
        assert (frame["width"], frame["height"]) == (48, 32)
        assert "--fstop 4.0" in frame["command"] and "--position 0.3,0.3,-0.7" in frame["command"]
        assert frame["camera"]["resolved"]["depth_of_field"]
        assert "<a href" in live._repr_html_()
    assert not live.running()


def test_view_reports_a_bad_start():
    if not cli_path():
        pytest.skip("the obscura CLI is not available (run through ctest)")
    with pytest.raises(obscura.Error, match="no-such-scene"):
        obscura.view("no-such-scene", cli=cli_path())
