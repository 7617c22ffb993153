# frictionlab's words in English: the browser page's (web/), the lab report's (the report-*
# messages) and the lab's own (check-*, reading-*, estimate-*, ...: the lab says them, in English
# from this file compiled in), one message an id, in Mozilla's
# Fluent (https://projectfluent.org/fluent/guide/). A language is one such file, TAG.ftl beside
# this one (fr.ftl: French), with every message of this one; the page offers each file it finds
# here. English is every message's fallback. A number in { $name } comes written already, in the
# page's language; one a message chooses by ({ $periods -> [one] ... *[other] ... }) is a count.

language-name = English

## The page's frame

page-title = frictionlab — the friction oscillator in your browser
page-subtitle = the friction oscillator in your browser
class-page-title = frictionlab — the class's table
class-page-subtitle = the class's table
language-label = Language
skip-to-controls = Skip to the controls
lab-place-browser = The lab runs in this browser: nothing is sent anywhere.
lab-place-server = The lab runs on the server at { $host }.
page-problem-unexpected = The lab did not answer as expected: { $message }
# Between the parts of a list on one line: "thin plate T = 0.634 s; μₖ = 0.29".
parts-separator = {"; "}
# A value in seconds, as the readouts write it.
seconds = { $seconds } s

## The rig in 3D

view-title = The rig in 3D
view-canvas-label = The rig in 3D: the plate on its two rollers
view-reset = Reset view
force-normal = normal force
force-friction = friction
force-weight = weight m g (3 cm)
view-hint-mouse = Drag to orbit · scroll to zoom.
view-hint-touch = Drag to orbit · pinch to zoom.
view-keys = Keys on the view: arrows orbit, Shift + arrows pan, + and − zoom, Home resets.
view-near-side = show the near wall

## The run

run-title = Run
run-play = Play
run-pause = Pause
run-play-again = Play again
run-step = Step
    .title = One frame: 1/30 s of simulated time
run-reset = Reset
run-slow-motion = Slow motion
run-status-connecting = connecting
run-status-paused = paused
run-status-playing = playing
run-status-done = done
run-status-no-session = no session
run-time = t = { $t } s
run-failure = The run stopped: { $message }
period = T = { $period } s
period-none = T = — s
period-waiting = T = … s
mu-k = μₖ = { $muK }
mu-k-none = μₖ = —
period-detail-none = no period accepted yet
period-detail-no-spread =
    from { $periods ->
        [one] { $periods } period
       *[other] { $periods } periods
    }: no spread yet
period-detail-spread =
    ± is the standard deviation of { $periods ->
        [one] { $periods } period
       *[other] { $periods } periods
    }; the mean's standard error, σ/√N, { $se } s, is how well T is known
period-detail-done = the run's result: ± is the periods' standard deviation; the mean's standard error, σ/√N, { $se } s, is how well T is known
scene-paper-rig = The paper's rig
scene-paper-rig-77K = The paper's rig at 77 K
scene-paper-rig-77K-warming = The paper's rig at 77 K, warming up
scene-minimal = The minimal rig
scene-roller-ramp = The minimal rig, its rollers slowed and sped up
regime-label = Regime:

## The regimes the lab names (its summary's `regime`); a regime this file lacks shows as the lab
## wrote it.

regime-oscillates = oscillates
regime-clipped = clipped
regime-stick-slip = stick-slip
regime-grows = grows
regime-decays = decays
regime-sticks = sticks
regime-tips = tips
regime-no-restoring-force = no restoring force
regime-lost = lost
regime-numerically-failed = numerically failed
regime-since = { " " }since t = { $t } s
regime-jumps = ; { $jumps ->
        [one] { $jumps } jump
       *[other] { $jumps } jumps
    } off a roller, up to { $height } mm
regime-help-oscillates = Both rollers slip under the plate throughout: the harmonic oscillation whose period gives μk.
regime-help-clipped = Once, the plate moved as fast as a roller's surface and stuck to it: that clipped the amplitude to the rollers' surface speed over ω. The period is unchanged.
regime-help-stick-slip = The plate sticks to a roller for part of each cycle, then slips: its period is no longer the formula's.
regime-help-grows = Friction falls with the slip speed here: the amplitude grows from cycle to cycle.
regime-help-decays = Friction rises with the slip speed here: the amplitude decays from cycle to cycle.
regime-help-sticks = The plate stays stuck to a roller (or the rollers stand still): there is no oscillation to time.
regime-help-tips = A roller's normal force reached zero: the plate tipped or lifted off it.
regime-help-no-restoring-force = Friction pushes the plate away from the middle (l ≤ 2 μk h_c, or rollers turning outward): it drifts off.
regime-help-lost = The plate fell off the rollers or left the rig.
regime-help-numerically-failed = The simulation broke down (a number became infinite, or the energy grew without bound).

## The plots and the periods

plots-title = Plots
plot-position-caption = Plate position x(t), theory dashed (last 5 s)
plot-position-box =
    .aria-label = Plot of the plate's position x against the time t, the last 5 s; its data are in the table below
plot-hall-caption = Hall sensor, its pulses dashed (last 5 s)
plot-hall-box =
    .aria-label = Plot of the Hall sensor's ADC counts against the time t, the last 5 s, the pulses the estimator found marked; its data are in the table below
plot-hall-none = This rig has no Hall sensor.
plot-table-summary = Data as a table
plot-table-position-hidden = : the plate's position
plot-table-hall-hidden = : the Hall sensor's ADC counts
plot-hall-column = Hall (ADC counts)
plot-adc-axis = ADC counts
plot-position-series = x (mm)
plot-theory-series = theory x_th (mm)
plot-rig-hall-series = rig's Hall (ADC)
# What a plot's table holds, for its caption ("No samples of ... yet.").
plot-table-position-what = the plate's position x (mm)
plot-table-hall-what = the Hall sensor's ADC counts
plot-table-empty = No samples of { $what } yet.
# $what: plot-table-position-what or plot-table-hall-what, its first letter made a capital.
plot-table-every = { $what }, t from { $from } to { $to } s: every sample plotted ({ $rows }).
plot-table-some = { $what }, t from { $from } to { $to } s: { $rows } of the { $samples } samples plotted, evenly in time.
periods-caption = Periods as the estimator judges them:
periods-region =
    .aria-label = Periods table
periods-from = from (s)
periods-accepted-column = accepted
periods-status-column = status
periods-yes = ✓ yes
periods-no = ✗ no
periods-accepted = accepted
periods-rejected = rejected
periods-none = none yet
periods-tally = { $accepted } of { $count } accepted

## The side panel: the rig and its theory

panel =
    .aria-label = Set-up and tools
rig-values-title = Rig and theory
rig-values-spacing = Spacing l
rig-values-rollers = Rollers
rig-values-plate = Plate
rig-values-theory = Theory
spacing-value = { $spacing } mm
rollers-value = { $rpm } rpm
rollers-value-driven = { $rpm } rpm (motor drive)
theory-thin = thin plate T = { $period } s
theory-thick = thick plate { $period } s
theory-mu-k = μₖ = { $muK }
theory-paper = paper: T = { $period } s, μₖ = { $muK }

## The stopwatch

stopwatch-title = Stopwatch: time ten periods
stopwatch-start = Start
stopwatch-stop = Stop
stopwatch-clear = Clear
stopwatch-space = or press Space
stopwatch-wall = Wall clock
stopwatch-simulated = Simulated
stopwatch-estimator = Estimator
# $total: the time between the presses; $periods: the periods timed; $period: one of them.
stopwatch-timed = { $total } s, ÷ { $periods } = { $period } s

## The set-up

setup-title = Set-up
setup-scene = Scene
setup-material = Plate material (Table I)
setup-spacing = Roller spacing l
setup-spacing-slider =
    .aria-label = Roller spacing l, slider (mm)
setup-speed = Roller speed
setup-speed-slider =
    .aria-label = Roller speed, slider (rpm)
unit-rpm = rpm
setup-duty = Motor duty (PWM)
setup-duty-slider =
    .aria-label = Motor duty, slider (%)
setup-law = Friction law
setup-law-scene = as the scene
setup-mu-s = μs (static)
setup-from-scene =
    .placeholder = scene
setup-runout = Roller run-out
setup-offset = Starting offset
setup-offset-slider =
    .aria-label = Starting offset, slider (mm)
setup-duration = Run for
setup-duration-hint = Long enough to time ten periods by hand (about 8 s on the paper's rig) and more.
setup-accepts = This set-up accepts { $least } to { $most } { $unit }.
setup-beyond = { $found } { $unit } is beyond what this set-up accepts, { $least } to { $most } { $unit }: the lab runs on as it was.
number-nothing = expected a number, found nothing
number-decimal-point = expected a number with a decimal point, such as 89.5, found "{ $text }"
number-expected = expected a number, such as { $example }, found "{ $text }"

# The plate's materials of the paper's Table I (assets/paper/table1.yaml), by key.
material-lego = LEGO blocks
material-paper = Paper
material-polished-wood = Polished wood
material-construction-wood = Construction wood
material-iron = Iron
material-plexiglas = Plexiglas
material-brass = Brass
material-cardboard = Cardboard
material-rigid-foam = Polyurethane rigid foam
material-flexible-foam = Polyurethane flexible foam

## The class

class-title = The class
student-name-label = Your name (for the class table)
student-name-hint = Shown in the class's table as you type, and sent with every session you start; letters, digits, spaces and . - _ ' , ( ).
student-name-not-sent = Not sent: { $problem }.
student-name-too-long = at most { $most } characters
student-name-characters = only letters, digits, spaces and . - _ ' , ( ), beginning with a letter or digit
class-link = The class's table

## Your measurement

measurement-title = Your measurement
measurement-file = A file you measured
measurement-note = Your rig's Hall log, a phone's phyphox export (CSV or zip), Tracker's data, a position-time table or a short phone video, chosen here or dropped on this panel: the lab reads its period, and μₖ with this set-up's spacing.
measurement-reading = reading { $file }
measurement-busy = the lab is reading other files; { $file } again in a moment
# $instrument: the lab's name of what made the file (and its channel).
measurement-result =
    { $file }: { $instrument }, N = { $periods } { $periods ->
        [one] period
       *[other] periods
    }; μₖ = { $muK } with l = { $spacing } mm
measurement-phone-note = A phone on the plate raises its centre of mass: this μₖ, by the paper's formula, is high by the fraction 4π²h_c/(gT²) (frictionlab estimate --h-c gives the thick formula's)

## The live rig

rig-title = The live rig
rig-summary-looking = looking for the rig's Arduino
rig-summary-connect = connect the rig's Arduino
rig-summary-no-web-serial = Web Serial missing: choose its log file
rig-summary-ports =
    { $ports ->
        [one] { $ports } serial port found
       *[other] { $ports } serial ports found
    }
rig-port-label = Serial port of the rig's Arduino
rig-no-port-found = no serial port found
rig-connect = Connect
rig-close = Close
rig-choose-note = A shared lab: only the lab's own computer chooses the port.
rig-connect-note = Connecting plays this set-up's simulation from t = 0 beside it.
rig-plot-caption = The rig's Hall sensor (last 10 s): periods end at the orange-red lines (grey dashed: rejected)
rig-periods-caption = The rig's periods, newest first:
rig-periods-region =
    .aria-label = The rig's periods
rig-log = The rig's raw log
rig-log-named = The rig's raw log ({ $name })
rig-problem = The rig: { $message }
rig-lines =
    { $lines ->
        [one] { $lines } line
       *[other] { $lines } lines
    }
# The port's state, as the lab names it (closed, waiting, receiving, unplugged, failed, full).
rig-port-state =
    { $state ->
        [closed] closed
        [waiting] waiting
        [receiving] receiving
        [unplugged] unplugged
        [failed] failed
        [full] full
       *[other] { $state }
    }
rig-state-none = no port open
# $lines: rig-lines, written.
rig-state-closed = closed ({ $port } was open, { $lines } received)
rig-state-waiting = waiting for { $port }: nothing received yet
rig-state-receiving = receiving from { $port }, { $lines }
rig-state-unplugged = unplugged: { $port } went away after { $lines }
rig-state-failed = failed: { $port }
rig-state-other = { $state }: { $port }
rig-the-port = the port
rig-geometry-one-pulse = one pulse per period
rig-geometry-pair = a pair of pulses per period
rig-geometry-unknown = pulses not yet recognised
rig-estimate-periods =
    N = { $periods } { $periods ->
        [one] period
       *[other] periods
    }
rig-estimate-se = the mean's standard error, σ/√N, { $se } s
rig-estimate-spacing = l = { $spacing } mm (this set-up's spacing)
rig-estimate-note = ± is the periods' standard deviation, dμₖ in quadrature

## Export

export-title = Export
export-files = The run's files (after it is done):
export-report = Lab report
export-report-hint = After the run: the set-up, the data, T and μk with their uncertainties, against the paper, as a page to hand in or print to PDF.
export-report-writing = Writing the report…
export-report-done = report.html is downloaded: open it, and print it to PDF from the browser to hand it in.
export-png = PNG of the view
export-link = Link to this set-up
export-copy = Copy
export-copy-by-hand = Select the link and copy it by hand.
export-copied = Copied.

## The rig in words, for a screen reader

# Where the plate is: $side is left, right or centre; $mm its distance from the centre.
plate-where =
    { $side ->
        [left] { $mm } mm left of centre
        [right] { $mm } mm right of centre
       *[centre] at the centre
    }
# $where: plate-where, written; $motion: left, right or rest.
plate-now =
    The plate is { $where }, { $motion ->
        [left] moving left
        [right] moving right
       *[rest] at rest
    }.
rollers-one = The plate rests on the { $side ->
        [left] left
       *[right] right
    } roller alone ({ $newtons } N).
rollers-same = Both rollers carry the same weight ({ $newtons } N each).
rollers-more =
    The { $more ->
        [left] left
       *[right] right
    } roller carries more of its weight: { $most } N against { $least } N on the { $more ->
        [left] right
       *[right] left
    }.
period-said-done = The run's period: T = { $period } s.
period-said-none = No period measured yet.
period-said-so-far =
    The period so far: T = { $period } s, from { $periods ->
        [one] { $periods } period
       *[other] { $periods } periods
    }.
# $sense: inward or outward; $material: the lab's name of the plate's material; $start: plate-where.
set-up-said =
    Two rollers { $spacing } mm apart (the spacing l), their tops turning { $sense ->
        [inward] toward each other
       *[outward] away from each other
    } at { $rpm } rpm, under a plate of { $material }, { $length } mm long and { $mass } g; the plate starts { $start }. The thin-plate theory's period: { $period } s.
# $moment: playing, paused or over; $motion: plate-now and what follows it, written.
moment-said =
    { $moment ->
        [paused] Paused at
        [over] The run is over at
       *[playing] Playing, at
    } t = { $t } s. { $motion }

## The class's table (class.html)

class-back = Back to the lab
class-caption = Every open session's set-up and result, like the paper's Table I filled by the class:
class-asking = asking the lab
class-column-name = name
class-column-scene = scene
class-column-material = material
class-column-temperature = temperature (K)
class-column-spacing = spacing l (mm)
class-column-state = state
class-column-period = period T ± dT (s)
class-column-paper = paper's μₖ
class-column-hide = hide the row
class-show-hidden = Show the hidden rows
class-show-hidden-count =
    Show the { $hidden } hidden { $hidden ->
        [one] row
       *[other] rows
    }
class-hint = T ± dT: the mean of the accepted periods ± its standard error, rounded to it ("motion fit": a rig without a Hall sensor, its period fitted to the plate's motion); μₖ ± dμₖ in quadrature with the spacing's dl; the paper's μₖ from its Table I; — where there is none yet. Refreshed every 2 s. A column's heading sorts the rows by it (again: the other way). "Hide" takes a row off this page only (a student who left, a run you have noted), kept so in this browser; class.csv holds every open session.
class-motion-fit = { $period } (motion fit)
class-hide = Hide
class-hide-named = Hide the row of { $name }
class-hide-unnamed = Hide the unnamed session's row
class-no-session = No session is open.
class-all-hidden = Every row is hidden.
class-count =
    { $sessions ->
        [one] { $sessions } session
       *[other] { $sessions } sessions
    }
class-count-hidden =
    { $sessions ->
        [one] { $sessions } session
       *[other] { $sessions } sessions
    }, { $hidden } hidden here
# $state: rig-port-state, written; $lines: rig-lines, written.
class-rig = The live rig: { $port }, { $state }, { $lines } received
class-rig-no-port = no port
class-updated = updated { $time }
# A session's state, as the lab names it (paused, playing, done).
session-state =
    { $state ->
        [paused] paused
        [playing] playing
        [done] done
       *[other] { $state }
    }

## The page's own words about the lab (where the lab's answer says nothing)

lab-no-json = the lab answered { $status } with no JSON
lab-answered = the lab answered { $status }
lab-busy = the lab is busy: too many requests from this computer; try again in a few s
lab-busy-seconds = the lab is busy: too many requests from this computer; try again in { $seconds } s
lab-setup-problems = the set-up has problems
lab-full = the lab is full: try again when a session ends
lab-stopped = the lab stopped
lab-superseded = a newer set-up took this one's place
browser-lab-stopped = the lab in this browser stopped: { $why }
browser-lab-worker-failed = its worker failed
browser-lab-no-class = the class's table is a classroom server's (frictionlab serve): this lab runs in one browser
serial-choose = the browser asks which
serial-missing = This browser cannot open the rig's serial port (Web Serial is in Chrome, Edge and Opera on a computer): save the rig's log (the Arduino's serial monitor, or frictionlab log) and choose the file under “Your measurement”
serial-no-baud = the lab gave no baud rate for the rig's port
serial-none-chosen = no port chosen: press Connect again and choose the rig's Arduino
serial-not-opened = the port could not be opened ({ $why }): close the Arduino IDE's serial monitor or any other page using it, and connect again
serial-chosen-port = the chosen serial port

## The lab's own messages: what it refuses and why, said by the lab (src/scene/scene_checks.cpp,
## src/core/plausible_range.cpp, src/scene/drive_layout.cpp) on the command line and here. The lab
## reads this file's English itself, so each message here is plain text with { $variable }
## placeables only; other languages may use all of Fluent. A number comes in the unit its name
## says ($spacing_mm: millimetres), written with six significant digits at most; $unit is a
## unit's symbol with its space before it (" mm"), or nothing.

check-must-be-positive = must be positive, found { $value }
check-must-be-positive-in = must be positive, found { $value } { $unit }
check-length-must-be-positive = must be positive, found { $value } m ({ $value_mm } mm)
check-must-be-finite = must be finite
check-implausible = expected { $what } from { $least } to { $most }{ $unit } (the paper's rig: { $paper }), found { $value }{ $unit }
check-implausible-value = { $why }; check the value and its unit (a plain number is SI)
check-tilt = must be between -30 and 30 degrees, found { $degrees } deg (an angle without a unit is in radians)
check-solver-iterations = must be between 1 and 10000, found { $iterations }
check-step-resolves = expected a step that resolves the oscillation, shorter than a quarter of its period ({ $quarter } s for the thin plate), found { $step } s; use a step of 1 ms
check-duration-one-step = must be at least one step of world.time_step ({ $step } s), found { $duration } s: a run of no step measures nothing
check-duration-steps = needs { $steps } steps, more than 1e9; use a larger world.time_step or a shorter duration
check-speed-not-negative = must be >= 0, found { $speed } rad/s
check-duty = must lie between 0 % and 100 %, found { $duty_percent } %
check-rollers-overlap = the rollers overlap: l = { $spacing_mm } mm is not more than their radii's sum { $radii_mm } mm
check-no-oscillation = no oscillation exists: l = { $spacing_mm } mm <= 2 mu_k h_c = { $limit_mm } mm (mu_k = { $mu_k }, h_c = { $h_c_mm } mm); widen the rollers, lower the plate's centre of mass or lower mu_k
check-plate-too-short = the plate ({ $length_mm } mm) is shorter than l + 2 x amplitude = { $needed_mm } mm: it would leave a roller; use a longer plate or a smaller offset
check-drive-coupling = the drive's coupling (a { $roller_teeth }-tooth roller gear and two { $idler_teeth }-tooth idlers) spans roller spacings from { $least_mm } to { $most_mm } mm, found { $spacing_mm } mm; choose a spacing in that span, or other gears in drive.coupling
check-sensor-in-magnet-path = the sensor lies inside the volume magnet { $magnet } sweeps as the plate moves; raise it above the magnet's top at { $top_mm } mm
check-magnetometer-in-plate-path = phone { $phone }: the magnetometer at [{ $x_mm }, { $y_mm }, { $z_mm }] mm lies inside the volume the plate sweeps; lay the phone beside the rig (|y| above { $half_width_mm } mm)
check-magnetometer-in-magnet-path = phone { $phone }: the magnetometer lies inside the volume magnet { $magnet } sweeps as the plate moves; lay the phone beside the rig
check-not-negative = must be >= 0, found { $value }
check-not-negative-in = must be >= 0, found { $value } { $unit }
check-angles-finite = must be finite angles
check-ramp-time = point { $point }: its time { $time } s must be >= 0 and after the previous point's
check-ramp-value = point { $point }: its value { $value }{ $unit } must lie from { $least } to { $most }
check-ramp-times-match = roller 1's points must be at roller 0's times
check-ramp-with-drive = the drive sets the rollers' speed; ramp drive.motor.duty_ramp instead
check-two-radii-drive = two radii go with the ideal drive only (the drive's gear train is laid out for one roller size); give one radius or drop the drive
check-skew = must be between -10 and 10 degrees (axes that far from parallel are no bench's misalignment), found { $degrees } degrees
check-rolling-resistance = must be >= 0 and below half the roller's radius ({ $half_radius_mm } mm): a pressure centre that far ahead of the top is no roller's, found { $found_mm } mm
check-runout = must be >= 0 and below half the roller's radius ({ $half_radius_mm } mm), found { $found_mm } mm
check-warming-room = must be warmer than the rollers' start (friction.temperature, { $start_k } K), found { $room_k } K
check-speed-1-not-negative = roller 1's speed must be >= 0, found { $speed } rad/s
check-two-speeds-drive = two speeds [roller 0, roller 1] are the ideal drive's: a drive turns both rollers through its gears at one speed; remove the drive or give one speed
check-two-speeds-ramp = two speeds go with a constant speed, not with rollers.speed_ramp; give one
check-payload-on-plate = must lie on the plate, within half its length ({ $half_length_mm } mm) of its middle, found { $x_mm } mm
check-mu-k-positive = mu_k must be positive, found { $mu_k }
check-mu-s-at-least-mu-k = the static limit mu_s must be at least mu_k = { $mu_k }, found { $mu_s }
check-stribeck-v-s = a stribeck law with mu_s > mu_k needs friction.v_s, the speed over which friction falls from mu_s to mu_k (e.g. 10 mm/s)
check-beta-finite = beta must be finite, found { $beta }
check-mu-negative = the law's mu(s) goes negative ({ $mu_min } at the run's largest slip speed { $slip_speed } m/s); use a smaller |beta| or a larger mu_k
check-magnet-size = magnet { $magnet }: diameter, thickness and density must be positive
check-magnet-remanence = magnet { $magnet }: remanence must be non-zero
check-magnet-on-plate = magnet { $magnet } at x = { $x_mm } mm does not sit on the plate (half length { $half_length_mm } mm)
check-axis-non-zero = must be a non-zero vector
check-adc-bits = must be between 1 and 16, found { $bits }
check-jitter = must be >= 0 and below a quarter of the sample interval
check-clock-error = must lie within +-10 % (a resonator is off by 0.5 % at most), found { $error }
check-sensor-offset = must lie between 0 V and the supply
check-sensor-above = the sensor must sit above the rollers' tops (z > 0)
check-phone-rate = phone { $phone }: rate must lie from 1 Hz to 10 kHz (phyphox records at 50 to 500 Hz), found { $rate } Hz
check-phone-noise = phone { $phone }: noise must be >= 0, found { $noise }
check-phone-turn = phone { $phone }: turn must be finite
check-phone-earth-field = phone { $phone }: the Earth's field must be finite and at most 1 mT (it is 25 to 65 uT), found { $field_ut } uT
check-phone-position = phone { $phone }: position must be finite
check-phone-mass = phone { $phone }: mass must be positive, found { $mass_kg } kg
check-phone-size = phone { $phone }: size (width, length, thickness) must be positive
check-phone-height = phone { $phone }: height must be >= 0, found { $height_mm } mm
check-phone-on-plate = phone { $phone }: x = { $x_mm } mm puts the phone's centre off the plate (half length { $half_length_mm } mm)
# A measurement's file the lab cannot read (src/hall_log/, src/lab/logs/). $tried: the reading
# options tried, as the page names them.
reading-expected = a header naming the time and ADC columns (for example "t_us,adc", "t_s,adc" or "time,value") or lines of samples
reading-empty = the log is empty: expected { $expected }
reading-only-comments = the log has only comment lines: expected { $expected }
reading-no-sample-line = none of the log's { $lines } lines is a header or a sample: expected { $expected }, found lines such as { $example }
reading-tried-one = { $problem }; tried { $tried } on it: it gives no period of a rig; is it the rig's Hall log, captured whole?
reading-tried = { $problem }; tried { $tried } on it: none gives a period of a rig; is it the rig's Hall log, captured whole?
reading-no-samples-timed = no samples after the header: expected lines of { $time } and { $value } values
reading-no-samples = no samples after the header: expected lines of { $value } values
estimate-no-pulse = no pulse in { $samples } samples over { $duration_s } s (lines { $first_line }-{ $last_line }): the ADC values stay within { $low }..{ $high } counts; { $why }
estimate-swing-too-small = a swing of { $swing } counts is below the { $needed } counts a pulse needs: does the magnet pass the sensor?
estimate-not-learned = the signal swings { $swing } counts, but the estimator learns the baseline and polarity from the first two pulses and did not see two (between pulses the signal must rest at its baseline, more than half of the time)
estimate-no-timing-level = the signal swings { $swing } counts but no pulse rose past the timing level
estimate-one-pulse = only one pulse in { $duration_s } s of log (at t = { $at_s } s, after the two the signal was learned from): a period needs at least two
estimate-few-pulses = only { $pulses } pulses (intervals { $intervals } s): the estimator needs five in a row to tell one pulse per period from a pair; record more periods
estimate-no-turning-points = { $pulses } pulses, but no two turning points: the intervals between pulses ({ $intervals } s) fit neither one pulse per period (equal intervals) nor a close pair per period (alternating short and long, the short under 0.6 of the long); { $advice }
estimate-pulses-alternate = they alternate short and long: two pulses per period (the magnet passing the sensor and back, a sensor inside the turning point or near the middle of the travel), too wide a pair to recognise on its own: give { $geometry }
estimate-pulses-irregular = they are irregular (spurious pulses, the plate jumping, a weak or noisy signal): { $plot } shows them
estimate-counts-one = { $pulses } pulses gave { $periods } period, { $accepted } accepted and { $discarded } discarded
estimate-counts = { $pulses } pulses gave { $periods } periods, { $accepted } accepted and { $discarded } discarded
estimate-look = { $plot } shows the pulses and why each period was discarded
estimate-more-discarded-none = { $counts }: more discarded than accepted, so the pulses keep no steady period (a rig's estimator discards a period only at a missing, spurious or bent pulse, and accepts one within { $tolerance_percent } % of the running median, which intervals at random also fall within now and then); no T is computed: is the log the Hall sensor's, of a plate that oscillates? A plate that jumps more often than not needs a steadier rig; { $look }
estimate-more-discarded = { $counts }: more discarded than accepted, so the pulses keep no steady period (a rig's estimator discards a period only at a missing, spurious or bent pulse, and accepts one within { $tolerance_percent } % of the running median, which intervals at random also fall within now and then); no T is computed from the { $accepted } accepted: is the log the Hall sensor's, of a plate that oscillates? A plate that jumps more often than not needs a steadier rig; { $look }
estimate-too-few-accepted = { $counts }: T +- dT needs at least { $least } accepted periods (the paper averaged 10 to 100); record a longer log
estimate-scatter = { $counts }: the accepted periods scatter by dT/T = { $scatter_percent } % (dT = { $spread_s } s about T = { $period_s } s), beyond the { $most_percent } % of any rig (the paper's periods: 0.5 to 8 %): periods spread over the whole of the estimator's +-{ $tolerance_percent } % window are no oscillation's; is the log the Hall sensor's? { $look }
estimate-no-rig = T = { $period_s } s and mu_k = { $mu_k } are no rig's ({ $why }); nothing is computed from them
table-too-many-fields = expected at most { $named } fields as the header names, found { $found }
table-not-a-number = expected a number in the column "{ $column }", found "{ $found }"
table-no-header = expected a header whose first column names a time ("t", "Time (s)"), found none
reading-not-periodic = expected a periodic motion, found none in the { $instrument }'s { $column }: its strongest frequency, { $frequency_hz } Hz (a period of { $period_s } s), stands { $ratio } times above its spectrum's median, where a swinging plate's stands { $least_ratio } times or more; its noise is { $noise } and it swings by { $swing } (in that column's unit). Is it a recording of the rig oscillating, not of a phone lying still or of another experiment?
column-named = "{ $name }"
column-field-magnitude = |B|
column-plate-position = plate's position ({ $unit })
# What made a measurement's file.
instrument-hall-sensor = Hall sensor
instrument-phyphox-magnetometer = phyphox magnetometer
instrument-phyphox-accelerometer = phyphox accelerometer
instrument-phyphox-linear-accelerometer = phyphox accelerometer (without g)
instrument-tracker = Tracker
instrument-position-table = position-time table
instrument-phyphox-location = phyphox location (GPS)
instrument-phyphox-audio = phyphox audio
instrument-phyphox-other = phyphox sensor of another kind
instrument-phyphox-export = phyphox export (zip)
instrument-excel = Excel workbook (.xlsx)
instrument-zip = zip archive
instrument-video = video
# The rig's serial port (src/hall_log/serial_port.cpp, src/serve/board_feed.cpp).
port-not-there = no such serial port (is the board plugged in? ls /dev/ttyACM* /dev/ttyUSB*)
port-not-allowed = this computer's user may not open the serial port (add yourself to the dialout group, then log in again)
port-busy = another program has the serial port open: close the serial monitor
port-failed = cannot open { $port }: { $why }
port-log-full = the log reached its { $megabytes } MB (about { $minutes } minutes at the firmware's 1 kHz): the port is closed and the log kept; connect again to start a new one
port-unplugged = { $port } went away at { $time } (the board unplugged?): the { $lines } lines received are kept, download them below; plug the board in and connect again
# The classroom server's own refusals (src/serve/lab_server.cpp).
server-no-session = no such session (it ended or never began)
server-full = the lab is full: it runs { $sessions } sessions at once, its limit; try again when one ends
server-reading-files = the lab is reading other students' files: send yours again in a few seconds
server-too-many = too many requests from { $address }: at most { $per_second } a second; wait { $wait_s } s
# The quantities core/plausible_range.hpp bounds, as check-implausible's $what.
quantity-spacing = the roller spacing l
quantity-mu-k = mu_k
quantity-h-c = the centre-of-mass height h_c
quantity-period = the period T
quantity-amplitude = the amplitude A
quantity-gravity = gravity g
quantity-roller-speed = the rollers' speed
quantity-roller-radius = the roller radius
# The paper's rig's values of those quantities, as check-implausible's $paper.
paper-spacing = 89 mm
paper-mu-k = 0.2 to 10
paper-h-c = a few mm
paper-period = 0.3 to 1 s
paper-amplitude = 20 mm
paper-gravity = 9.81 m/s^2
paper-roller-speed = 1600 rpm
paper-roller-radius = 10 mm

## The lab report (frictionlab report, the page's "Lab report"): read by the lab itself, so each
## message here is plain text with { $variable } placeables only.

report-title = Lab report: the friction oscillator
report-decimal-sign = .
report-method = Method
report-method-text = A plate lies on two rollers a distance l apart that turn in opposite senses, their tops toward each other. Kinetic friction at each contact is μk times the roller's share of the plate's weight, and the nearer roller carries more: the difference pulls the plate back toward the middle with a force proportional to its offset. The plate oscillates with period T = π √(2 l / (μk g)), so a measured period gives μk = 2π² l / (g T²) ({ $citation }). A Hall sensor senses the magnets on the plate's ends; the rig's estimator times its pulses, keeps each period within 20 % of the running median, and averages them.
report-simulation-title = Simulation: { $name }
report-measurement-title = Measurement: { $name }
report-set-up = Set-up
report-data = Data
report-result = Result
report-periods = The periods
report-comparison = Comparison
report-stopwatch = Timed by hand
report-setup-scene = scene
report-setup-spacing = roller spacing l
report-setup-speed = rollers' speed
report-setup-plate = plate
report-setup-mu-k-set = μk set in the simulation
report-setup-h-c = plate's centre of mass above the contacts, h_c
report-setup-mass = plate's mass
report-setup-duration = simulated time
report-setup-time-step = time step
report-setup-seed = seed (the sensor's noise)
report-setup-instrument = instrument
report-setup-file = file
report-setup-gravity = g
report-setup-samples = samples, their span and rate
report-axis-time = t (s)
report-axis-position = x (mm)
report-axis-hall = Hall sensor (ADC counts)
report-axis-start = start of the period (s)
report-axis-period = T (s)
report-position-caption = The plate's position x(t), the whole run (the simulation's trajectory).
report-hall-caption = The Hall sensor's signal, as the rig's Arduino reads it: a pulse each time a magnet passes over the sensor.
report-measurement-caption = The measurement, as read: the channel the estimator timed.
report-periods-plot = Each period against its start
report-periods-caption = Each period at its start: the scatter of the accepted ones is the periods' standard deviation.
report-accepted = accepted
report-discarded = discarded
report-no-period = The estimator found no period.
report-column-start = start (s)
report-column-end = end (s)
report-column-accepted = accepted
report-yes = yes
report-no-beyond-median = no: beyond 20 % of the running median
report-no-spread = no spread: one period
report-period-why = T is the mean of the { $count } accepted periods; dT is their standard error (their standard deviation, { $sd } s, over the square root of their number).
report-mu-k-why = μk = 2π² l / (g T²), with l = { $spacing } mm and g = { $gravity } m/s². Its uncertainty combines in quadrature the spacing's, dl / l with dl = { $dl } mm, and the period's, 2 σT / T with σT the periods' standard deviation, as the rig's Arduino computes it; added instead of combined, they give ± { $worst }.
report-regime = Regime: { $regime }.
report-regime-oscillates = oscillates
report-regime-clipped = clipped
report-regime-stick-slip = stick-slip
report-regime-grows = grows
report-regime-decays = decays
report-regime-sticks = sticks
report-regime-tips = tips or lifts off a roller
report-regime-no-restoring-force = no restoring force
report-regime-lost = lost (off the rig)
report-regime-numerically-failed = numerically failed
report-source = source
report-theory-row = Theory for the μk set, { $mu }: thin plate, π √(2 l / (μk g)); with the plate's thickness
report-thick-row = { $name }: μk from T through the thick formula, 2π² l / (g T² + 4π² h_c), with the plate's centre of mass h_c above the contacts
report-paper-row = The paper's Table I: { $material }, { $kelvin } K
report-no-paper-row = The paper's Table I has no row for this material at this temperature.
report-column-periods = periods
report-column-wall = wall clock (s)
report-column-simulated = simulated (s)
report-column-by-hand = T by hand (s)
report-stopwatch-why = A press of the stopwatch is late or early by a reaction time, about 0.2 s: over ten periods that is 0.02 s in T.
report-footer = Made with { $version }: the simulation and the estimator of the rig's Arduino code; the method of { $citation }.
