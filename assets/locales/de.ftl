# Die Wörter von frictionlab auf Deutsch: die der Browserseite (web/) und die des Versuchsprotokolls
# (die report-*-Nachrichten, die das Labor selbst liest), eine Nachricht je Kennung, im
# Fluent-Format von Mozilla (https://projectfluent.org/fluent/guide/). Jede Nachricht aus en.ftl
# steht hier, mit denselben Variablen. Eine Zahl in { $name } kommt schon in der Sprache der Seite
# geschrieben; eine, nach der eine Nachricht auswählt ({ $periods -> [one] ... *[other] ... }), ist
# eine Anzahl. Begriffe: Periodendauer T, Gleitreibungszahl μk, Achsabstand der Rollen l,
# Standardabweichung, Standardfehler.

language-name = Deutsch

## Der Rahmen der Seite

page-title = frictionlab — der Reibungsoszillator in Ihrem Browser
page-subtitle = der Reibungsoszillator in Ihrem Browser
class-page-title = frictionlab — die Klassentabelle
class-page-subtitle = die Klassentabelle
language-label = Sprache
skip-to-controls = Zu den Bedienelementen springen
lab-place-browser = Das Labor läuft in diesem Browser: Es wird nichts irgendwohin gesendet.
lab-place-server = Das Labor läuft auf dem Server { $host }.
page-problem-unexpected = Das Labor hat nicht wie erwartet geantwortet: { $message }
# Zwischen den Teilen einer Liste in einer Zeile: „dünne Platte T = 0,634 s; μₖ = 0,29“.
parts-separator = {"; "}
# Ein Wert in Sekunden, wie ihn die Anzeigen schreiben.
seconds = { $seconds } s

## Der Aufbau in 3D

view-title = Der Aufbau in 3D
view-canvas-label = Der Aufbau in 3D: die Platte auf ihren zwei Rollen
view-reset = Ansicht zurücksetzen
force-normal = Normalkraft
force-friction = Reibung
force-weight = Gewichtskraft m g (3 cm)
view-hint-mouse = Ziehen zum Drehen · Mausrad zum Zoomen.
view-hint-touch = Ziehen zum Drehen · zwei Finger zum Zoomen.
view-keys = Tasten in der Ansicht: Pfeile drehen, Umschalt + Pfeile verschieben, + und − zoomen, Pos1 setzt zurück.
view-near-side = vordere Wand zeigen

## Die Simulation

run-title = Simulation
run-play = Abspielen
run-pause = Pause
run-play-again = Erneut abspielen
run-step = Schritt
    .title = Ein Bild: 1/30 s simulierte Zeit
run-reset = Zurücksetzen
run-slow-motion = Zeitlupe
run-status-connecting = verbindet
run-status-paused = pausiert
run-status-playing = läuft
run-status-done = fertig
run-status-no-session = keine Sitzung
run-time = t = { $t } s
run-failure = Die Simulation brach ab: { $message }
period = T = { $period } s
period-none = T = — s
period-waiting = T = … s
mu-k = μₖ = { $muK }
mu-k-none = μₖ = —
period-detail-none = noch keine Periode akzeptiert
period-detail-no-spread =
    aus { $periods ->
        [one] { $periods } Periode
       *[other] { $periods } Perioden
    }: noch keine Streuung
period-detail-spread =
    ± ist die Standardabweichung von { $periods ->
        [one] { $periods } Periode
       *[other] { $periods } Perioden
    }; der Standardfehler des Mittelwerts, σ/√N, { $se } s, gibt an, wie genau T bekannt ist
period-detail-done = Ergebnis der Simulation: ± ist die Standardabweichung der Perioden; der Standardfehler des Mittelwerts, σ/√N, { $se } s, gibt an, wie genau T bekannt ist
scene-paper-rig = Der Aufbau aus dem Artikel
scene-paper-rig-77K = Der Aufbau aus dem Artikel bei 77 K
scene-paper-rig-77K-warming = Der Aufbau aus dem Artikel bei 77 K, beim Aufwärmen
scene-minimal = Der minimale Aufbau
scene-roller-ramp = Der minimale Aufbau, seine Rollen gebremst und beschleunigt
regime-label = Bewegungsform:

## Die Bewegungsformen, die das Labor nennt (das `regime` seiner Zusammenfassung); eine, die in
## dieser Datei fehlt, erscheint so, wie das Labor sie schrieb.

regime-oscillates = schwingt
regime-clipped = begrenzt
regime-stick-slip = Haftgleiten
regime-grows = wächst
regime-decays = klingt ab
regime-sticks = haftet
regime-tips = kippt
regime-no-restoring-force = keine Rückstellkraft
regime-lost = Platte verloren
regime-numerically-failed = numerisch gescheitert
regime-since = { " " }seit t = { $t } s
regime-jumps = ; { $jumps ->
        [one] { $jumps } Sprung
       *[other] { $jumps } Sprünge
    } von einer Rolle, bis zu { $height } mm
regime-help-oscillates = Beide Rollen gleiten ständig unter der Platte: die harmonische Schwingung, deren Periodendauer μk liefert.
regime-help-clipped = Einmal war die Platte so schnell wie die Oberfläche einer Rolle und haftete an ihr: Das begrenzte die Amplitude auf die Umfangsgeschwindigkeit der Rollen geteilt durch ω. Die Periodendauer bleibt gleich.
regime-help-stick-slip = Die Platte haftet in jedem Zyklus eine Zeit lang an einer Rolle und gleitet dann: Ihre Periodendauer ist nicht mehr die der Formel.
regime-help-grows = Hier nimmt die Reibung mit der Gleitgeschwindigkeit ab: Die Amplitude wächst von Zyklus zu Zyklus.
regime-help-decays = Hier nimmt die Reibung mit der Gleitgeschwindigkeit zu: Die Amplitude klingt von Zyklus zu Zyklus ab.
regime-help-sticks = Die Platte haftet an einer Rolle (oder die Rollen stehen still): Es gibt keine Schwingung zu stoppen.
regime-help-tips = Die Normalkraft einer Rolle ist auf null gefallen: Die Platte ist gekippt oder hat von ihr abgehoben.
regime-help-no-restoring-force = Die Reibung treibt die Platte von der Mitte weg (l ≤ 2 μk h_c, oder nach außen drehende Rollen): Sie driftet ab.
regime-help-lost = Die Platte ist von den Rollen gefallen oder hat den Aufbau verlassen.
regime-help-numerically-failed = Die Simulation ist zusammengebrochen (eine Zahl wurde unendlich, oder die Energie wuchs unbegrenzt).

## Die Diagramme und die Perioden

plots-title = Diagramme
plot-position-caption = Position x(t) der Platte, Theorie gestrichelt (letzte 5 s)
plot-position-box =
    .aria-label = Diagramm der Position x der Platte über der Zeit t, die letzten 5 s; die Daten stehen in der Tabelle darunter
plot-hall-caption = Hall-Sensor, seine Impulse gestrichelt (letzte 5 s)
plot-hall-box =
    .aria-label = Diagramm der ADC-Werte des Hall-Sensors über der Zeit t, die letzten 5 s, mit den vom Schätzer gefundenen Impulsen markiert; die Daten stehen in der Tabelle darunter
plot-hall-none = Dieser Aufbau hat keinen Hall-Sensor.
plot-table-summary = Daten als Tabelle
plot-table-position-hidden = : die Position der Platte
plot-table-hall-hidden = : die ADC-Werte des Hall-Sensors
plot-hall-column = Hall (ADC-Werte)
plot-adc-axis = ADC-Werte
plot-position-series = x (mm)
plot-theory-series = Theorie x_th (mm)
plot-rig-hall-series = Hall des Aufbaus (ADC)
# Was die Tabelle eines Diagramms enthält, für ihre Beschriftung („Noch keine Messwerte für ...“).
plot-table-position-what = die Position x der Platte (mm)
plot-table-hall-what = die ADC-Werte des Hall-Sensors
plot-table-empty = Noch keine Messwerte für { $what }.
# $what: plot-table-position-what oder plot-table-hall-what, der erste Buchstabe großgeschrieben.
plot-table-every = { $what }, t von { $from } bis { $to } s: alle Messwerte dargestellt ({ $rows }).
plot-table-some = { $what }, t von { $from } bis { $to } s: { $rows } der { $samples } Messwerte dargestellt, zeitlich gleichmäßig verteilt.
periods-caption = Perioden, wie der Schätzer sie bewertet:
periods-region =
    .aria-label = Tabelle der Perioden
periods-from = Beginn (s)
periods-accepted-column = akzeptiert
periods-status-column = Status
periods-yes = ✓ ja
periods-no = ✗ nein
periods-accepted = akzeptiert
periods-rejected = verworfen
periods-none = noch keine
periods-tally = { $accepted } von { $count } akzeptiert

## Die Seitenleiste: der Aufbau und seine Theorie

panel =
    .aria-label = Einstellungen und Werkzeuge
rig-values-title = Aufbau und Theorie
rig-values-spacing = Achsabstand l
rig-values-rollers = Rollen
rig-values-plate = Platte
rig-values-theory = Theorie
spacing-value = { $spacing } mm
rollers-value = { $rpm } U/min
rollers-value-driven = { $rpm } U/min (Motorantrieb)
theory-thin = dünne Platte T = { $period } s
theory-thick = dicke Platte { $period } s
theory-mu-k = μₖ = { $muK }
theory-paper = Artikel: T = { $period } s, μₖ = { $muK }

## Die Stoppuhr

stopwatch-title = Stoppuhr: zehn Perioden stoppen
stopwatch-start = Start
stopwatch-stop = Stopp
stopwatch-clear = Löschen
stopwatch-space = oder Leertaste drücken
stopwatch-wall = Echtzeit
stopwatch-simulated = Simuliert
stopwatch-estimator = Schätzer
# $total: die Zeit zwischen den Tastendrücken; $periods: die gestoppten Perioden; $period: eine davon.
stopwatch-timed = { $total } s, ÷ { $periods } = { $period } s

## Die Einstellungen

setup-title = Einstellungen
setup-scene = Szene
setup-material = Material der Platte (Tabelle I)
setup-spacing = Achsabstand der Rollen l
setup-spacing-slider =
    .aria-label = Achsabstand der Rollen l, Schieberegler (mm)
setup-speed = Drehzahl der Rollen
setup-speed-slider =
    .aria-label = Drehzahl der Rollen, Schieberegler (U/min)
unit-rpm = U/min
setup-duty = Tastverhältnis des Motors (PWM)
setup-duty-slider =
    .aria-label = Tastverhältnis des Motors, Schieberegler (%)
setup-law = Reibungsgesetz
setup-law-scene = wie in der Szene
setup-mu-s = μs (Haftreibung)
setup-from-scene =
    .placeholder = Szene
setup-runout = Rundlauffehler der Rollen
setup-offset = Anfangsauslenkung
setup-offset-slider =
    .aria-label = Anfangsauslenkung, Schieberegler (mm)
setup-duration = Laufzeit
setup-duration-hint = Lang genug, um zehn Perioden von Hand zu stoppen (etwa 8 s beim Aufbau aus dem Artikel), und mehr.
setup-accepts = Diese Einstellung erlaubt { $least } bis { $most } { $unit }.
setup-beyond = { $found } { $unit } liegt außerhalb dessen, was diese Einstellung erlaubt, { $least } bis { $most } { $unit }: Das Labor läuft unverändert weiter.
number-nothing = eine Zahl erwartet, nichts gefunden
number-decimal-point = eine Zahl mit Dezimalpunkt erwartet, etwa 89.5, gefunden: „{ $text }“
number-expected = eine Zahl erwartet, etwa { $example }, gefunden: „{ $text }“

# Die Plattenmaterialien aus Tabelle I des Artikels.
material-lego = LEGO-Steine
material-paper = Papier
material-polished-wood = Poliertes Holz
material-construction-wood = Bauholz
material-iron = Eisen
material-plexiglas = Plexiglas
material-brass = Messing
material-cardboard = Pappe
material-rigid-foam = PU-Hartschaum
material-flexible-foam = PU-Weichschaum

## Die Klasse

class-title = Die Klasse
student-name-label = Ihr Name (für die Klassentabelle)
student-name-hint = Erscheint schon beim Tippen in der Klassentabelle und wird mit jeder Sitzung gesendet, die Sie starten; Buchstaben, Ziffern, Leerzeichen und . - _ ' , ( ).
student-name-not-sent = Nicht gesendet: { $problem }.
student-name-too-long = höchstens { $most } Zeichen
student-name-characters = nur Buchstaben, Ziffern, Leerzeichen und . - _ ' , ( ), am Anfang ein Buchstabe oder eine Ziffer
class-link = Die Klassentabelle

## Ihre Messung

measurement-title = Ihre Messung
measurement-file = Eine eigene Messdatei
measurement-note = Das Hall-Sensor-Log Ihres Aufbaus, ein phyphox-Export vom Handy (CSV oder zip), Tracker-Daten, eine Weg-Zeit-Tabelle oder ein kurzes Handyvideo, hier gewählt oder auf dieses Feld gezogen: Das Labor liest daraus die Periodendauer und μₖ mit dem Achsabstand dieser Einstellung.
measurement-reading = { $file } wird gelesen
measurement-busy = das Labor liest andere Dateien; { $file } gleich danach
# $instrument: der Name, den das Labor dem gibt, was die Datei erzeugt hat (und sein Kanal).
measurement-result =
    { $file }: { $instrument }, N = { $periods } { $periods ->
        [one] Periode
       *[other] Perioden
    }; μₖ = { $muK } mit l = { $spacing } mm
measurement-phone-note = Ein Handy auf der Platte hebt ihren Schwerpunkt an: Dieses μₖ nach der Formel des Artikels ist um den Anteil 4π²h_c/(gT²) zu groß (frictionlab estimate --h-c liefert den Wert der Formel für dicke Platten)

## Der reale Aufbau

rig-title = Der reale Aufbau
rig-summary-looking = Arduino des Aufbaus wird gesucht
rig-summary-connect = Arduino des Aufbaus verbinden
rig-summary-no-web-serial = kein Web Serial: Log-Datei wählen
rig-summary-ports =
    { $ports ->
        [one] { $ports } serieller Port gefunden
       *[other] { $ports } serielle Ports gefunden
    }
rig-port-label = Serieller Port des Arduino am Aufbau
rig-no-port-found = kein serieller Port gefunden
rig-connect = Verbinden
rig-close = Schließen
rig-choose-note = Gemeinsames Labor: Nur der Laborrechner wählt den Port.
rig-connect-note = Beim Verbinden läuft daneben die Simulation dieser Einstellung ab t = 0.
rig-plot-caption = Der Hall-Sensor des Aufbaus (letzte 10 s): Perioden enden an den orangeroten Linien (grau gestrichelt: verworfen)
rig-periods-caption = Die Perioden des Aufbaus, neueste zuerst:
rig-periods-region =
    .aria-label = Die Perioden des Aufbaus
rig-log = Das Rohlog des Aufbaus
rig-log-named = Das Rohlog des Aufbaus ({ $name })
rig-problem = Der Aufbau: { $message }
rig-lines =
    { $lines ->
        [one] { $lines } Zeile
       *[other] { $lines } Zeilen
    }
# Der Zustand des Ports, wie das Labor ihn nennt (closed, waiting, receiving, unplugged, failed, full).
rig-port-state =
    { $state ->
        [closed] geschlossen
        [waiting] wartet
        [receiving] empfängt
        [unplugged] getrennt
        [failed] fehlgeschlagen
        [full] voll
       *[other] { $state }
    }
rig-state-none = kein Port geöffnet
# $lines: rig-lines, ausgeschrieben.
rig-state-closed = geschlossen ({ $port } war offen, { $lines } empfangen)
rig-state-waiting = wartet auf { $port }: noch nichts empfangen
rig-state-receiving = Empfang von { $port }, { $lines }
rig-state-unplugged = getrennt: { $port } verschwand nach { $lines }
rig-state-failed = fehlgeschlagen: { $port }
rig-state-other = { $state }: { $port }
rig-the-port = der Port
rig-geometry-one-pulse = ein Impuls pro Periode
rig-geometry-pair = ein Impulspaar pro Periode
rig-geometry-unknown = Impulse noch nicht erkannt
rig-estimate-periods =
    N = { $periods } { $periods ->
        [one] Periode
       *[other] Perioden
    }
rig-estimate-se = der Standardfehler des Mittelwerts, σ/√N, { $se } s
rig-estimate-spacing = l = { $spacing } mm (Achsabstand dieser Einstellung)
rig-estimate-note = ± ist die Standardabweichung der Perioden, dμₖ quadratisch addiert

## Export

export-title = Export
export-files = Die Dateien der Simulation (nach ihrem Ende):
export-report = Versuchsprotokoll
export-report-hint = Nach der Simulation: Einstellungen, Daten, T und μk mit ihren Unsicherheiten, verglichen mit dem Artikel, als Seite zum Abgeben oder zum Drucken als PDF.
export-report-writing = Protokoll wird erstellt…
export-report-done = report.html ist heruntergeladen: Öffnen Sie es und drucken Sie es im Browser als PDF, um es abzugeben.
export-png = PNG der Ansicht
export-link = Link zu dieser Einstellung
export-copy = Kopieren
export-copy-by-hand = Link markieren und von Hand kopieren.
export-copied = Kopiert.

## Der Aufbau in Worten, für einen Screenreader

# Wo die Platte ist: $side ist left, right oder centre; $mm ihr Abstand von der Mitte.
plate-where =
    { $side ->
        [left] { $mm } mm links der Mitte
        [right] { $mm } mm rechts der Mitte
       *[centre] in der Mitte
    }
# $where: plate-where, ausgeschrieben; $motion: left, right oder rest.
plate-now =
    Die Platte ist { $where } und { $motion ->
        [left] bewegt sich nach links
        [right] bewegt sich nach rechts
       *[rest] ruht
    }.
rollers-one = Die Platte liegt nur auf der { $side ->
        [left] linken
       *[right] rechten
    } Rolle ({ $newtons } N).
rollers-same = Beide Rollen tragen gleich viel (je { $newtons } N).
rollers-more =
    Die { $more ->
        [left] linke
       *[right] rechte
    } Rolle trägt mehr von der Gewichtskraft der Platte: { $most } N gegenüber { $least } N auf der { $more ->
        [left] rechten
       *[right] linken
    }.
period-said-done = Die Periodendauer der Simulation: T = { $period } s.
period-said-none = Noch keine Periode gemessen.
period-said-so-far =
    Die Periodendauer bisher: T = { $period } s, aus { $periods ->
        [one] { $periods } Periode
       *[other] { $periods } Perioden
    }.
# $sense: inward oder outward; $material: der Name, den das Labor dem Material der Platte gibt; $start: plate-where.
set-up-said =
    Zwei Rollen im Abstand von { $spacing } mm (Achsabstand l), ihre Oberseiten drehen sich mit { $rpm } U/min { $sense ->
        [inward] aufeinander zu
       *[outward] voneinander weg
    }, darauf eine Platte aus { $material }, { $length } mm lang und { $mass } g schwer; die Platte startet { $start }. Die Periodendauer nach der Theorie der dünnen Platte: { $period } s.
# $moment: playing, paused oder over; $motion: plate-now und was darauf folgt, ausgeschrieben.
moment-said =
    { $moment ->
        [paused] Pausiert bei
        [over] Die Simulation ist zu Ende bei
       *[playing] Läuft, bei
    } t = { $t } s. { $motion }

## Die Klassentabelle (class.html)

class-back = Zurück zum Labor
class-caption = Einstellung und Ergebnis jeder offenen Sitzung, wie Tabelle I des Artikels, von der Klasse ausgefüllt:
class-asking = Labor wird abgefragt
class-column-name = Name
class-column-scene = Szene
class-column-material = Material
class-column-temperature = Temperatur (K)
class-column-spacing = Achsabstand l (mm)
class-column-state = Zustand
class-column-period = Periodendauer T ± dT (s)
class-column-paper = μₖ des Artikels
class-column-hide = Zeile ausblenden
class-show-hidden = Ausgeblendete Zeilen anzeigen
class-show-hidden-count =
    { $hidden ->
        [one] Die ausgeblendete Zeile anzeigen
       *[other] Die { $hidden } ausgeblendeten Zeilen anzeigen
    }
class-hint = T ± dT: der Mittelwert der akzeptierten Perioden ± sein Standardfehler, auf diesen gerundet („Bewegungsfit“: ein Aufbau ohne Hall-Sensor, dessen Periodendauer an die Bewegung der Platte angepasst ist); μₖ ± dμₖ quadratisch addiert mit dem dl des Achsabstands; μₖ des Artikels aus seiner Tabelle I; — wo es noch keinen Wert gibt. Alle 2 s aktualisiert. Eine Spaltenüberschrift sortiert die Zeilen danach (nochmals: umgekehrt). „Ausblenden“ entfernt eine Zeile nur von dieser Seite (jemand ist gegangen, ein Lauf ist schon notiert), dauerhaft in diesem Browser; class.csv enthält alle offenen Sitzungen.
class-motion-fit = { $period } (Bewegungsfit)
class-hide = Ausblenden
class-hide-named = Zeile von { $name } ausblenden
class-hide-unnamed = Zeile der unbenannten Sitzung ausblenden
class-no-session = Es ist keine Sitzung offen.
class-all-hidden = Alle Zeilen sind ausgeblendet.
class-count =
    { $sessions ->
        [one] { $sessions } Sitzung
       *[other] { $sessions } Sitzungen
    }
class-count-hidden =
    { $sessions ->
        [one] { $sessions } Sitzung
       *[other] { $sessions } Sitzungen
    }, davon { $hidden } hier ausgeblendet
# $state: rig-port-state, ausgeschrieben; $lines: rig-lines, ausgeschrieben.
class-rig = Der reale Aufbau: { $port }, { $state }, { $lines } empfangen
class-rig-no-port = kein Port
class-updated = aktualisiert um { $time }
# Der Zustand einer Sitzung, wie das Labor ihn nennt (paused, playing, done).
session-state =
    { $state ->
        [paused] pausiert
        [playing] läuft
        [done] fertig
       *[other] { $state }
    }

## Die eigenen Worte der Seite über das Labor (wo die Antwort des Labors nichts sagt)

lab-no-json = das Labor antwortete { $status } ohne JSON
lab-answered = das Labor antwortete { $status }
lab-busy = das Labor ist ausgelastet: zu viele Anfragen von diesem Computer; in ein paar Sekunden erneut versuchen
lab-busy-seconds = das Labor ist ausgelastet: zu viele Anfragen von diesem Computer; in { $seconds } s erneut versuchen
lab-setup-problems = die Einstellung hat Fehler
lab-full = das Labor ist voll: erneut versuchen, wenn eine Sitzung endet
lab-stopped = das Labor wurde beendet
lab-superseded = eine neuere Einstellung hat diese ersetzt
browser-lab-stopped = das Labor in diesem Browser wurde beendet: { $why }
browser-lab-worker-failed = sein Worker ist ausgefallen
browser-lab-no-class = die Klassentabelle gehört zu einem Klassenserver (frictionlab serve): Dieses Labor läuft in einem einzigen Browser
serial-choose = der Browser fragt, welcher
serial-missing = Dieser Browser kann den seriellen Port des Aufbaus nicht öffnen (Web Serial gibt es in Chrome, Edge und Opera auf dem Computer): Speichern Sie das Log des Aufbaus (über den seriellen Monitor des Arduino oder frictionlab log) und wählen Sie die Datei unter „Ihre Messung“
serial-no-baud = das Labor hat keine Baudrate für den Port des Aufbaus angegeben
serial-none-chosen = kein Port gewählt: Erneut auf Verbinden drücken und den Arduino des Aufbaus wählen
serial-not-opened = der Port ließ sich nicht öffnen ({ $why }): Schließen Sie den seriellen Monitor der Arduino-IDE oder jede andere Seite, die ihn nutzt, und verbinden Sie erneut
serial-chosen-port = der gewählte serielle Port

## Das Versuchsprotokoll (frictionlab report, „Versuchsprotokoll“ auf der Seite): vom Labor selbst
## gelesen, daher ist jede Nachricht hier einfacher Text mit nur { $variable }-Platzhaltern.

## Die eigenen Meldungen des Labors: was es ablehnt und warum.

check-must-be-positive = muss positiv sein, gefunden: { $value }
check-must-be-positive-in = muss positiv sein, gefunden: { $value } { $unit }
check-length-must-be-positive = muss positiv sein, gefunden: { $value } m ({ $value_mm } mm)
check-must-be-finite = muss endlich sein
check-implausible = erwartet: { $what } von { $least } bis { $most }{ $unit } (der Aufbau des Artikels: { $paper }), gefunden: { $value }{ $unit }
check-implausible-value = { $why }; prüfe den Wert und seine Einheit (eine Zahl ohne Einheit ist in SI)
check-tilt = muss zwischen -30 und 30 Grad liegen, gefunden: { $degrees }° (ein Winkel ohne Einheit ist im Bogenmaß)
check-solver-iterations = muss zwischen 1 und 10000 liegen, gefunden: { $iterations }
check-step-resolves = erwartet: ein Zeitschritt, der die Schwingung auflöst, kürzer als ein Viertel ihrer Periode ({ $quarter } s für die dünne Platte), gefunden: { $step } s; nimm einen Schritt von 1 ms
check-duration-one-step = muss mindestens einen Schritt von world.time_step ({ $step } s) dauern, gefunden: { $duration } s: ein Lauf ohne Schritt misst nichts
check-duration-steps = braucht { $steps } Schritte, mehr als 10⁹; nimm einen größeren world.time_step oder eine kürzere Dauer
check-speed-not-negative = muss größer oder gleich 0 sein, gefunden: { $speed } rad/s
check-duty = muss zwischen 0 % und 100 % liegen, gefunden: { $duty_percent } %
check-rollers-overlap = die Rollen überlappen sich: l = { $spacing_mm } mm ist nicht größer als die Summe ihrer Radien, { $radii_mm } mm
check-no-oscillation = es gibt keine Schwingung: l = { $spacing_mm } mm ≤ 2 μk h_c = { $limit_mm } mm (μk = { $mu_k }, h_c = { $h_c_mm } mm); stelle die Rollen weiter auseinander, senke den Schwerpunkt der Platte oder verringere μk
check-plate-too-short = die Platte ({ $length_mm } mm) ist kürzer als l + 2 × Amplitude = { $needed_mm } mm: sie würde eine Rolle verlassen; nimm eine längere Platte oder eine kleinere Anfangsauslenkung
check-drive-coupling = das Getriebe des Antriebs (ein Zahnrad mit { $roller_teeth } Zähnen an jeder Rolle und zwei Zwischenräder mit { $idler_teeth } Zähnen) erlaubt Achsabstände von { $least_mm } bis { $most_mm } mm, gefunden: { $spacing_mm } mm; wähle einen Abstand in diesem Bereich oder andere Zahnräder in drive.coupling
check-sensor-in-magnet-path = der Sensor liegt in dem Volumen, das Magnet { $magnet } überstreicht, wenn sich die Platte bewegt; setze ihn über die Oberseite des Magneten, auf { $top_mm } mm
check-magnetometer-in-plate-path = Handy { $phone }: das Magnetometer bei [{ $x_mm }, { $y_mm }, { $z_mm }] mm liegt in dem Volumen, das die Platte überstreicht; lege das Handy neben den Aufbau (|y| über { $half_width_mm } mm)
check-magnetometer-in-magnet-path = Handy { $phone }: das Magnetometer liegt in dem Volumen, das Magnet { $magnet } überstreicht, wenn sich die Platte bewegt; lege das Handy neben den Aufbau
check-not-negative = muss größer oder gleich 0 sein, gefunden: { $value }
check-not-negative-in = muss größer oder gleich 0 sein, gefunden: { $value } { $unit }
check-angles-finite = müssen endliche Winkel sein
check-ramp-time = Punkt { $point }: sein Zeitpunkt { $time } s muss ≥ 0 sein und nach dem des vorigen Punkts liegen
check-ramp-value = Punkt { $point }: sein Wert { $value }{ $unit } muss zwischen { $least } und { $most } liegen
check-ramp-times-match = die Punkte von Rolle 1 müssen zu den Zeitpunkten derer von Rolle 0 liegen
check-ramp-with-drive = der Antrieb legt die Drehzahl der Rollen fest; verändere stattdessen drive.motor.duty_ramp
check-two-radii-drive = zwei Radien gehören nur zum idealen Antrieb (das Getriebe des Antriebs ist für eine Rollengröße ausgelegt); gib einen Radius an oder entferne den Antrieb
check-skew = muss zwischen -10 und 10 Grad liegen (so weit von parallel entfernte Achsen sind keine Fehlausrichtung eines Versuchsaufbaus), gefunden: { $degrees } Grad
check-rolling-resistance = muss ≥ 0 und kleiner als der halbe Rollenradius ({ $half_radius_mm } mm) sein: ein so weit vor dem Scheitel liegender Druckmittelpunkt gehört zu keiner Rolle, gefunden: { $found_mm } mm
check-runout = muss ≥ 0 und kleiner als der halbe Rollenradius ({ $half_radius_mm } mm) sein, gefunden: { $found_mm } mm
check-warming-room = muss wärmer sein als die Rollen zu Beginn (friction.temperature, { $start_k } K), gefunden: { $room_k } K
check-speed-1-not-negative = die Drehzahl von Rolle 1 muss größer oder gleich 0 sein, gefunden: { $speed } rad/s
check-two-speeds-drive = zwei Drehzahlen [Rolle 0, Rolle 1] gehören zum idealen Antrieb: ein Antrieb dreht beide Rollen über sein Getriebe mit einer Drehzahl; entferne den Antrieb oder gib eine Drehzahl an
check-two-speeds-ramp = zwei Drehzahlen gehören zu einer festen Drehzahl, nicht zu rollers.speed_ramp; gib eine an
check-payload-on-plate = muss auf der Platte liegen, höchstens eine halbe Länge ({ $half_length_mm } mm) von ihrer Mitte entfernt, gefunden: { $x_mm } mm
check-mu-k-positive = μk muss positiv sein, gefunden: { $mu_k }
check-mu-s-at-least-mu-k = die Haftgrenze μs muss mindestens μk = { $mu_k } sein, gefunden: { $mu_s }
check-stribeck-v-s = ein Stribeck-Gesetz mit μs > μk braucht friction.v_s, die Geschwindigkeit, über die die Reibung von μs auf μk fällt (zum Beispiel 10 mm/s)
check-beta-finite = β muss endlich sein, gefunden: { $beta }
check-mu-negative = das μ(s) des Gesetzes wird negativ ({ $mu_min } bei der größten Gleitgeschwindigkeit des Laufs, { $slip_speed } m/s); nimm ein kleineres |β| oder ein größeres μk
check-magnet-size = Magnet { $magnet }: Durchmesser, Dicke und Dichte müssen positiv sein
check-magnet-remanence = Magnet { $magnet }: die Remanenz darf nicht null sein
check-magnet-on-plate = Magnet { $magnet } bei x = { $x_mm } mm liegt nicht auf der Platte (halbe Länge { $half_length_mm } mm)
check-axis-non-zero = muss ein Vektor ungleich null sein
check-adc-bits = muss zwischen 1 und 16 liegen, gefunden: { $bits }
check-jitter = muss ≥ 0 und kleiner als ein Viertel des Abtastintervalls sein
check-clock-error = muss innerhalb von ±10 % liegen (ein Resonator weicht höchstens um 0,5 % ab), gefunden: { $error }
check-sensor-offset = muss zwischen 0 V und der Versorgungsspannung liegen
check-sensor-above = der Sensor muss über dem Scheitel der Rollen sitzen (z > 0)
check-phone-rate = Handy { $phone }: die Rate muss zwischen 1 Hz und 10 kHz liegen (phyphox zeichnet mit 50 bis 500 Hz auf), gefunden: { $rate } Hz
check-phone-noise = Handy { $phone }: das Rauschen muss größer oder gleich 0 sein, gefunden: { $noise }
check-phone-turn = Handy { $phone }: die Drehung muss endlich sein
check-phone-earth-field = Handy { $phone }: das Erdfeld muss endlich und höchstens 1 mT sein (es beträgt 25 bis 65 µT), gefunden: { $field_ut } µT
check-phone-position = Handy { $phone }: die Position muss endlich sein
check-phone-mass = Handy { $phone }: die Masse muss positiv sein, gefunden: { $mass_kg } kg
check-phone-size = Handy { $phone }: die Größe (Breite, Länge, Dicke) muss positiv sein
check-phone-height = Handy { $phone }: die Höhe muss größer oder gleich 0 sein, gefunden: { $height_mm } mm
check-phone-on-plate = Handy { $phone }: x = { $x_mm } mm legt die Mitte des Handys neben die Platte (halbe Länge { $half_length_mm } mm)
reading-expected = eine Kopfzeile, die die Spalten für Zeit und ADC benennt (zum Beispiel „t_us,adc“, „t_s,adc“ oder „time,value“), oder Zeilen mit Messwerten
reading-empty = die Aufzeichnung ist leer: erwartet: { $expected }
reading-only-comments = die Aufzeichnung enthält nur Kommentarzeilen: erwartet: { $expected }
reading-no-sample-line = keine der { $lines } Zeilen der Aufzeichnung ist eine Kopfzeile oder ein Messwert: erwartet: { $expected }, gefunden: Zeilen wie { $example }
reading-tried-one = { $problem }; { $tried } versucht: das ergibt keine Periode eines Aufbaus; ist es die Aufzeichnung des Hall-Sensors des Aufbaus, vollständig erfasst?
reading-tried = { $problem }; { $tried } versucht: keines ergibt eine Periode eines Aufbaus; ist es die Aufzeichnung des Hall-Sensors des Aufbaus, vollständig erfasst?
reading-no-samples-timed = keine Messwerte nach der Kopfzeile: erwartet: Zeilen mit Werten für { $time } und { $value }
reading-no-samples = keine Messwerte nach der Kopfzeile: erwartet: Zeilen mit Werten für { $value }
estimate-no-pulse = kein Puls in { $samples } Messwerten über { $duration_s } s (Zeilen { $first_line } bis { $last_line }): die ADC-Werte bleiben zwischen { $low } und { $high } Stufen; { $why }
estimate-swing-too-small = ein Hub von { $swing } Stufen liegt unter den { $needed } Stufen, die ein Puls braucht: läuft der Magnet am Sensor vorbei?
estimate-not-learned = das Signal schwankt um { $swing } Stufen, aber der Schätzer lernt Grundlinie und Polarität aus den ersten beiden Pulsen und hat keine zwei gesehen (zwischen den Pulsen muss das Signal mehr als die Hälfte der Zeit auf seiner Grundlinie ruhen)
estimate-no-timing-level = das Signal schwankt um { $swing } Stufen, aber kein Puls stieg über die Zeitmessschwelle
estimate-one-pulse = nur ein Puls in { $duration_s } s Aufzeichnung (bei t = { $at_s } s, nach den beiden, aus denen das Signal gelernt wurde): eine Periode braucht mindestens zwei
estimate-few-pulses = nur { $pulses } Pulse (Abstände { $intervals } s): der Schätzer braucht fünf in Folge, um einen Puls pro Periode von einem Paar zu unterscheiden; zeichne mehr Perioden auf
estimate-no-turning-points = { $pulses } Pulse, aber keine zwei Umkehrpunkte: die Abstände zwischen den Pulsen ({ $intervals } s) passen weder zu einem Puls pro Periode (gleiche Abstände) noch zu einem engen Paar pro Periode (abwechselnd kurz und lang, der kurze unter dem 0,6-Fachen des langen); { $advice }
estimate-pulses-alternate = sie wechseln zwischen kurz und lang: zwei Pulse pro Periode (der Magnet läuft hin und zurück am Sensor vorbei, der Sensor liegt vor dem Umkehrpunkt oder nahe der Mitte des Wegs), ein zu weites Paar, um es allein zu erkennen: gib { $geometry } an
estimate-pulses-irregular = sie sind unregelmäßig (Störpulse, die Platte springt, ein schwaches oder verrauschtes Signal): { $plot } zeigt sie
estimate-counts-one = { $pulses } Pulse ergaben { $periods } Periode, { $accepted } angenommen und { $discarded } verworfen
estimate-counts = { $pulses } Pulse ergaben { $periods } Perioden, { $accepted } angenommen und { $discarded } verworfen
estimate-look = { $plot } zeigt die Pulse und warum jede Periode verworfen wurde
estimate-more-discarded-none = { $counts }: mehr verworfen als angenommen, die Pulse halten also keine gleichmäßige Periode (der Schätzer eines Aufbaus verwirft eine Periode nur bei einem fehlenden, gestörten oder verformten Puls und nimmt eine innerhalb von { $tolerance_percent } % des gleitenden Medians an, in die ab und zu auch zufällige Abstände fallen); es wird kein T berechnet: ist es die Aufzeichnung des Hall-Sensors, von einer schwingenden Platte? Eine Platte, die öfter springt als nicht, braucht einen ruhigeren Aufbau; { $look }
estimate-more-discarded = { $counts }: mehr verworfen als angenommen, die Pulse halten also keine gleichmäßige Periode (der Schätzer eines Aufbaus verwirft eine Periode nur bei einem fehlenden, gestörten oder verformten Puls und nimmt eine innerhalb von { $tolerance_percent } % des gleitenden Medians an, in die ab und zu auch zufällige Abstände fallen); aus den { $accepted } angenommenen wird kein T berechnet: ist es die Aufzeichnung des Hall-Sensors, von einer schwingenden Platte? Eine Platte, die öfter springt als nicht, braucht einen ruhigeren Aufbau; { $look }
estimate-too-few-accepted = { $counts }: T ± ΔT braucht mindestens { $least } angenommene Perioden (der Artikel mittelte über 10 bis 100); zeichne länger auf
estimate-scatter = { $counts }: die angenommenen Perioden streuen um ΔT/T = { $scatter_percent } % (ΔT = { $spread_s } s um T = { $period_s } s), mehr als die { $most_percent } % jedes Aufbaus (die Perioden des Artikels: 0,5 bis 8 %): Perioden, die über das ganze ±{ $tolerance_percent } %-Fenster des Schätzers verteilt sind, gehören zu keiner Schwingung; ist es die Aufzeichnung des Hall-Sensors? { $look }
estimate-no-rig = T = { $period_s } s und μk = { $mu_k } gehören zu keinem Aufbau ({ $why }); daraus wird nichts berechnet
table-too-many-fields = erwartet: höchstens { $named } Felder, wie die Kopfzeile sie benennt, gefunden: { $found }
table-not-a-number = erwartet: eine Zahl in der Spalte „{ $column }“, gefunden: „{ $found }“
table-no-header = erwartet: eine Kopfzeile, deren erste Spalte eine Zeit benennt („t“, „Time (s)“), keine gefunden
reading-not-periodic = erwartet: eine periodische Bewegung, keine gefunden in { $column } der Aufzeichnung ({ $instrument }): ihre stärkste Frequenz, { $frequency_hz } Hz (eine Periode von { $period_s } s), liegt { $ratio }-mal über dem Median ihres Spektrums, wo die einer schwingenden Platte { $least_ratio }-mal oder mehr darüber liegt; ihr Rauschen beträgt { $noise } und sie schwankt um { $swing } (in der Einheit dieser Spalte). Ist es eine Aufzeichnung des schwingenden Aufbaus, nicht eines ruhig liegenden Handys oder eines anderen Versuchs?
column-named = „{ $name }“
column-field-magnitude = |B|
column-plate-position = die Position der Platte ({ $unit })
# Was die Datei einer Messung erzeugt hat.
instrument-hall-sensor = Hall-Sensor
instrument-phyphox-magnetometer = phyphox-Magnetometer
instrument-phyphox-accelerometer = phyphox-Beschleunigungssensor
instrument-phyphox-linear-accelerometer = phyphox-Beschleunigungssensor (ohne g)
instrument-tracker = Tracker
instrument-position-table = Weg-Zeit-Tabelle
instrument-phyphox-location = phyphox-Standort (GPS)
instrument-phyphox-audio = phyphox-Audio
instrument-phyphox-other = phyphox-Sensor einer anderen Art
instrument-phyphox-export = phyphox-Export (zip)
instrument-excel = Excel-Arbeitsmappe (.xlsx)
instrument-zip = Zip-Archiv
instrument-video = Video
# Die serielle Schnittstelle des Aufbaus.
port-not-there = diese serielle Schnittstelle gibt es nicht (ist die Platine eingesteckt? ls /dev/ttyACM* /dev/ttyUSB*)
port-not-allowed = der Benutzer dieses Rechners darf die serielle Schnittstelle nicht öffnen (trage dich in die Gruppe dialout ein und melde dich neu an)
port-busy = ein anderes Programm hat die serielle Schnittstelle offen: schließe den seriellen Monitor
port-failed = { $port } lässt sich nicht öffnen: { $why }
port-log-full = die Aufzeichnung hat ihre { $megabytes } MB erreicht (etwa { $minutes } Minuten bei den 1 kHz der Firmware): die Schnittstelle ist geschlossen und die Aufzeichnung bleibt erhalten; verbinde dich neu, um eine neue zu beginnen
port-unplugged = { $port } ist um { $time } verschwunden (Platine ausgesteckt?): die { $lines } empfangenen Zeilen bleiben erhalten, lade sie unten herunter; stecke die Platine ein und verbinde dich neu
# Die Ablehnungen des Klassenservers.
server-no-session = diese Sitzung gibt es nicht (sie ist beendet oder hat nie begonnen)
server-full = das Labor ist voll: es führt { $sessions } Sitzungen gleichzeitig aus, seine Grenze; versuche es wieder, wenn eine endet
server-reading-files = das Labor liest gerade die Dateien anderer Schüler: schicke deine in ein paar Sekunden noch einmal
server-too-many = zu viele Anfragen von { $address }: höchstens { $per_second } pro Sekunde; warte { $wait_s } s
quantity-spacing = den Achsabstand der Rollen l
quantity-mu-k = μk
quantity-h-c = die Schwerpunkthöhe h_c
quantity-period = die Periode T
quantity-amplitude = die Amplitude A
quantity-gravity = die Fallbeschleunigung g
quantity-roller-speed = die Drehzahl der Rollen
quantity-roller-radius = den Rollenradius
paper-spacing = 89 mm
paper-mu-k = 0,2 bis 10
paper-h-c = einige mm
paper-period = 0,3 bis 1 s
paper-amplitude = 20 mm
paper-gravity = 9,81 m/s²
paper-roller-speed = 1600 U/min
paper-roller-radius = 10 mm

report-title = Versuchsprotokoll: der Reibungsoszillator
report-decimal-sign = ,
report-method = Methode
report-method-text = Eine Platte liegt auf zwei Rollen im Achsabstand l, die sich gegensinnig drehen, ihre Oberseiten aufeinander zu. Die Gleitreibung an jedem Kontakt ist das μk-Fache des Anteils der Gewichtskraft der Platte, den die jeweilige Rolle trägt, und die nähere Rolle trägt mehr: Die Differenz zieht die Platte mit einer Kraft proportional zu ihrer Auslenkung zur Mitte zurück. Die Platte schwingt mit der Periodendauer T = π √(2 l / (μk g)), eine gemessene Periodendauer liefert also μk = 2π² l / (g T²) ({ $citation }). Ein Hall-Sensor erfasst die Magnete an den Enden der Platte; der Schätzer des Aufbaus misst die Zeiten seiner Impulse, behält jede Periode, die höchstens 20 % vom gleitenden Median abweicht, und mittelt sie.
report-simulation-title = Simulation: { $name }
report-measurement-title = Messung: { $name }
report-set-up = Versuchsaufbau
report-data = Daten
report-result = Ergebnis
report-periods = Die Perioden
report-comparison = Vergleich
report-stopwatch = Von Hand gestoppt
report-setup-scene = Szene
report-setup-spacing = Achsabstand der Rollen l
report-setup-speed = Drehzahl der Rollen
report-setup-plate = Platte
report-setup-mu-k-set = in der Simulation eingestelltes μk
report-setup-h-c = Höhe des Plattenschwerpunkts über den Kontakten, h_c
report-setup-mass = Masse der Platte
report-setup-duration = simulierte Zeit
report-setup-time-step = Zeitschritt
report-setup-seed = Seed (Rauschen des Sensors)
report-setup-instrument = Messgerät
report-setup-file = Datei
report-setup-gravity = g
report-setup-samples = Messwerte, Zeitspanne und Abtastrate
report-axis-time = t (s)
report-axis-position = x (mm)
report-axis-hall = Hall-Sensor (ADC-Werte)
report-axis-start = Beginn der Periode (s)
report-axis-period = T (s)
report-position-caption = Die Position x(t) der Platte über die ganze Simulation (ihre simulierte Bahn).
report-hall-caption = Das Signal des Hall-Sensors, wie der Arduino des Aufbaus es liest: ein Impuls bei jedem Vorbeilaufen eines Magneten über dem Sensor.
report-measurement-caption = Die Messung, wie gelesen: der Kanal, dessen Zeiten der Schätzer gemessen hat.
report-periods-plot = Jede Periode über ihrem Beginn
report-periods-caption = Jede Periode an ihrem Beginn: Die Streuung der akzeptierten ist die Standardabweichung der Perioden.
report-accepted = akzeptiert
report-discarded = verworfen
report-no-period = Der Schätzer hat keine Periode gefunden.
report-column-start = Beginn (s)
report-column-end = Ende (s)
report-column-accepted = akzeptiert
report-yes = ja
report-no-beyond-median = nein: mehr als 20 % vom gleitenden Median entfernt
report-no-spread = keine Streuung: nur eine Periode
report-period-why = T ist der Mittelwert der { $count } akzeptierten Perioden; dT ist ihr Standardfehler (ihre Standardabweichung, { $sd } s, geteilt durch die Wurzel ihrer Anzahl).
report-mu-k-why = μk = 2π² l / (g T²), mit l = { $spacing } mm und g = { $gravity } m/s². Seine Unsicherheit addiert quadratisch die des Achsabstands, dl / l mit dl = { $dl } mm, und die der Periodendauer, 2 σT / T, wobei σT die Standardabweichung der Perioden ist, so wie der Arduino des Aufbaus sie berechnet; linear statt quadratisch addiert ergeben sie ± { $worst }.
report-regime = Bewegungsform: { $regime }.
report-regime-oscillates = schwingt
report-regime-clipped = begrenzt
report-regime-stick-slip = Haftgleiten
report-regime-grows = wächst
report-regime-decays = klingt ab
report-regime-sticks = haftet
report-regime-tips = kippt oder hebt von einer Rolle ab
report-regime-no-restoring-force = keine Rückstellkraft
report-regime-lost = verloren (vom Aufbau gefallen)
report-regime-numerically-failed = numerisch gescheitert
report-source = Quelle
report-theory-row = Theorie für das eingestellte μk, { $mu }: dünne Platte, π √(2 l / (μk g)); mit der Dicke der Platte
report-thick-row = { $name }: μk aus T nach der Formel für dicke Platten, 2π² l / (g T² + 4π² h_c), wobei h_c die Höhe des Plattenschwerpunkts über den Kontakten ist
report-paper-row = Tabelle I des Artikels: { $material }, { $kelvin } K
report-no-paper-row = Tabelle I des Artikels hat keine Zeile für dieses Material bei dieser Temperatur.
report-column-periods = Perioden
report-column-wall = Echtzeit (s)
report-column-simulated = simuliert (s)
report-column-by-hand = T von Hand (s)
report-stopwatch-why = Jeder Druck auf die Stoppuhr kommt um eine Reaktionszeit zu früh oder zu spät, etwa 0,2 s: Über zehn Perioden sind das 0,02 s in T.
report-footer = Erstellt mit { $version }: die Simulation und der Schätzer aus dem Arduino-Code des Aufbaus; die Methode nach { $citation }.
