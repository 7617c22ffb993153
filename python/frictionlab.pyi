"""frictionlab: a virtual lab of the friction (Timoshenko) oscillator (type stubs).

The compiled module's docstrings (help(frictionlab.run)) say what each function does; these
stubs give the types. Quantities are SI; arguments that are quantities also take text with
units ("89mm", "1600rpm").
"""

import os
from typing import Any, Callable, ClassVar, Iterable, Mapping, Optional, Union

import numpy as np
import numpy.typing as npt

__version__: str

PathLike = Union[str, os.PathLike[str]]
Quantity = Union[str, float]
Overrides = Union[Mapping[str, Any], Iterable[str], None]

class InputError(ValueError):
    """Bad input; str(error) is the frictionlab command's message, file:line:column, with
    the command's options spelled as this module's arguments."""

    file: Optional[str]
    line: Optional[int]
    column: Optional[int]
    field: Optional[str]

class Regime:
    """A pybind11 enum: compare with ==; int(regime) is its value in core/regime.hpp."""

    OSCILLATES: ClassVar[Regime]
    CLIPPED: ClassVar[Regime]
    STICK_SLIP: ClassVar[Regime]
    GROWS: ClassVar[Regime]
    DECAYS: ClassVar[Regime]
    STICKS: ClassVar[Regime]
    TIPS: ClassVar[Regime]
    NO_RESTORING_FORCE: ClassVar[Regime]
    LOST: ClassVar[Regime]
    NUMERICALLY_FAILED: ClassVar[Regime]
    __members__: ClassVar[dict[str, Regime]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...
    @property
    def label(self) -> str: ...
    @property
    def harmonic(self) -> bool: ...
    @staticmethod
    def from_label(label: str) -> Regime: ...

class PeriodSource:
    HALL_ESTIMATOR: ClassVar[PeriodSource]
    TRAJECTORY: ClassVar[PeriodSource]
    __members__: ClassVar[dict[str, PeriodSource]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class Measured:
    value: float
    uncertainty: float

# ---- scenes ----

class Scene:
    class RampPoint:
        at: float
        value: float

    class World:
        gravity: float
        time_step: float
        solver_iterations: int
        duration: float
        seed: int

    class Rollers:
        spacing: float
        radius: float
        diameter: float
        length: float
        speed: float
        speed_ramp: list[Scene.RampPoint]
        wall: float
        density: float
        sense: str
        runout: float
        runout_phase: list[float]
        material: str

    class Payload:
        mass: float
        height: float

    class PlateBlock:
        part: str
        x: float
        y: float
        turn: int
        mass: float
        com_z: float
        height: float

    class Plate:
        length: float
        width: float
        thickness: float
        mass: Optional[float]
        density: float
        material: str
        payload: Scene.Payload
        blocks: list[Scene.PlateBlock]
        offset: float
        velocity: float
        sideways_velocity: float

    class Magnet:
        x: float
        height: float
        diameter: float
        thickness: float
        remanence: float
        density: float

    class Sensor:
        position: list[float]
        axis: list[float]
        sensitivity: float
        supply: float
        offset: Optional[float]
        adc_bits: int
        sample_rate: float
        noise: float
        jitter: float
        clock_error: float

    class Phone:
        sensor: str  # "magnetometer" or "accelerometer"
        rate: float
        noise: float
        turn: float
        position: list[float]
        earth: list[float]
        gravity: bool
        x: float
        height: float
        mass: float
        size: list[float]

    class Warming:
        room: float
        time_constant: float
        hold: float
        mu_k_room: Optional[float]

    class Friction:
        law: str
        mu_k: float
        mu_s: Optional[float]
        v_s: Optional[float]
        beta: float
        temperature: float
        warming: Optional[Scene.Warming]
        paper_material: Optional[str]
        paper_period: Optional[Measured]
        paper_mu_k: Optional[Measured]

    class Motor:
        rated_voltage: float
        no_load_speed: float
        stall_torque: float
        duty: float
        duty_ramp: list[Scene.RampPoint]
        inertia: float

    class GearStage:
        driver: int
        driven: int

    class Drive:
        motor: Scene.Motor
        gearbox: dict[str, list[Scene.GearStage]]
        coupling: dict[str, int]
        ratio: float

    class FramePart:
        part: str
        at: list[int]
        turn: int
        guide: bool
        position: list[float]

    class Frame:
        origin: list[float]
        parts: list[Scene.FramePart]

    class Output:
        trajectory: bool
        hall: bool
        summary: bool
        cycles: bool
        periods: bool
        jumps: bool
        phones: bool

    name: str
    file: Optional[str]
    overrides: dict[str, str]
    expected_regime: Optional[Regime]
    world: Scene.World
    rollers: Scene.Rollers
    plate: Scene.Plate
    magnets: list[Scene.Magnet]
    sensor: Optional[Scene.Sensor]
    phones: list[Scene.Phone]
    friction: Scene.Friction
    drive: Optional[Scene.Drive]
    frame: Optional[Scene.Frame]
    output: Scene.Output
    def __getitem__(self, key: str) -> Any: ...
    def get(self, key: str, default: Any = None) -> Any: ...
    def with_set(self, set: Overrides) -> Scene: ...

def load_scene(path: PathLike, *, set: Overrides = None, assets: Optional[PathLike] = None) -> Scene: ...
def parse_scene(
    text: str, name: str = "inline", *, set: Overrides = None, assets: Optional[PathLike] = None
) -> Scene: ...

# ---- runs ----

class EstimatorReport:
    periods_used: int
    periods_discarded: int
    pulses: int
    period: Optional[float]
    period_std: Optional[float]
    period_std_error: Optional[float]
    mu_k: Optional[float]
    mu_k_err_worst: Optional[float]
    mu_k_err_quadrature: Optional[float]

class DriveReport:
    motor_speed: float
    motor_torque: float
    roller_speeds: list[float]
    gearbox_ratio: float
    turning_fraction: float
    speed_ratio: Optional[float]
    speed_ratio_error: Optional[float]
    senses_opposite: Optional[bool]
    load_torque: float

class WarmingWindow:
    periods: int
    period: float
    mu_k: float

class WarmingReport:
    start_temperature: float
    room_temperature: float
    time_constant: float
    hold: float
    mu_k_start: float
    mu_k_room: float
    end_temperature: float
    mu_k_end: float
    mu_k_cold_paper_formula: float
    first_10_periods: Optional[WarmingWindow]
    first_30_s: Optional[WarmingWindow]
    whole_run: Optional[WarmingWindow]

class VideoReport:
    frames: int
    title_frames: int
    ending_frames: int
    width: int
    height: int
    fps: int
    slow_motion: float
    camera: str
    backend: str
    triangles: int
    setup_seconds: float
    render_seconds: float
    finish_seconds: float

class RunSummary:
    # generated: run-summary-attributes (tools/generate-fields, from src/lab/run/summary_fields.cpp)
    scene: str
    seed: int
    regime: Regime
    regime_since: float
    period_withheld: Optional[str]
    failure: Optional[str]
    interrupted_at: Optional[float]
    estimator_disagreement: Optional[str]
    condition_period: float
    condition_spacing: float
    condition_h_c: float
    period: Optional[float]
    period_trajectory: Optional[float]
    period_trajectory_err: Optional[float]
    oscillation_centre: Optional[float]
    oscillation_centre_theory: Optional[float]
    drift_speed: Optional[float]
    drift_speed_theory: Optional[float]
    tilt: float
    period_thin: float
    period_thick: Optional[float]
    mu_k_set: float
    mu_k_recovered: Optional[float]
    mu_k_source: Optional[PeriodSource]
    mu_k_recovered_thick: Optional[float]
    mu_k_estimator: Optional[float]
    mu_k_err_worst: Optional[float]
    mu_k_err_quadrature: Optional[float]
    estimator: Optional[EstimatorReport]
    predicted_integrator_bias: Optional[float]
    clock_error: Optional[float]
    runout: Optional[float]
    runout_threshold: Optional[float]
    spacing: float
    h_c: float
    plate_mass: float
    temperature: float
    gravity: float
    roller_speed: float
    roller_speed_1: float
    drive: Optional[DriveReport]
    plate_speed_max: float
    slip_margin: float
    slip_threshold: Optional[float]
    amplitude_start: Optional[float]
    amplitude_end: Optional[float]
    amplitude_drift_per_period: Optional[float]
    clip_time: Optional[float]
    amplitude_before_clip: Optional[float]
    amplitude_clipped: Optional[float]
    stick_slip_period: Optional[float]
    stick_slip_amplitude: Optional[float]
    stick_duration: Optional[float]
    growth_rate: Optional[float]
    e_folding_time: Optional[float]
    jumps: Optional[int]
    first_jump_time: Optional[float]
    longest_jump: Optional[float]
    highest_jump: Optional[float]
    regime_theory: Optional[Regime]
    amplitude_clipped_theory: Optional[float]
    stick_slip_period_theory: Optional[float]
    stick_slip_amplitude_theory: Optional[float]
    stick_duration_theory: Optional[float]
    growth_rate_theory: Optional[float]
    warming: Optional[WarmingReport]
    paper_material: Optional[str]
    paper_period: Optional[Measured]
    paper_mu_k: Optional[Measured]
    min_normal_force: float
    max_penetration: float
    time_step: float
    solver_iterations: int
    solver_iterations_raised: Optional[str]
    duration: float
    steps: int
    regime_evidence: str
    harmonic: bool
    wall_s: float
    real_time_factor: float
    steps_per_second: float
    # end generated
    def __getitem__(self, key: str) -> Any: ...
    def json(self) -> dict[str, Any]: ...

class RunResult(RunSummary):
    # Structured arrays (see help(frictionlab.RunResult) for their fields); None with record=False.
    trajectory: Optional[npt.NDArray[np.void]]
    hall: Optional[npt.NDArray[np.void]]
    cycles: Optional[npt.NDArray[np.void]]
    periods: Optional[npt.NDArray[np.void]]
    jump_list: Optional[npt.NDArray[np.void]]
    phones: Optional[list[npt.NDArray[np.void]]]
    video: Optional[VideoReport]
    plot_failure: Optional[str]

def run(
    scene: Union[Scene, PathLike],
    duration: Optional[Quantity] = None,
    seed: Optional[int] = None,
    out: Optional[PathLike] = None,
    *,
    accuracy: Optional[Quantity] = None,
    record: bool = True,
    plot: bool = False,
    video: Optional[PathLike] = None,
    frames: Optional[PathLike] = None,
    still: Optional[PathLike] = None,
    gl: Optional[str] = None,
    fps: Optional[int] = None,
    size: Union[str, tuple[int, int], None] = None,
    slow_motion: Optional[Quantity] = None,
    camera: Optional[str] = None,
    title: Optional[str] = None,
    orbit: Optional[Quantity] = None,
    captions: Optional[PathLike] = None,
) -> RunResult: ...

# ---- the rig's estimator ----

class Estimate:
    # generated: estimate-attributes (tools/generate-fields, from src/lab/logs/estimate_fields.cpp)
    instrument: str
    channel: Optional[str]
    duration: float
    sample_rate: float
    polarity: int
    baseline: Optional[float]
    geometry: str
    periods_used: int
    periods_discarded: int
    outliers: int
    period: float
    period_std: float
    period_std_error: float
    mu_k: float
    mu_k_err_worst: float
    mu_k_err_quadrature: float
    mu_k_thick: Optional[float]
    amplitude: Optional[float]
    amplitude_unit: Optional[str]
    spacing: float
    spacing_err: float
    gravity: float
    # end generated
    pulses: npt.NDArray[np.void]
    periods: npt.NDArray[np.void]
    def json(self) -> dict[str, Any]: ...

def estimate(
    t: npt.ArrayLike,
    adc: npt.ArrayLike,
    *,
    spacing: Quantity = "89 mm",
    spacing_err: Quantity = "2 mm",
    gravity: Quantity = "9.81 m/s^2",
    geometry: str = "auto",
    name: str = "samples",
) -> Estimate: ...
def estimate_file(
    path: PathLike,
    *,
    spacing: Quantity = "89 mm",
    spacing_err: Quantity = "2 mm",
    gravity: Quantity = "9.81 m/s^2",
    geometry: str = "auto",
    columns: str = "",
    rate: Optional[Quantity] = None,
    time_unit: str = "",
    material: Optional[str] = None,
    temperature: Optional[Quantity] = None,
    h_c: Optional[Quantity] = None,
) -> Estimate: ...

# ---- the analytic model ----

class FrictionLaw:
    kind: str
    mu_k: float
    mu_s: float
    v_s: float
    beta: float

class MuKUncertainty:
    mu_k: float
    worst: float
    quadrature: float
    condition_period: float
    condition_spacing: float
    condition_h_c: float

class StickSlipCycle:
    omega: float
    break_offset: float
    amplitude: float
    stick_duration: float
    slip_duration: float
    period: float
    clipped: bool

class LinearisedMotion:
    mu: float
    slope: float
    omega: float
    gamma: float
    period: float
    period_0: float

class FrictionRegimePrediction:
    regime: Regime
    motion: LinearisedMotion
    margin: float
    break_offset: float
    tipping_offset: float
    growth_rate: float
    settled_amplitude: Optional[float]
    stick_time: Optional[float]
    tip_time: Optional[float]
    cycle: Optional[StickSlipCycle]

class AnalyticLaw:
    law: FrictionLaw
    surface_speed: float
    mu_at_surface_speed: float
    full_slip_roller_speed: float
    break_offset: float
    cycle: Optional[StickSlipCycle]
    linearised: Optional[LinearisedMotion]
    prediction: FrictionRegimePrediction

class AnalyticReport:
    spacing: float
    spacing_err: float
    h_c: float
    gravity: float
    roller_speed: float
    amplitude: float
    source: str
    material: Optional[str]
    temperature: Optional[float]
    paper_mu_k: Optional[Measured]
    period_measured: Optional[float]
    period_measured_err: Optional[float]
    mu_k_thin: Optional[MuKUncertainty]
    mu_k_thick: Optional[MuKUncertainty]
    mu_k: float
    restoring_force: bool
    period_thin: float
    period_thick: Optional[float]
    tipping_amplitude: Optional[float]
    roller_speed_for_full_slip: Optional[float]
    slip_margin: Optional[float]
    friction_law: Optional[AnalyticLaw]
    friction_law_refused: Optional[str]
    def json(self) -> dict[str, Any]: ...

def analytic(
    *,
    spacing: Quantity = "89 mm",
    spacing_err: Quantity = "2 mm",
    mu_k: Optional[Quantity] = None,
    period: Optional[Quantity] = None,
    period_err: Optional[Quantity] = None,
    material: Optional[str] = None,
    temperature: Optional[Quantity] = None,
    h_c: Quantity = "0 mm",
    gravity: Quantity = "9.81 m/s^2",
    roller_radius: Quantity = "10 mm",
    roller_speed: Quantity = "1600 rpm",
    amplitude: Quantity = "20 mm",
    law: str = "coulomb",
    mu_s: Optional[Quantity] = None,
    v_s: Optional[Quantity] = None,
    beta: Optional[Quantity] = None,
    assets: Optional[PathLike] = None,
) -> AnalyticReport: ...

# ---- the paper's Table I ----

class PaperMeasurement:
    temperature: float
    period: Measured
    mu_k: Measured

class LiteratureRange:
    low: float
    high: float

class PaperMaterial:
    key: str
    name: str
    note: str
    room: PaperMeasurement
    cold: Optional[PaperMeasurement]
    literature: Optional[LiteratureRange]
    measurements: list[PaperMeasurement]

class PaperTable:
    source: str
    spacing: Measured
    materials: list[PaperMaterial]
    def find(self, key: str) -> Optional[PaperMaterial]: ...

def paper_table(*, assets: Optional[PathLike] = None) -> PaperTable: ...
def track(
    video: PathLike,
    *,
    out: PathLike,
    roi: str = "",
    scale: Optional[float] = None,
    plate_length: Optional[Quantity] = None,
) -> dict[str, Any]: ...
def report(
    inputs: list[PathLike],
    *,
    out: PathLike,
    student: str = "",
    stopwatch: list[tuple[int, float, Optional[float]]] = [],
    spacing: Quantity = "89 mm",
    material: Optional[str] = None,
    temperature: Optional[Quantity] = None,
    assets: Optional[PathLike] = None,
    language: str = "en",
) -> dict[str, Any]: ...
def table(
    *,
    gravity: Quantity = "9.81 m/s^2",
    h_c: Quantity = "0 mm",
    assets: Optional[PathLike] = None,
) -> dict[str, Any]: ...

# ---- sweeps ----

# Numbers as NumPy masked arrays (masked where a point has no value), text as lists.
SweepColumn = Union[np.ma.MaskedArray, list[Optional[str]]]

def sweep(
    file: PathLike,
    *,
    jobs: Optional[int] = None,
    out: Optional[PathLike] = None,
    fresh: bool = False,
    shard: Optional[str] = None,
    plot: bool = False,
    progress: Optional[Callable[[dict[str, Any]], None]] = None,
    assets: Optional[PathLike] = None,
    accuracy: Optional[Quantity] = None,
) -> dict[str, SweepColumn]: ...
def merge(
    dirs: list[PathLike], *, out: Optional[PathLike] = None, plot: bool = False
) -> dict[str, Any]: ...

# ---- a spacing series' fit ----

class FitReport:
    mu_k: Optional[float]
    mu_k_err: Optional[float]
    h_c: Optional[float]
    h_c_err: Optional[float]
    correlation: Optional[float]
    slope: float
    intercept: float
    chi2: float
    degrees_of_freedom: int
    chi2_per_dof: Optional[float]
    mu_k_thin_line: float
    mu_k_thin_line_err: float
    gravity: float
    paper: Optional[dict[str, Any]]
    written: list[str]
    plot: Optional[str]
    plot_failure: Optional[str]
    rig_failure: Optional[str]
    def json(self) -> dict[str, Any]: ...

def fit(
    series: PathLike,
    *,
    gravity: Quantity = "9.81 m/s^2",
    out: Optional[PathLike] = None,
    plot: Optional[PathLike] = None,
    mc: Optional[int] = None,
    seed: int = 1,
    through_rig: bool = False,
    scene: Union[Scene, PathLike, None] = None,
    set: Overrides = None,
    jobs: int = 0,
    material: Optional[str] = None,
    temperature: Optional[Quantity] = None,
) -> FitReport: ...

# ---- comparisons and the studies of the numerics: each returns the command's --json object ----

def compare(
    *,
    measured: Optional[PathLike] = None,
    log: Optional[PathLike] = None,
    scene: Optional[PathLike] = None,
    set: Overrides = None,
    duration: Optional[Quantity] = None,
    jobs: int = 0,
    out: PathLike = "out/compare",
    plot: bool = False,
    refit: bool = True,
    geometry: str = "",
    columns: str = "",
    rate: Optional[Quantity] = None,
    time_unit: str = "",
    assets: Optional[PathLike] = None,
    material: Optional[str] = None,
    temperature: Optional[Quantity] = None,
) -> dict[str, Any]: ...
def accuracy(
    scene: Union[Scene, PathLike],
    *,
    set: Overrides = None,
    periods: int = 10,
    out: PathLike = "out/accuracy",
    plot: bool = False,
) -> dict[str, Any]: ...
def stability(
    *,
    dir: Optional[PathLike] = None,
    only: str = "",
    jobs: Optional[int] = None,
    out: Optional[PathLike] = None,
    assets: Optional[PathLike] = None,
) -> dict[str, Any]: ...
