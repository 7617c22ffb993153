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


@pytest.mark.skipif(not HAS_VIDEO, reason="this build has no video module")
def test_title_orbit_and_captions(tmp_path):
    base = dict(duration="0.2s", size=(320, 180), fps=10)
    # A title turns the card on: 2 s x 10 fps of it before the run's 2 frames.
    r = fl.run(SCENES / "minimal.yaml", frames=tmp_path / "titled", title="Friction", **base)
    assert (r.video.title_frames, r.video.frames) == (20, 22)
    plain = fl.run(SCENES / "minimal.yaml", still=tmp_path / "plain.png", **base)
    assert plain.video.title_frames == 0
    # The orbit turns the view by 90 deg/s x 0.2 s at the last step; captions add a subtitle.
    fl.run(SCENES / "minimal.yaml", still=tmp_path / "orbit.png", orbit="90deg/s", **base)
    captions = tmp_path / "captions.yaml"
    captions.write_text("captions:\n  - at: 0 s\n    text: The plate swings.\n")
    fl.run(SCENES / "minimal.yaml", still=tmp_path / "caption.png", captions=captions, **base)
    empty = tmp_path / "none.yaml"
    empty.write_text("captions: []\n")
    fl.run(SCENES / "minimal.yaml", still=tmp_path / "none.png", captions=empty, **base)
    still = {n: (tmp_path / f"{n}.png").read_bytes() for n in ("plain", "orbit", "caption", "none")}
    assert still["orbit"] != still["plain"]
    assert still["caption"] != still["none"]
    assert still["none"] == still["plain"]  # the minimal scene has no captions of its own
    # The still turns as the frame after the video's last would, with or without the video.
    fl.run(SCENES / "minimal.yaml", still=tmp_path / "with.png", frames=tmp_path / "orbiting",
           orbit="90deg/s", **base)
    assert (tmp_path / "with.png").read_bytes() == still["orbit"]


def test_frame_arguments_without_frames_are_refused(tmp_path):
    for name, value in [("title", "Friction"), ("orbit", "10deg/s"), ("camera", "top"),
                        ("fps", 10), ("captions", tmp_path / "c.yaml")]:
        with pytest.raises(fl.InputError, match=rf"^{name}: error: this shapes the frames"):
            fl.run(SCENES / "minimal.yaml", duration="0.2s", **{name: value})


def test_a_bad_captions_file_is_located(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("captions:\n  - at: 2 s\n    text: later\n  - at: 1 s\n    text: earlier\n")
    with pytest.raises(fl.InputError, match=r"bad\.yaml:4:\d+: error: captions\[1\]\.at: expected a time after"):
        fl.run(SCENES / "minimal.yaml", duration="0.2s", still=tmp_path / "x.png", captions=bad)
