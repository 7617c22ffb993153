# Las palabras de frictionlab en español: las de la página del navegador (web/) y las del informe
# de laboratorio (los mensajes report-*, que lee el propio laboratorio), un mensaje por
# identificador, en el formato Fluent de Mozilla (https://projectfluent.org/fluent/guide/). Cada
# mensaje de en.ftl está aquí, con las mismas variables. Un número en { $name } llega ya escrito
# en el idioma de la página; el que un mensaje usa para elegir ({ $periods -> [one] ... *[other]
# ... }) es una cuenta. Términos: periodo T, coeficiente de rozamiento cinético μk, separación de
# los rodillos l, desviación típica, error típico.

language-name = Español

## El marco de la página

page-title = frictionlab — el oscilador de rozamiento en tu navegador
page-subtitle = el oscilador de rozamiento en tu navegador
class-page-title = frictionlab — la tabla de la clase
class-page-subtitle = la tabla de la clase
language-label = Idioma
skip-to-controls = Ir a los controles
lab-place-browser = El laboratorio funciona en este navegador: no se envía nada a ninguna parte.
lab-place-server = El laboratorio funciona en el servidor { $host }.
page-problem-unexpected = El laboratorio no respondió como se esperaba: { $message }
# Entre las partes de una lista en una línea: "placa delgada T = 0,634 s; μₖ = 0,29".
parts-separator = {"; "}
# Un valor en segundos, tal como lo escriben las lecturas.
seconds = { $seconds } s

## El montaje en 3D

view-title = El montaje en 3D
view-canvas-label = El montaje en 3D: la placa sobre sus dos rodillos
view-reset = Restablecer vista
force-normal = fuerza normal
force-friction = rozamiento
force-weight = peso m g (3 cm)
view-hint-mouse = Arrastra para girar · rueda para ampliar.
view-hint-touch = Arrastra para girar · pellizca para ampliar.
view-keys = Teclas en la vista: flechas giran, Mayús + flechas desplazan, + y − amplían, Inicio restablece.
view-near-side = mostrar la pared delantera

## La simulación

run-title = Simulación
run-play = Reproducir
run-pause = Pausa
run-play-again = Volver a reproducir
run-step = Paso
    .title = Un fotograma: 1/30 s de tiempo simulado
run-reset = Reiniciar
run-slow-motion = Cámara lenta
run-status-connecting = conectando
run-status-paused = en pausa
run-status-playing = en marcha
run-status-done = terminada
run-status-no-session = sin sesión
run-time = t = { $t } s
run-failure = La simulación se detuvo: { $message }
period = T = { $period } s
period-none = T = — s
period-waiting = T = … s
mu-k = μₖ = { $muK }
mu-k-none = μₖ = —
period-detail-none = aún no hay ningún periodo aceptado
period-detail-no-spread =
    de { $periods ->
        [one] { $periods } periodo
       *[other] { $periods } periodos
    }: aún sin dispersión
period-detail-spread =
    ± es la desviación típica de { $periods ->
        [one] { $periods } periodo
       *[other] { $periods } periodos
    }; el error típico de la media, σ/√N, { $se } s, indica con qué precisión se conoce T
period-detail-done = resultado de la simulación: ± es la desviación típica de los periodos; el error típico de la media, σ/√N, { $se } s, indica con qué precisión se conoce T
scene-paper-rig = El montaje del artículo
scene-paper-rig-77K = El montaje del artículo a 77 K
scene-paper-rig-77K-warming = El montaje del artículo a 77 K, calentándose
scene-minimal = El montaje mínimo
scene-roller-ramp = El montaje mínimo, con sus rodillos frenados y acelerados
regime-label = Régimen:

## Los regímenes que nombra el laboratorio (el `regime` de su resumen); un régimen que falte en
## este archivo se muestra tal como lo escribió el laboratorio.

regime-oscillates = oscila
regime-clipped = recortado
regime-stick-slip = pegado-deslizamiento
regime-grows = crece
regime-decays = decrece
regime-sticks = se pega
regime-tips = vuelca
regime-no-restoring-force = sin fuerza recuperadora
regime-lost = placa perdida
regime-numerically-failed = fallo numérico
regime-since = { " " }desde t = { $t } s
regime-jumps = ; { $jumps ->
        [one] { $jumps } salto
       *[other] { $jumps } saltos
    } sobre un rodillo, de hasta { $height } mm
regime-help-oscillates = Ambos rodillos deslizan bajo la placa todo el tiempo: la oscilación armónica cuyo periodo da μk.
regime-help-clipped = Una vez, la placa fue tan rápida como la superficie de un rodillo y se pegó a ella: eso recortó la amplitud a la velocidad superficial de los rodillos dividida por ω. El periodo no cambia.
regime-help-stick-slip = La placa se pega a un rodillo durante parte de cada ciclo y luego desliza: su periodo ya no es el de la fórmula.
regime-help-grows = Aquí el rozamiento disminuye con la velocidad de deslizamiento: la amplitud crece de un ciclo a otro.
regime-help-decays = Aquí el rozamiento aumenta con la velocidad de deslizamiento: la amplitud decrece de un ciclo a otro.
regime-help-sticks = La placa sigue pegada a un rodillo (o los rodillos están parados): no hay oscilación que cronometrar.
regime-help-tips = La fuerza normal de un rodillo llegó a cero: la placa volcó o se levantó de él.
regime-help-no-restoring-force = El rozamiento aleja la placa del centro (l ≤ 2 μk h_c, o rodillos que giran hacia fuera): se va desplazando.
regime-help-lost = La placa se cayó de los rodillos o salió del montaje.
regime-help-numerically-failed = La simulación falló (un número se hizo infinito, o la energía creció sin límite).

## Las gráficas y los periodos

plots-title = Gráficas
plot-position-caption = Posición x(t) de la placa, teoría a trazos (últimos 5 s)
plot-position-box =
    .aria-label = Gráfica de la posición x de la placa frente al tiempo t, los últimos 5 s; sus datos están en la tabla de abajo
plot-hall-caption = Sensor Hall, sus pulsos a trazos (últimos 5 s)
plot-hall-box =
    .aria-label = Gráfica de las cuentas del ADC del sensor Hall frente al tiempo t, los últimos 5 s, con los pulsos que halló el estimador marcados; sus datos están en la tabla de abajo
plot-hall-none = Este montaje no tiene sensor Hall.
plot-table-summary = Datos en tabla
plot-table-position-hidden = : la posición de la placa
plot-table-hall-hidden = : las cuentas del ADC del sensor Hall
plot-hall-column = Hall (cuentas ADC)
plot-adc-axis = cuentas ADC
plot-position-series = x (mm)
plot-theory-series = teoría x_th (mm)
plot-rig-hall-series = Hall del montaje (ADC)
# Lo que contiene la tabla de una gráfica, para su leyenda ("Aún no hay muestras de ...").
plot-table-position-what = la posición x de la placa (mm)
plot-table-hall-what = las cuentas del ADC del sensor Hall
plot-table-empty = Aún no hay muestras de { $what }.
# $what: plot-table-position-what o plot-table-hall-what, con la primera letra en mayúscula.
plot-table-every = { $what }, t de { $from } a { $to } s: todas las muestras representadas ({ $rows }).
plot-table-some = { $what }, t de { $from } a { $to } s: { $rows } de las { $samples } muestras representadas, repartidas uniformemente en el tiempo.
periods-caption = Periodos según los juzga el estimador:
periods-region =
    .aria-label = Tabla de periodos
periods-from = inicio (s)
periods-accepted-column = aceptado
periods-status-column = estado
periods-yes = ✓ sí
periods-no = ✗ no
periods-accepted = aceptado
periods-rejected = rechazado
periods-none = ninguno aún
periods-tally = aceptados: { $accepted } de { $count }

## El panel lateral: el montaje y su teoría

panel =
    .aria-label = Configuración y herramientas
rig-values-title = Montaje y teoría
rig-values-spacing = Separación l
rig-values-rollers = Rodillos
rig-values-plate = Placa
rig-values-theory = Teoría
spacing-value = { $spacing } mm
rollers-value = { $rpm } rpm
rollers-value-driven = { $rpm } rpm (accionados por el motor)
theory-thin = placa delgada T = { $period } s
theory-thick = placa gruesa { $period } s
theory-mu-k = μₖ = { $muK }
theory-paper = artículo: T = { $period } s, μₖ = { $muK }

## El cronómetro

stopwatch-title = Cronómetro: mide diez periodos
stopwatch-start = Iniciar
stopwatch-stop = Parar
stopwatch-clear = Borrar
stopwatch-space = o pulsa Espacio
stopwatch-wall = Tiempo real
stopwatch-simulated = Simulado
stopwatch-estimator = Estimador
# $total: el tiempo entre las pulsaciones; $periods: los periodos cronometrados; $period: uno de ellos.
stopwatch-timed = { $total } s, ÷ { $periods } = { $period } s

## La configuración

setup-title = Configuración
setup-scene = Escena
setup-material = Material de la placa (tabla I)
setup-spacing = Separación de los rodillos l
setup-spacing-slider =
    .aria-label = Separación de los rodillos l, control deslizante (mm)
setup-speed = Velocidad de los rodillos
setup-speed-slider =
    .aria-label = Velocidad de los rodillos, control deslizante (rpm)
unit-rpm = rpm
setup-duty = Ciclo de trabajo del motor (PWM)
setup-duty-slider =
    .aria-label = Ciclo de trabajo del motor, control deslizante (%)
setup-law = Ley de rozamiento
setup-law-scene = la de la escena
setup-mu-s = μs (estático)
setup-from-scene =
    .placeholder = escena
setup-runout = Excentricidad de los rodillos
setup-offset = Desplazamiento inicial
setup-offset-slider =
    .aria-label = Desplazamiento inicial, control deslizante (mm)
setup-duration = Duración
setup-duration-hint = Lo bastante para cronometrar a mano diez periodos (unos 8 s en el montaje del artículo), y más.
setup-accepts = Esta configuración admite de { $least } a { $most } { $unit }.
setup-beyond = { $found } { $unit } está fuera de lo que admite esta configuración, de { $least } a { $most } { $unit }: el laboratorio sigue como estaba.
number-nothing = se esperaba un número y no hay nada
number-decimal-point = se esperaba un número con punto decimal, como 89.5, y no «{ $text }»
number-expected = se esperaba un número, como { $example }, y no «{ $text }»

# Los materiales de la placa de la tabla I del artículo.
material-lego = Bloques de LEGO
material-paper = Papel
material-polished-wood = Madera pulida
material-construction-wood = Madera de construcción
material-iron = Hierro
material-plexiglas = Plexiglás
material-brass = Latón
material-cardboard = Cartón
material-rigid-foam = Espuma rígida de poliuretano
material-flexible-foam = Espuma flexible de poliuretano

## La clase

class-title = La clase
student-name-label = Tu nombre (para la tabla de la clase)
student-name-hint = Aparece en la tabla de la clase mientras escribes y se envía con cada sesión que inicies; letras, cifras, espacios y . - _ ' , ( ).
student-name-not-sent = No enviado: { $problem }.
student-name-too-long = como máximo { $most } caracteres
student-name-characters = solo letras, cifras, espacios y . - _ ' , ( ), empezando por una letra o una cifra
class-link = La tabla de la clase

## Tu medición

measurement-title = Tu medición
measurement-file = Un archivo que has medido
measurement-note = El registro del sensor Hall de tu montaje, una exportación de phyphox de un móvil (CSV o zip), datos de Tracker, una tabla posición-tiempo o un vídeo corto de móvil, elegido aquí o soltado en este panel: el laboratorio lee su periodo, y μₖ con la separación de esta configuración.
measurement-reading = leyendo { $file }
measurement-busy = el laboratorio está leyendo otros archivos; { $file } en un momento
# $instrument: el nombre que da el laboratorio a lo que hizo el archivo (y su canal).
measurement-result =
    { $file }: { $instrument }, N = { $periods } { $periods ->
        [one] periodo
       *[other] periodos
    }; μₖ = { $muK } con l = { $spacing } mm
measurement-phone-note = Un móvil sobre la placa eleva su centro de masas: este μₖ, según la fórmula del artículo, es demasiado alto en la fracción 4π²h_c/(gT²) (frictionlab estimate --h-c da el de la fórmula de placa gruesa)

## El montaje real

rig-title = El montaje real
rig-summary-looking = buscando el Arduino del montaje
rig-summary-connect = conecta el Arduino del montaje
rig-summary-no-web-serial = sin Web Serial: elige su archivo de registro
rig-summary-ports =
    { $ports ->
        [one] { $ports } puerto serie encontrado
       *[other] { $ports } puertos serie encontrados
    }
rig-port-label = Puerto serie del Arduino del montaje
rig-no-port-found = no se encontró ningún puerto serie
rig-connect = Conectar
rig-close = Cerrar
rig-choose-note = Laboratorio compartido: solo el ordenador del laboratorio elige el puerto.
rig-connect-note = Al conectar se reproduce a su lado la simulación de esta configuración desde t = 0.
rig-plot-caption = El sensor Hall del montaje (últimos 10 s): los periodos terminan en las líneas rojo anaranjado (gris a trazos: rechazados)
rig-periods-caption = Los periodos del montaje, el más reciente primero:
rig-periods-region =
    .aria-label = Los periodos del montaje
rig-log = El registro en bruto del montaje
rig-log-named = El registro en bruto del montaje ({ $name })
rig-problem = El montaje: { $message }
rig-lines =
    { $lines ->
        [one] { $lines } línea
       *[other] { $lines } líneas
    }
# El estado del puerto, como lo nombra el laboratorio (closed, waiting, receiving, unplugged, failed, full).
rig-port-state =
    { $state ->
        [closed] cerrado
        [waiting] en espera
        [receiving] recibiendo
        [unplugged] desconectado
        [failed] fallido
        [full] lleno
       *[other] { $state }
    }
rig-state-none = ningún puerto abierto
# $lines: rig-lines, ya escrito.
rig-state-closed = cerrado ({ $port } estuvo abierto; recibido: { $lines })
rig-state-waiting = esperando a { $port }: aún no se ha recibido nada
rig-state-receiving = recibiendo de { $port }, { $lines }
rig-state-unplugged = desconectado: { $port } desapareció tras { $lines }
rig-state-failed = fallo: { $port }
rig-state-other = { $state }: { $port }
rig-the-port = el puerto
rig-geometry-one-pulse = un pulso por periodo
rig-geometry-pair = un par de pulsos por periodo
rig-geometry-unknown = pulsos aún no reconocidos
rig-estimate-periods =
    N = { $periods } { $periods ->
        [one] periodo
       *[other] periodos
    }
rig-estimate-se = el error típico de la media, σ/√N, { $se } s
rig-estimate-spacing = l = { $spacing } mm (la separación de esta configuración)
rig-estimate-note = ± es la desviación típica de los periodos, dμₖ en cuadratura

## Exportar

export-title = Exportar
export-files = Los archivos de la simulación (al terminar):
export-report = Informe de laboratorio
export-report-hint = Tras la simulación: la configuración, los datos, T y μk con sus incertidumbres, frente al artículo, en una página para entregar o imprimir en PDF.
export-report-writing = Redactando el informe…
export-report-done = report.html se ha descargado: ábrelo e imprímelo en PDF desde el navegador para entregarlo.
export-png = PNG de la vista
export-link = Enlace a esta configuración
export-copy = Copiar
export-copy-by-hand = Selecciona el enlace y cópialo a mano.
export-copied = Copiado.

## El montaje en palabras, para un lector de pantalla

# Dónde está la placa: $side es left, right o centre; $mm su distancia al centro.
plate-where =
    { $side ->
        [left] a { $mm } mm a la izquierda del centro
        [right] a { $mm } mm a la derecha del centro
       *[centre] en el centro
    }
# $where: plate-where, ya escrito; $motion: left, right o rest.
plate-now =
    La placa está { $where }, { $motion ->
        [left] moviéndose hacia la izquierda
        [right] moviéndose hacia la derecha
       *[rest] en reposo
    }.
rollers-one = La placa descansa solo sobre el rodillo { $side ->
        [left] izquierdo
       *[right] derecho
    } ({ $newtons } N).
rollers-same = Ambos rodillos soportan el mismo peso ({ $newtons } N cada uno).
rollers-more =
    El rodillo { $more ->
        [left] izquierdo
       *[right] derecho
    } soporta más peso de la placa: { $most } N frente a { $least } N en el { $more ->
        [left] derecho
       *[right] izquierdo
    }.
period-said-done = El periodo de la simulación: T = { $period } s.
period-said-none = Aún no se ha medido ningún periodo.
period-said-so-far =
    El periodo hasta ahora: T = { $period } s, de { $periods ->
        [one] { $periods } periodo
       *[other] { $periods } periodos
    }.
# $sense: inward u outward; $material: el nombre que da el laboratorio al material de la placa; $start: plate-where.
set-up-said =
    Dos rodillos separados { $spacing } mm (la separación l), con sus partes superiores girando { $sense ->
        [inward] una hacia la otra
       *[outward] alejándose una de otra
    } a { $rpm } rpm, bajo una placa de { $material } de { $length } mm de largo y { $mass } g; la placa parte { $start }. El periodo según la teoría de placa delgada: { $period } s.
# $moment: playing, paused u over; $motion: plate-now y lo que le sigue, ya escrito.
moment-said =
    { $moment ->
        [paused] En pausa en
        [over] La simulación terminó en
       *[playing] Reproduciendo, en
    } t = { $t } s. { $motion }

## La tabla de la clase (class.html)

class-back = Volver al laboratorio
class-caption = La configuración y el resultado de cada sesión abierta, como la tabla I del artículo rellenada por la clase:
class-asking = consultando al laboratorio
class-column-name = nombre
class-column-scene = escena
class-column-material = material
class-column-temperature = temperatura (K)
class-column-spacing = separación l (mm)
class-column-state = estado
class-column-period = periodo T ± dT (s)
class-column-paper = μₖ del artículo
class-column-hide = ocultar la fila
class-show-hidden = Mostrar las filas ocultas
class-show-hidden-count =
    { $hidden ->
        [one] Mostrar la fila oculta
       *[other] Mostrar las { $hidden } filas ocultas
    }
class-hint = T ± dT: la media de los periodos aceptados ± su error típico, redondeada a este («ajuste del movimiento»: un montaje sin sensor Hall, con su periodo ajustado al movimiento de la placa); μₖ ± dμₖ en cuadratura con el dl de la separación; el μₖ del artículo, de su tabla I; — donde aún no hay. Se actualiza cada 2 s. El encabezado de una columna ordena las filas por ella (otra vez: al revés). «Ocultar» quita una fila solo de esta página (un estudiante que se fue, una simulación ya anotada), y así sigue en este navegador; class.csv contiene todas las sesiones abiertas.
class-motion-fit = { $period } (ajuste del movimiento)
class-hide = Ocultar
class-hide-named = Ocultar la fila de { $name }
class-hide-unnamed = Ocultar la fila de la sesión sin nombre
class-no-session = No hay ninguna sesión abierta.
class-all-hidden = Todas las filas están ocultas.
class-count =
    { $sessions ->
        [one] { $sessions } sesión
       *[other] { $sessions } sesiones
    }
class-count-hidden =
    { $sessions ->
        [one] { $sessions } sesión
       *[other] { $sessions } sesiones
    }, { $hidden ->
        [one] { $hidden } oculta
       *[other] { $hidden } ocultas
    } aquí
# $state: rig-port-state, ya escrito; $lines: rig-lines, ya escrito.
class-rig = El montaje real: { $port }, { $state }, recibido: { $lines }
class-rig-no-port = sin puerto
class-updated = actualizado a las { $time }
# El estado de una sesión, como lo nombra el laboratorio (paused, playing, done).
session-state =
    { $state ->
        [paused] en pausa
        [playing] en marcha
        [done] terminada
       *[other] { $state }
    }

## Las palabras de la página sobre el laboratorio (donde la respuesta del laboratorio no dice nada)

lab-no-json = el laboratorio respondió { $status } sin JSON
lab-answered = el laboratorio respondió { $status }
lab-busy = el laboratorio está ocupado: demasiadas peticiones desde este ordenador; inténtalo de nuevo en unos segundos
lab-busy-seconds = el laboratorio está ocupado: demasiadas peticiones desde este ordenador; inténtalo de nuevo en { $seconds } s
lab-setup-problems = la configuración tiene problemas
lab-full = el laboratorio está lleno: inténtalo de nuevo cuando termine una sesión
lab-stopped = el laboratorio se detuvo
lab-superseded = una configuración más reciente ocupó el lugar de esta
browser-lab-stopped = el laboratorio de este navegador se detuvo: { $why }
browser-lab-worker-failed = su worker falló
browser-lab-no-class = la tabla de la clase es de un servidor de aula (frictionlab serve): este laboratorio funciona en un solo navegador
serial-choose = el navegador pregunta cuál
serial-missing = Este navegador no puede abrir el puerto serie del montaje (Web Serial está en Chrome, Edge y Opera en ordenador): guarda el registro del montaje (el monitor serie del Arduino, o frictionlab log) y elige el archivo en «Tu medición»
serial-no-baud = el laboratorio no dio ninguna velocidad en baudios para el puerto del montaje
serial-none-chosen = no se eligió ningún puerto: pulsa Conectar de nuevo y elige el Arduino del montaje
serial-not-opened = no se pudo abrir el puerto ({ $why }): cierra el monitor serie del IDE de Arduino o cualquier otra página que lo use, y vuelve a conectar
serial-chosen-port = el puerto serie elegido

## El informe de laboratorio (frictionlab report, el «Informe de laboratorio» de la página): lo
## lee el propio laboratorio, así que cada mensaje aquí es texto plano con solo { $variable }.

## Los mensajes del propio laboratorio: lo que rechaza y por qué.

check-must-be-positive = debe ser un valor positivo, se encontró { $value }
check-must-be-positive-in = debe ser un valor positivo, se encontró { $value } { $unit }
check-length-must-be-positive = debe ser un valor positivo, se encontró { $value } m ({ $value_mm } mm)
check-must-be-finite = debe ser finito
check-implausible = se esperaba { $what } de { $least } a { $most }{ $unit } (el montaje del artículo: { $paper }), se encontró { $value }{ $unit }
check-implausible-value = { $why }; revisa el valor y su unidad (un número sin unidad está en SI)
check-tilt = debe estar entre -30 y 30 grados, se encontró { $degrees } ° (un ángulo sin unidad está en radianes)
check-solver-iterations = debe estar entre 1 y 10000, se encontró { $iterations }
check-step-resolves = se esperaba un paso que resuelva la oscilación, más corto que un cuarto de su periodo ({ $quarter } s para la placa delgada), se encontró { $step } s; usa un paso de 1 ms
check-duration-one-step = debe durar al menos un paso de world.time_step ({ $step } s), se encontró { $duration } s: una simulación sin pasos no mide nada
check-duration-steps = necesita { $steps } pasos, más de 10⁹; usa un world.time_step mayor o una duración más corta
check-speed-not-negative = debe ser mayor o igual que 0, se encontró { $speed } rad/s
check-duty = debe estar entre 0 % y 100 %, se encontró { $duty_percent } %
check-rollers-overlap = los rodillos se solapan: l = { $spacing_mm } mm no supera la suma de sus radios, { $radii_mm } mm
check-no-oscillation = no existe oscilación: l = { $spacing_mm } mm ≤ 2 μk h_c = { $limit_mm } mm (μk = { $mu_k }, h_c = { $h_c_mm } mm); separa más los rodillos, baja el centro de masas de la placa o reduce μk
check-plate-too-short = la placa ({ $length_mm } mm) es más corta que l + 2 × amplitud = { $needed_mm } mm: dejaría un rodillo; usa una placa más larga o un desplazamiento inicial menor
check-drive-coupling = el engranaje de la transmisión (una rueda de { $roller_teeth } dientes en cada rodillo y dos ruedas intermedias de { $idler_teeth } dientes) admite separaciones de { $least_mm } a { $most_mm } mm, se encontró { $spacing_mm } mm; elige una separación en ese intervalo u otras ruedas en drive.coupling
check-sensor-in-magnet-path = el sensor está dentro del volumen que barre el imán { $magnet } al moverse la placa; súbelo por encima de la parte superior del imán, a { $top_mm } mm
check-magnetometer-in-plate-path = móvil { $phone }: el magnetómetro en [{ $x_mm }, { $y_mm }, { $z_mm }] mm está dentro del volumen que barre la placa; pon el móvil junto al montaje (|y| mayor que { $half_width_mm } mm)
check-magnetometer-in-magnet-path = móvil { $phone }: el magnetómetro está dentro del volumen que barre el imán { $magnet } al moverse la placa; pon el móvil junto al montaje
check-not-negative = debe ser mayor o igual que 0, se encontró { $value }
check-not-negative-in = debe ser mayor o igual que 0, se encontró { $value } { $unit }
check-angles-finite = deben ser ángulos finitos
check-ramp-time = punto { $point }: su instante { $time } s debe ser ≥ 0 y posterior al del punto anterior
check-ramp-value = punto { $point }: su valor { $value }{ $unit } debe estar entre { $least } y { $most }
check-ramp-times-match = los puntos del rodillo 1 deben estar en los instantes de los del rodillo 0
check-ramp-with-drive = la transmisión fija la velocidad de los rodillos; varía drive.motor.duty_ramp en su lugar
check-two-radii-drive = dos radios solo van con la transmisión ideal (el engranaje de la transmisión está pensado para un solo tamaño de rodillo); da un solo radio o quita la transmisión
check-skew = debe estar entre -10 y 10 grados (unos ejes tan lejos de ser paralelos no son un desalineamiento de banco), se encontró { $degrees } grados
check-rolling-resistance = debe ser ≥ 0 y menor que la mitad del radio del rodillo ({ $half_radius_mm } mm): un centro de presión tan adelantado respecto a la cima no es de ningún rodillo, se encontró { $found_mm } mm
check-runout = debe ser ≥ 0 y menor que la mitad del radio del rodillo ({ $half_radius_mm } mm), se encontró { $found_mm } mm
check-warming-room = debe ser más cálida que los rodillos al inicio (friction.temperature, { $start_k } K), se encontró { $room_k } K
check-speed-1-not-negative = la velocidad del rodillo 1 debe ser mayor o igual que 0, se encontró { $speed } rad/s
check-two-speeds-drive = dos velocidades [rodillo 0, rodillo 1] son de la transmisión ideal: una transmisión hace girar ambos rodillos con sus engranajes a una sola velocidad; quita la transmisión o da una sola velocidad
check-two-speeds-ramp = dos velocidades van con una velocidad constante, no con rollers.speed_ramp; da una
check-payload-on-plate = debe estar sobre la placa, a menos de media longitud ({ $half_length_mm } mm) de su centro, se encontró { $x_mm } mm
check-mu-k-positive = μk debe ser positivo, se encontró { $mu_k }
check-mu-s-at-least-mu-k = el límite estático μs debe ser al menos μk = { $mu_k }, se encontró { $mu_s }
check-stribeck-v-s = una ley de Stribeck con μs > μk necesita friction.v_s, la velocidad en la que el rozamiento pasa de μs a μk (por ejemplo 10 mm/s)
check-beta-finite = β debe ser finito, se encontró { $beta }
check-mu-negative = el μ(s) de la ley se vuelve negativo ({ $mu_min } a la mayor velocidad de deslizamiento de la simulación, { $slip_speed } m/s); usa un |β| menor o un μk mayor
check-magnet-size = imán { $magnet }: diámetro, espesor y densidad deben ser positivos
check-magnet-remanence = imán { $magnet }: la remanencia no debe ser nula
check-magnet-on-plate = el imán { $magnet } en x = { $x_mm } mm no está sobre la placa (media longitud { $half_length_mm } mm)
check-axis-non-zero = debe ser un vector no nulo
check-adc-bits = debe estar entre 1 y 16, se encontró { $bits }
check-jitter = debe ser ≥ 0 y menor que un cuarto del intervalo de muestreo
check-clock-error = debe estar dentro de ±10 % (un resonador se desvía como mucho un 0,5 %), se encontró { $error }
check-sensor-offset = debe estar entre 0 V y la tensión de alimentación
check-sensor-above = el sensor debe estar por encima de la cima de los rodillos (z > 0)
check-phone-rate = móvil { $phone }: la frecuencia debe estar entre 1 Hz y 10 kHz (phyphox registra a 50 a 500 Hz), se encontró { $rate } Hz
check-phone-noise = móvil { $phone }: el ruido debe ser mayor o igual que 0, se encontró { $noise }
check-phone-turn = móvil { $phone }: el giro debe ser finito
check-phone-earth-field = móvil { $phone }: el campo terrestre debe ser finito y de 1 mT como mucho (es de 25 a 65 µT), se encontró { $field_ut } µT
check-phone-position = móvil { $phone }: la posición debe ser finita
check-phone-mass = móvil { $phone }: la masa debe ser positiva, se encontró { $mass_kg } kg
check-phone-size = móvil { $phone }: el tamaño (ancho, largo, grosor) debe ser positivo
check-phone-height = móvil { $phone }: la altura debe ser mayor o igual que 0, se encontró { $height_mm } mm
check-phone-on-plate = móvil { $phone }: x = { $x_mm } mm pone el centro del móvil fuera de la placa (media longitud { $half_length_mm } mm)
reading-expected = una cabecera que nombre las columnas del tiempo y del ADC (por ejemplo «t_us,adc», «t_s,adc» o «time,value») o líneas de muestras
reading-empty = el registro está vacío: se esperaba { $expected }
reading-only-comments = el registro solo tiene líneas de comentario: se esperaba { $expected }
reading-no-sample-line = ninguna de las { $lines } líneas del registro es una cabecera o una muestra: se esperaba { $expected }, se encontraron líneas como { $example }
reading-tried-one = { $problem }; se probó { $tried }: no da ningún periodo de un montaje; ¿es el registro del sensor Hall del montaje, capturado entero?
reading-tried = { $problem }; se probaron { $tried }: ninguno da un periodo de un montaje; ¿es el registro del sensor Hall del montaje, capturado entero?
reading-no-samples-timed = no hay muestras tras la cabecera: se esperaban líneas de valores de { $time } y { $value }
reading-no-samples = no hay muestras tras la cabecera: se esperaban líneas de valores de { $value }
estimate-no-pulse = ningún pulso en { $samples } muestras durante { $duration_s } s (líneas { $first_line } a { $last_line }): los valores del ADC se quedan entre { $low } y { $high } cuentas; { $why }
estimate-swing-too-small = una variación de { $swing } cuentas está por debajo de las { $needed } cuentas que necesita un pulso: ¿pasa el imán por delante del sensor?
estimate-not-learned = la señal varía { $swing } cuentas, pero el estimador aprende la línea base y la polaridad de los dos primeros pulsos y no vio dos (entre pulsos la señal debe quedarse en su línea base más de la mitad del tiempo)
estimate-no-timing-level = la señal varía { $swing } cuentas, pero ningún pulso superó el nivel de cronometraje
estimate-one-pulse = solo un pulso en { $duration_s } s de registro (en t = { $at_s } s, tras los dos de los que se aprendió la señal): un periodo necesita al menos dos
estimate-few-pulses = solo { $pulses } pulsos (intervalos { $intervals } s): el estimador necesita cinco seguidos para distinguir un pulso por periodo de un par; registra más periodos
estimate-no-turning-points = { $pulses } pulsos, pero no hay dos puntos de retorno: los intervalos entre pulsos ({ $intervals } s) no encajan ni con un pulso por periodo (intervalos iguales) ni con un par cercano por periodo (corto y largo alternados, el corto por debajo de 0,6 veces el largo); { $advice }
estimate-pulses-alternate = alternan corto y largo: dos pulsos por periodo (el imán pasa ante el sensor a la ida y a la vuelta, con el sensor antes del punto de retorno o cerca del centro del recorrido), un par demasiado ancho para reconocerlo solo: indica { $geometry }
estimate-pulses-irregular = son irregulares (pulsos espurios, la placa salta, una señal débil o ruidosa): { $plot } los muestra
estimate-counts-one = { $pulses } pulsos dieron { $periods } periodo, { $accepted } aceptado y { $discarded } descartado
estimate-counts =
    { $pulses } pulsos dieron { $periods } periodos, { $accepted } { $accepted ->
        [one] aceptado
       *[other] aceptados
    } y { $discarded } { $discarded ->
        [one] descartado
       *[other] descartados
    }
estimate-look = { $plot } muestra los pulsos y por qué se descartó cada periodo
estimate-more-discarded-none = { $counts }: más descartados que aceptados, así que los pulsos no mantienen un periodo estable (el estimador de un montaje solo descarta un periodo ante un pulso que falta, espurio o deformado, y acepta uno dentro del { $tolerance_percent } % de la mediana móvil, donde también caen de vez en cuando intervalos al azar); no se calcula T: ¿es el registro del sensor Hall, de una placa que oscila? Una placa que salta más veces que no necesita un montaje más estable; { $look }
estimate-more-discarded = { $counts }: más descartados que aceptados, así que los pulsos no mantienen un periodo estable (el estimador de un montaje solo descarta un periodo ante un pulso que falta, espurio o deformado, y acepta uno dentro del { $tolerance_percent } % de la mediana móvil, donde también caen de vez en cuando intervalos al azar); no se calcula T a partir de los { $accepted } aceptados: ¿es el registro del sensor Hall, de una placa que oscila? Una placa que salta más veces que no necesita un montaje más estable; { $look }
estimate-too-few-accepted = { $counts }: T ± ΔT necesita al menos { $least } periodos aceptados (el artículo promediaba de 10 a 100); registra durante más tiempo
estimate-scatter = { $counts }: los periodos aceptados se dispersan ΔT/T = { $scatter_percent } % (ΔT = { $spread_s } s en torno a T = { $period_s } s), más allá del { $most_percent } % de cualquier montaje (los periodos del artículo: 0,5 a 8 %): periodos repartidos por toda la ventana de ±{ $tolerance_percent } % del estimador no son de ninguna oscilación; ¿es el registro del sensor Hall? { $look }
estimate-no-rig = T = { $period_s } s y μk = { $mu_k } no son de ningún montaje ({ $why }); no se calcula nada a partir de ellos
table-too-many-fields = se esperaban como mucho { $named } campos, los que nombra la cabecera, se encontraron { $found }
table-not-a-number = se esperaba un número en la columna «{ $column }», se encontró «{ $found }»
table-no-header = se esperaba una cabecera cuya primera columna nombre un tiempo («t», «Time (s)»), no se encontró ninguna
reading-not-periodic = se esperaba un movimiento periódico, no se encontró ninguno en { $column } del registro ({ $instrument }): su frecuencia más fuerte, { $frequency_hz } Hz (un periodo de { $period_s } s), está { $ratio } veces por encima de la mediana de su espectro, donde la de una placa que oscila está { $least_ratio } veces o más; su ruido es { $noise } y varía { $swing } (en la unidad de esa columna). ¿Es un registro del montaje oscilando, y no de un móvil quieto o de otro experimento?
column-named = «{ $name }»
column-field-magnitude = |B|
column-plate-position = la posición de la placa ({ $unit })
# Lo que produjo el archivo de una medida.
instrument-hall-sensor = sensor Hall
instrument-phyphox-magnetometer = magnetómetro de phyphox
instrument-phyphox-accelerometer = acelerómetro de phyphox
instrument-phyphox-linear-accelerometer = acelerómetro de phyphox (sin g)
instrument-tracker = Tracker
instrument-position-table = tabla posición-tiempo
instrument-phyphox-location = ubicación de phyphox (GPS)
instrument-phyphox-audio = audio de phyphox
instrument-phyphox-other = sensor de phyphox de otro tipo
instrument-phyphox-export = exportación de phyphox (zip)
instrument-excel = libro de Excel (.xlsx)
instrument-zip = archivo zip
instrument-video = vídeo
# El puerto serie del montaje.
port-not-there = no existe ese puerto serie (¿está conectada la placa? ls /dev/ttyACM* /dev/ttyUSB*)
port-not-allowed = el usuario de este ordenador no puede abrir el puerto serie (añádete al grupo dialout y vuelve a iniciar sesión)
port-busy = otro programa tiene abierto el puerto serie: cierra el monitor serie
port-failed = no se puede abrir { $port }: { $why }
port-log-full = el registro llegó a sus { $megabytes } MB (unos { $minutes } minutos al 1 kHz del firmware): el puerto se cerró y el registro se guardó; vuelve a conectar para empezar otro
port-unplugged = { $port } desapareció a las { $time } (¿se desconectó la placa?): las { $lines } líneas recibidas se guardan, descárgalas abajo; conecta la placa y vuelve a conectar
# Los rechazos del servidor de la clase.
server-no-session = no existe esa sesión (terminó o nunca empezó)
server-full = el laboratorio está lleno: ejecuta { $sessions } sesiones a la vez, su límite; vuelve a intentarlo cuando termine una
server-reading-files = el laboratorio está leyendo los archivos de otros estudiantes: vuelve a enviar el tuyo en unos segundos
server-too-many = demasiadas peticiones desde { $address }: como mucho { $per_second } por segundo; espera { $wait_s } s
quantity-spacing = la separación de los rodillos l
quantity-mu-k = μk
quantity-h-c = la altura del centro de masas h_c
quantity-period = el periodo T
quantity-amplitude = la amplitud A
quantity-gravity = la gravedad g
quantity-roller-speed = la velocidad de los rodillos
quantity-roller-radius = el radio de los rodillos
paper-spacing = 89 mm
paper-mu-k = 0,2 a 10
paper-h-c = unos pocos mm
paper-period = 0,3 a 1 s
paper-amplitude = 20 mm
paper-gravity = 9,81 m/s²
paper-roller-speed = 1600 rpm
paper-roller-radius = 10 mm

report-title = Informe de laboratorio: el oscilador de rozamiento
report-decimal-sign = ,
report-method = Método
report-method-text = Una placa descansa sobre dos rodillos separados una distancia l que giran en sentidos opuestos, con sus partes superiores una hacia la otra. El rozamiento cinético en cada contacto es μk por la parte del peso de la placa que soporta ese rodillo, y el rodillo más cercano soporta más: la diferencia devuelve la placa hacia el centro con una fuerza proporcional a su desplazamiento. La placa oscila con periodo T = π √(2 l / (μk g)), así que un periodo medido da μk = 2π² l / (g T²) ({ $citation }). Un sensor Hall detecta los imanes de los extremos de la placa; el estimador del montaje cronometra sus pulsos, conserva cada periodo que quede dentro del 20 % de la mediana móvil y los promedia.
report-simulation-title = Simulación: { $name }
report-measurement-title = Medición: { $name }
report-set-up = Montaje
report-data = Datos
report-result = Resultado
report-periods = Los periodos
report-comparison = Comparación
report-stopwatch = Cronometrado a mano
report-setup-scene = escena
report-setup-spacing = separación de los rodillos l
report-setup-speed = velocidad de los rodillos
report-setup-plate = placa
report-setup-mu-k-set = μk fijado en la simulación
report-setup-h-c = altura del centro de masas de la placa sobre los contactos, h_c
report-setup-mass = masa de la placa
report-setup-duration = tiempo simulado
report-setup-time-step = paso de tiempo
report-setup-seed = semilla (el ruido del sensor)
report-setup-instrument = instrumento
report-setup-file = archivo
report-setup-gravity = g
report-setup-samples = muestras, su duración y su frecuencia
report-axis-time = t (s)
report-axis-position = x (mm)
report-axis-hall = sensor Hall (cuentas ADC)
report-axis-start = inicio del periodo (s)
report-axis-period = T (s)
report-position-caption = La posición x(t) de la placa durante toda la simulación (la trayectoria simulada).
report-hall-caption = La señal del sensor Hall, tal como la lee el Arduino del montaje: un pulso cada vez que un imán pasa sobre el sensor.
report-measurement-caption = La medición, tal como se leyó: el canal que cronometró el estimador.
report-periods-plot = Cada periodo frente a su inicio
report-periods-caption = Cada periodo en su inicio: la dispersión de los aceptados es la desviación típica de los periodos.
report-accepted = aceptado
report-discarded = descartado
report-no-period = El estimador no encontró ningún periodo.
report-column-start = inicio (s)
report-column-end = fin (s)
report-column-accepted = aceptado
report-yes = sí
report-no-beyond-median = no: fuera del 20 % de la mediana móvil
report-no-spread = sin dispersión: un solo periodo
report-period-why = T es la media de los { $count } periodos aceptados; dT es su error típico (su desviación típica, { $sd } s, dividida por la raíz cuadrada de su número).
report-mu-k-why = μk = 2π² l / (g T²), con l = { $spacing } mm y g = { $gravity } m/s². Su incertidumbre combina en cuadratura la de la separación, dl / l con dl = { $dl } mm, y la del periodo, 2 σT / T con σT la desviación típica de los periodos, tal como la calcula el Arduino del montaje; sumadas en lugar de combinadas, dan ± { $worst }.
report-regime = Régimen: { $regime }.
report-regime-oscillates = oscila
report-regime-clipped = recortado
report-regime-stick-slip = pegado-deslizamiento
report-regime-grows = crece
report-regime-decays = decrece
report-regime-sticks = se queda pegada
report-regime-tips = vuelca o se levanta de un rodillo
report-regime-no-restoring-force = sin fuerza recuperadora
report-regime-lost = perdida (fuera del montaje)
report-regime-numerically-failed = fallo numérico
report-source = fuente
report-theory-row = Teoría para el μk fijado, { $mu }: placa delgada, π √(2 l / (μk g)); con el grosor de la placa
report-thick-row = { $name }: μk a partir de T con la fórmula de placa gruesa, 2π² l / (g T² + 4π² h_c), con h_c la altura del centro de masas de la placa sobre los contactos
report-paper-row = La tabla I del artículo: { $material }, { $kelvin } K
report-no-paper-row = La tabla I del artículo no tiene ninguna fila para este material a esta temperatura.
report-column-periods = periodos
report-column-wall = tiempo real (s)
report-column-simulated = simulado (s)
report-column-by-hand = T a mano (s)
report-stopwatch-why = Cada pulsación del cronómetro se adelanta o se retrasa un tiempo de reacción, unos 0,2 s: en diez periodos son 0,02 s en T.
report-footer = Hecho con { $version }: la simulación y el estimador del código Arduino del montaje; el método de { $citation }.
