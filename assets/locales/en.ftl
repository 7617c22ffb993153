# frictionlab's messages in English: the page's and the lab report's (web/README.md says how to
# add a language).

language-name = English

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
