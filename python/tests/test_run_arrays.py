"""The recordings' arrays: their documented shapes and fields, in SI, held against the scene and
against what the physics must satisfy."""

import numpy as np

import frictionlab as fl
from conftest import SCENES


def upward_crossings(duration, period):
    """Of x = A cos(2 pi t / T) over [0, duration]: at t = (k + 3/4) T."""
    return int(np.floor(duration / period - 0.75)) + 1


def test_trajectory_rows_and_time_column():
    scene = fl.load_scene(SCENES / "minimal.yaml")
    r = fl.run(scene)
    trajectory = r.trajectory
    assert trajectory.shape == (r.steps + 1,)  # the start and every step
    t = trajectory["t_s"]
    assert t[0] == 0.0
    # The step is the scene's (to the rounding of t = n dt), in seconds.
    np.testing.assert_allclose(np.diff(t), scene["world.time_step"], rtol=1e-9)
    np.testing.assert_allclose(t[-1], scene["world.duration"], rtol=1e-12)
    for name in ("x_m", "z_m", "pitch_rad", "vx_m_s", "vz_m_s", "pitch_rate_rad_s", "y_m",
                 "yaw_rad", "normal0_n", "friction0_n", "penetration0_m", "normal1_n",
                 "friction1_n", "penetration1_m"):
        assert trajectory[name].dtype == np.float64, name
    for name in ("touching0", "stuck0", "touching1", "stuck1"):
        assert trajectory[name].dtype == np.bool_, name


def test_trajectory_units_agree_with_each_other():
    scene = fl.load_scene(SCENES / "minimal.yaml")
    trajectory = fl.run(scene, duration="3s").trajectory
    x, vx = trajectory["x_m"], trajectory["vx_m_s"]
    dt = scene["world.time_step"]
    # Semi-implicit Euler: x[n+1] = x[n] + vx[n+1] dt; metres and metres per second agree.
    np.testing.assert_allclose(np.diff(x) / dt, vx[1:], rtol=0, atol=1e-12)
    # The plate rests on the rollers: its weight is the two normal forces (N), m g.
    weight = fl.run(scene, duration="3s", record=False).plate_mass * scene["world.gravity"]
    total = trajectory["normal0_n"][1:] + trajectory["normal1_n"][1:]
    np.testing.assert_allclose(total, weight, rtol=1e-6)


def test_the_plate_stays_within_the_analytic_amplitude():
    # Released at rest at x = A0 with both rollers slipping: x(t) = A0 cos(Omega t), |x| <= A0,
    # to the integrator's drift (below 1e-5 of the amplitude per period at 1 ms,
    # docs/researchers.md).
    scene = fl.load_scene(SCENES / "minimal.yaml")
    r = fl.run(scene)
    a0 = scene["plate.offset"]
    periods = r.duration / r.period_thick
    x = r.trajectory["x_m"]
    assert np.max(np.abs(x)) <= a0 * (1 + 1e-5 * periods)
    # ... and it reaches it on both sides, once a period.
    assert np.max(x) >= a0 * (1 - 1e-5 * periods) and np.min(x) <= -a0 * (1 - 1e-5 * periods)
    # Upward crossings of the centre at t = (k + 3/4) T, k = 0, 1, ...
    crossings = np.count_nonzero(np.diff(np.sign(x)) > 0)
    assert crossings == upward_crossings(r.duration, r.period_thick)


def test_hall_samples_are_the_boards_clock_and_counts():
    scene = fl.load_scene(SCENES / "minimal.yaml")
    r = fl.run(scene)
    hall = r.hall
    rate = scene["sensor.sample_rate"]
    assert hall.shape == (round(r.duration * rate) + 1,)
    assert hall["t_us"].dtype == np.uint32 and hall["adc"].dtype == np.uint16
    # Stamped by the board's clock in microseconds, one sample every 1 / rate.
    assert np.all(np.diff(hall["t_us"].astype(np.int64)) == round(1e6 / rate))
    assert hall["adc"].max() <= 2 ** scene["sensor.adc_bits"] - 1
    # A pulse each time a magnet passes under the sensor: the estimator's count.
    assert r.estimator.pulses > 0


def test_cycles_are_the_plates_cycles():
    r = fl.run(SCENES / "minimal.yaml")
    cycles = r.cycles
    assert cycles.dtype.names == ("start_s", "period_s", "amplitude_m", "x_min_m", "x_max_m",
                                  "surface_speed_m_s", "stick_s")
    # A cycle runs from one upward crossing of the centre to the next.
    assert len(cycles) == upward_crossings(r.duration, r.period_thick) - 1
    np.testing.assert_allclose(cycles["period_s"], r.period_trajectory, rtol=1e-6)
    np.testing.assert_array_equal(cycles["stick_s"], 0.0)  # full slip


def test_no_sensor_no_hall_array():
    r = fl.run(fl.load_scene(SCENES / "minimal.yaml", set={"sensor": None, "magnets": []}),
               duration="2s")
    assert r.hall is None and r.estimator is None


def test_columns_are_views_of_the_recording():
    r = fl.run(SCENES / "minimal.yaml", duration="1s")
    x = r.trajectory["x_m"]
    assert not x.flags["OWNDATA"] and x.base is not None
    assert r.trajectory.strides[0] >= 8 * 9  # one row per step, fields side by side


def test_phones_record_what_the_plate_does_in_their_own_axes(tmp_path):
    # A still-air phone far from the magnets reads the Earth's field; one lying on the plate
    # (its top along +x, no g, no noise) reads -omega^2 x along its y, omega from the plate's own
    # period (its trajectory's), to within what a step's acceleration changes by (A omega^3 dt):
    # Bullet's semi-implicit step changes the velocity by the force at the step's start, so each
    # sample reads the acceleration of up to one step earlier.
    phones = ("[{sensor: magnetometer, noise: 0 uT, position: [50 m, 50 m, 0 m]},"
              " {sensor: accelerometer, noise: 0 m/s^2, gravity: false, mass: 100 g}]")
    scene = fl.load_scene(SCENES / "minimal.yaml", set={"phones": phones})
    assert [p.sensor for p in scene.phones] == ["magnetometer", "accelerometer"]
    r = fl.run(scene, duration="4s", out=tmp_path)
    far, on_plate = r.phones
    assert far.shape == (401,) and on_plate.shape == (1601,)  # 100 Hz and 400 Hz, t = 0 included
    np.testing.assert_allclose(far["t_s"], np.arange(401) / 100.0, rtol=0, atol=1e-12)
    # The Earth's default field, [21, -4, -43] uT in the rig's frame: in the phone's axes
    # (top along +x) x = -(-4), y = 21, z = -43; the magnets 70 m away add 5e-14 T.
    np.testing.assert_allclose(far["bx_t"], 4e-6, atol=1e-12)
    np.testing.assert_allclose(far["by_t"], 21e-6, atol=1e-12)
    np.testing.assert_allclose(far["bz_t"], -43e-6, atol=1e-12)
    t = on_plate["t_s"]
    x = np.interp(t, r.trajectory["t_s"], r.trajectory["x_m"])
    omega = 2 * np.pi / r.period_trajectory
    step = scene["world.time_step"]
    amplitude = scene["plate.offset"]
    np.testing.assert_allclose(on_plate["ay_m_s2"], -omega**2 * x,
                               rtol=0, atol=1.05 * amplitude * omega**3 * step)
    np.testing.assert_allclose(on_plate["ax_m_s2"], 0.0, atol=1e-12)
    # The files are the same samples, as phyphox writes them (nine decimals, the field in uT).
    rows = np.loadtxt(tmp_path / "phone-magnetometer.csv", delimiter=",", skiprows=1)
    np.testing.assert_allclose(rows[:, 2], far["by_t"] * 1e6, rtol=1e-9)
    rows = np.loadtxt(tmp_path / "phone-accelerometer.csv", delimiter=",", skiprows=1)
    np.testing.assert_allclose(rows[:, 2], on_plate["ay_m_s2"], rtol=1e-9, atol=1e-15)
