"""run's frames (video, frames, still), as `frictionlab run --still` and its options draw them, in
a build with rendering; in one without, the error says what is missing."""

import os
import struct

import pytest

import frictionlab as fl
from conftest import SCENES

pytestmark = pytest.mark.slow  # a GL context and a renderer

HAS_VIDEO = os.environ.get("FRICTIONLAB_HAS_VIDEO_MODULE", "1") == "1"


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", head[16:24])


@pytest.mark.skipif(not HAS_VIDEO, reason="this build has no video module")
def test_still_and_frames(tmp_path):
    r = fl.run(SCENES / "minimal.yaml", duration="0.2s", still=tmp_path / "end.png",
               frames=tmp_path / "frames", size=(320, 180), fps=10)
    assert png_size(tmp_path / "end.png") == (320, 180)
    # Frame k shows t = k / fps: ceil(0.2 s x 10 fps) frames.
    assert r.video.frames == 2 and (r.video.width, r.video.height) == (320, 180)
    assert sorted(p.name for p in (tmp_path / "frames").iterdir()) == [
        "frame_000000.png", "frame_000001.png"]
    # Drawing changes nothing of the run.
    plain = fl.run(SCENES / "minimal.yaml", duration="0.2s")
    assert r.trajectory["x_m"].tobytes() == plain.trajectory["x_m"].tobytes()


@pytest.mark.skipif(HAS_VIDEO, reason="this build has a video module")
def test_without_rendering_says_what_is_missing(tmp_path):
    with pytest.raises(RuntimeError, match="video"):
        fl.run(SCENES / "minimal.yaml", duration="0.2s", still=tmp_path / "end.png")


def test_bad_video_options_are_input_errors(tmp_path):
    with pytest.raises(fl.InputError, match=r"^size: error: expected WIDTHxHEIGHT"):
        fl.run(SCENES / "minimal.yaml", duration="0.2s", still=tmp_path / "x.png", size="320x18x")
