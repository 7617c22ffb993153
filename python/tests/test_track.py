"""frictionlab.track: a phone's video of the paper's rig (assets/examples/instruments/
phone-video.mp4, the lab's own `run --camera phone`) followed without clicks, giving the period
estimate_file gives for the same video, its files written, and bad input refused at the field."""
import pathlib

import pytest

import frictionlab

VIDEO = (pathlib.Path(__file__).resolve().parents[2] / "assets" / "examples" / "instruments"
         / "phone-video.mp4")


def test_track_gives_estimates_period_and_writes_its_files(tmp_path):
    report = frictionlab.track(VIDEO, out=tmp_path)
    assert report["unit"] == "px"
    assert report["mm_per_px"] is None
    assert report["video"]["codec"] == "h264"
    assert report["periods_used"] >= 10
    # The paper's rig: T = 0.7766 s (its trajectory's), within 0.05 %.
    assert report["period_s"] == pytest.approx(0.7766, rel=5e-4)
    estimate = frictionlab.estimate_file(VIDEO)
    assert estimate.instrument == "video"
    assert report["period_s"] == pytest.approx(estimate.period, rel=1e-6)
    assert (tmp_path / "track.csv").is_file()
    assert (tmp_path / "track.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # The table it wrote reads as a position table with the same period.
    assert frictionlab.estimate_file(tmp_path / "track.csv").period == pytest.approx(
        estimate.period, rel=1e-5)


def test_millimetres_from_the_plates_length(tmp_path):
    report = frictionlab.track(VIDEO, out=tmp_path, plate_length="200mm")
    assert report["unit"] == "mm"
    assert report["scale_from"] == "plate length"
    # The run's 30 mm swing, within what the rig's patterned plate leaves (docs/physics.md).
    assert report["amplitude"] == pytest.approx(30.0, rel=0.15)


def test_a_bad_region_is_refused_at_its_field(tmp_path):
    with pytest.raises(frictionlab.InputError) as refused:
        frictionlab.track(VIDEO, out=tmp_path, roi="1,2,3")
    assert "roi" in str(refused.value)
    assert "expected the region as X,Y,W,H" in str(refused.value)
