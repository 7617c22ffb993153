# Les mots de frictionlab en français : ceux de la page du navigateur (web/), un message par
# identifiant, au format Fluent de Mozilla (https://projectfluent.org/fluent/guide/). Chaque
# message de en.ftl y est, avec les mêmes variables. Les espaces avant « : », « ; », entre un
# nombre et son unité et dans les guillemets sont insécables (U+00A0), écrites telles quelles.

language-name = Français

## Le cadre de la page

page-title = frictionlab — l’oscillateur à frottement dans votre navigateur
page-subtitle = l’oscillateur à frottement dans votre navigateur
class-page-title = frictionlab — le tableau de la classe
class-page-subtitle = le tableau de la classe
language-label = Langue
skip-to-controls = Aller aux commandes
lab-place-browser = Le labo tourne dans ce navigateur : rien n’est envoyé ailleurs.
lab-place-server = Le labo tourne sur le serveur { $host }.
page-problem-unexpected = Le labo n’a pas répondu comme prévu : { $message }
parts-separator = {" ; "}
seconds = { $seconds } s

## Le dispositif en 3D

view-title = Le dispositif en 3D
view-canvas-label = Le dispositif en 3D : la plaque sur ses deux rouleaux
view-reset = Vue initiale
force-normal = réaction normale
force-friction = frottement
force-weight = poids m g (3 cm)
view-hint-mouse = Glisser pour tourner · molette pour zoomer.
view-hint-touch = Glisser pour tourner · pincer pour zoomer.
view-keys = Touches sur la vue : flèches pour tourner, Maj + flèches pour décaler, + et − pour zoomer, Début pour recentrer.
view-near-side = montrer la paroi avant

## La simulation

run-title = Simulation
run-play = Lecture
run-pause = Pause
run-play-again = Rejouer
run-step = Pas à pas
    .title = Une image : 1/30 s de temps simulé
run-reset = Remise à zéro
run-slow-motion = Ralenti
run-status-connecting = connexion…
run-status-paused = en pause
run-status-playing = en cours
run-status-done = terminée
run-status-no-session = aucune session
run-time = t = { $t } s
run-failure = La simulation s’est arrêtée : { $message }
period = T = { $period } s
period-none = T = — s
period-waiting = T = … s
mu-k = μₖ = { $muK }
mu-k-none = μₖ = —
period-detail-none = aucune période retenue pour l’instant
period-detail-no-spread =
    sur { $periods ->
        [one] { $periods } période
       *[other] { $periods } périodes
    } : pas encore d’écart-type
period-detail-spread =
    ± est l’écart-type de { $periods ->
        [one] { $periods } période
       *[other] { $periods } périodes
    } ; l’erreur-type de la moyenne, σ/√N, { $se } s, dit à quel point T est connue
period-detail-done = résultat de la simulation : ± est l’écart-type des périodes ; l’erreur-type de la moyenne, σ/√N, { $se } s, dit à quel point T est connue
scene-paper-rig = Le montage de l’article
scene-paper-rig-77K = Le montage de l’article à 77 K
scene-paper-rig-77K-warming = Le montage de l’article à 77 K, qui se réchauffe
scene-minimal = Le montage minimal
scene-roller-ramp = Le montage minimal, ses rouleaux ralentis puis accélérés
regime-label = Régime :

## Les régimes que nomme le labo (le `regime` de son résumé)

regime-oscillates = oscille
regime-clipped = écrêté
regime-stick-slip = adhérence-glissement
regime-grows = croît
regime-decays = décroît
regime-sticks = adhère
regime-tips = bascule
regime-no-restoring-force = sans force de rappel
regime-lost = plaque perdue
regime-numerically-failed = échec numérique
regime-since = { " " }depuis t = { $t } s
regime-jumps =  ; { $jumps ->
        [one] { $jumps } saut
       *[other] { $jumps } sauts
    } au-dessus d’un rouleau, jusqu’à { $height } mm
regime-help-oscillates = Les deux rouleaux glissent sous la plaque tout du long : l’oscillation harmonique dont la période donne μk.
regime-help-clipped = Une fois, la plaque est allée aussi vite que la surface d’un rouleau et s’y est collée : l’amplitude est écrêtée à la vitesse de surface des rouleaux divisée par ω. La période ne change pas.
regime-help-stick-slip = La plaque adhère à un rouleau pendant une partie de chaque cycle, puis glisse : sa période n’est plus celle de la formule.
regime-help-grows = Ici le frottement diminue avec la vitesse de glissement : l’amplitude croît d’un cycle à l’autre.
regime-help-decays = Ici le frottement augmente avec la vitesse de glissement : l’amplitude décroît d’un cycle à l’autre.
regime-help-sticks = La plaque reste collée à un rouleau (ou les rouleaux sont à l’arrêt) : il n’y a pas d’oscillation à chronométrer.
regime-help-tips = La réaction normale d’un rouleau est tombée à zéro : la plaque a basculé ou décollé.
regime-help-no-restoring-force = Le frottement éloigne la plaque du milieu (l ≤ 2 μk h_c, ou rouleaux tournant vers l’extérieur) : elle dérive.
regime-help-lost = La plaque est tombée des rouleaux ou a quitté le montage.
regime-help-numerically-failed = La simulation a échoué (un nombre est devenu infini, ou l’énergie a crû sans limite).

## Les graphiques et les périodes

plots-title = Graphiques
plot-position-caption = Position x(t) de la plaque, théorie en tirets (sur 5 s)
plot-position-box =
    .aria-label = Graphique de la position x de la plaque en fonction du temps t, sur les 5 dernières secondes ; ses données sont dans le tableau ci-dessous
plot-hall-caption = Capteur à effet Hall, ses impulsions en tirets (sur 5 s)
plot-hall-box =
    .aria-label = Graphique de la valeur du CAN du capteur à effet Hall en fonction du temps t, sur les 5 dernières secondes, avec les impulsions trouvées par l’estimateur ; ses données sont dans le tableau ci-dessous
plot-hall-none = Ce dispositif n’a pas de capteur à effet Hall.
plot-table-summary = Données en tableau
plot-table-position-hidden =  : la position de la plaque
plot-table-hall-hidden =  : la valeur du CAN du capteur à effet Hall
plot-hall-column = Hall (valeur du CAN)
plot-adc-axis = valeur CAN
plot-position-series = x (mm)
plot-theory-series = théorie x_th (mm)
plot-rig-hall-series = Hall du dispositif (CAN)
plot-table-position-what = la position x de la plaque (mm)
plot-table-hall-what = la valeur du CAN du capteur à effet Hall
plot-table-empty = Pas encore d’échantillon pour { $what }.
plot-table-every = { $what }, t de { $from } à { $to } s : tous les échantillons tracés ({ $rows }).
plot-table-some = { $what }, t de { $from } à { $to } s : { $rows } des { $samples } échantillons tracés, répartis régulièrement dans le temps.
periods-caption = Périodes jugées par l’estimateur :
periods-region =
    .aria-label = Tableau des périodes
periods-from = début (s)
periods-accepted-column = retenue
periods-status-column = statut
periods-yes = ✓ oui
periods-no = ✗ non
periods-accepted = retenue
periods-rejected = rejetée
periods-none = aucune pour l’instant
periods-tally =
    { $accepted ->
        [one] { $accepted } retenue
       *[other] { $accepted } retenues
    } sur { $count }

## Le panneau latéral : le dispositif et sa théorie

panel =
    .aria-label = Réglages et outils
rig-values-title = Dispositif et théorie
rig-values-spacing = Entraxe l
rig-values-rollers = Rouleaux
rig-values-plate = Plaque
rig-values-theory = Théorie
spacing-value = { $spacing } mm
rollers-value = { $rpm } tr/min
rollers-value-driven = { $rpm } tr/min (entraînés par le moteur)
theory-thin = plaque mince T = { $period } s
theory-thick = plaque épaisse { $period } s
theory-mu-k = μₖ = { $muK }
theory-paper = article : T = { $period } s, μₖ = { $muK }

## Le chronomètre

stopwatch-title = Chronomètre : mesurer dix périodes
stopwatch-start = Démarrer
stopwatch-stop = Arrêter
stopwatch-clear = Effacer
stopwatch-space = ou la touche Espace
stopwatch-wall = Temps réel
stopwatch-simulated = Temps simulé
stopwatch-estimator = Estimateur
stopwatch-timed = { $total } s, ÷ { $periods } = { $period } s

## Le réglage

setup-title = Réglage
setup-scene = Scène
setup-material = Matériau de la plaque (tableau I)
setup-spacing = Entraxe des rouleaux l
setup-spacing-slider =
    .aria-label = Entraxe des rouleaux l, curseur (mm)
setup-speed = Vitesse des rouleaux
setup-speed-slider =
    .aria-label = Vitesse des rouleaux, curseur (tr/min)
unit-rpm = tr/min
setup-duty = Rapport cyclique du moteur (MLI)
setup-duty-slider =
    .aria-label = Rapport cyclique du moteur, curseur (%)
setup-law = Loi de frottement
setup-law-scene = celle de la scène
setup-mu-s = μs (statique)
setup-from-scene =
    .placeholder = scène
setup-runout = Faux-rond des rouleaux
setup-offset = Décalage initial
setup-offset-slider =
    .aria-label = Décalage initial, curseur (mm)
setup-duration = Durée
setup-duration-hint = Assez longue pour chronométrer dix périodes à la main (environ 8 s sur le dispositif de l’article), et plus.
setup-accepts = Ce réglage accepte de { $least } à { $most } { $unit }.
setup-beyond = { $found } { $unit } est en dehors de ce que ce réglage accepte, de { $least } à { $most } { $unit } : le laboratoire continue comme avant.
number-nothing = un nombre est attendu, rien n’a été saisi
number-decimal-point = un nombre avec un point décimal est attendu, par exemple 89.5, et non « { $text } »
number-expected = un nombre est attendu, par exemple { $example }, et non « { $text } »

# Les matériaux de la plaque du tableau I de l’article.
material-lego = Blocs LEGO
material-paper = Papier
material-polished-wood = Bois poli
material-construction-wood = Bois de construction
material-iron = Fer
material-plexiglas = Plexiglas
material-brass = Laiton
material-cardboard = Carton
material-rigid-foam = Mousse rigide de polyuréthane
material-flexible-foam = Mousse souple de polyuréthane

## La classe

class-title = La classe
student-name-label = Votre nom (pour le tableau de la classe)
student-name-hint = Affiché dans le tableau de la classe pendant la saisie, et envoyé avec chaque session que vous lancez ; lettres, chiffres, espaces et . - _ ' , ( ).
student-name-not-sent = Non envoyé : { $problem }.
student-name-too-long = { $most } caractères au plus
student-name-characters = uniquement des lettres, des chiffres, des espaces et . - _ ' , ( ), en commençant par une lettre ou un chiffre
class-link = Le tableau de la classe

## Votre mesure

measurement-title = Votre mesure
measurement-file = Un fichier de vos mesures
measurement-note = Le journal du capteur à effet Hall de votre dispositif, un export phyphox d’un téléphone (CSV ou zip), des données de Tracker, un tableau position-temps ou une courte vidéo prise au téléphone, choisi ici ou déposé sur ce panneau : le labo en lit la période, et μₖ avec l’entraxe de ce réglage.
measurement-reading = lecture de { $file }
measurement-busy = le labo lit d’autres fichiers ; { $file } dans un instant
measurement-result =
    { $file } : { $instrument }, N = { $periods } { $periods ->
        [one] période
       *[other] périodes
    } ; μₖ = { $muK } avec l = { $spacing } mm
measurement-phone-note = Un téléphone posé sur la plaque élève son centre de masse : ce μₖ, calculé par la formule de l’article, est trop grand de la fraction 4π²h_c/(gT²) (frictionlab estimate --h-c donne celui de la formule de la plaque épaisse)

## Le dispositif réel

rig-title = Le dispositif réel
rig-summary-looking = recherche de l’Arduino du dispositif
rig-summary-connect = connectez l’Arduino du dispositif
rig-summary-no-web-serial = pas de Web Serial : choisissez son fichier journal
rig-summary-ports =
    { $ports ->
        [one] { $ports } port série trouvé
       *[other] { $ports } ports série trouvés
    }
rig-port-label = Port série de l’Arduino du dispositif
rig-no-port-found = aucun port série trouvé
rig-connect = Connecter
rig-close = Fermer
rig-choose-note = Labo partagé : seul l’ordinateur du labo choisit le port.
rig-connect-note = La connexion lance à côté la simulation de ce réglage depuis t = 0.
rig-plot-caption = Le capteur à effet Hall du dispositif (sur 10 s) : les périodes finissent aux traits rouge orangé (tirets gris : rejetées)
rig-periods-caption = Les périodes du dispositif, la plus récente en premier :
rig-periods-region =
    .aria-label = Les périodes du dispositif
rig-log = Le journal brut du dispositif
rig-log-named = Le journal brut du dispositif ({ $name })
rig-problem = Le dispositif : { $message }
rig-lines =
    { $lines ->
        [one] { $lines } ligne
       *[other] { $lines } lignes
    }
rig-port-state =
    { $state ->
        [closed] fermé
        [waiting] en attente
        [receiving] réception
        [unplugged] débranché
        [failed] en échec
        [full] complet
       *[other] { $state }
    }
rig-state-none = aucun port ouvert
rig-state-closed = fermé ({ $port } était ouvert ; reçu : { $lines })
rig-state-waiting = en attente de { $port } : rien reçu pour l’instant
rig-state-receiving = réception depuis { $port }, { $lines }
rig-state-unplugged = débranché : { $port } a disparu après { $lines }
rig-state-failed = échec : { $port }
rig-state-other = { $state } : { $port }
rig-the-port = le port
rig-geometry-one-pulse = une impulsion par période
rig-geometry-pair = une paire d’impulsions par période
rig-geometry-unknown = impulsions pas encore reconnues
rig-estimate-periods =
    N = { $periods } { $periods ->
        [one] période
       *[other] périodes
    }
rig-estimate-se = l’erreur-type de la moyenne, σ/√N, { $se } s
rig-estimate-spacing = l = { $spacing } mm (l’entraxe de ce réglage)
rig-estimate-note = ± est l’écart-type des périodes, dμₖ en quadrature

## Exporter

export-title = Exporter
export-files = Les fichiers de la simulation (une fois terminée) :
export-report = Compte rendu de TP
export-report-hint = Après la simulation : le réglage, les données, T et μk avec leurs incertitudes, comparés à l’article, en une page à rendre ou à imprimer en PDF.
export-report-writing = Rédaction du compte rendu…
export-report-done = report.html est téléchargé : ouvrez-le, et imprimez-le en PDF depuis le navigateur pour le rendre.
export-png = PNG de la vue
export-link = Lien vers ce réglage
export-copy = Copier
export-copy-by-hand = Sélectionnez le lien et copiez-le à la main.
export-copied = Copié.

## Le dispositif en mots, pour un lecteur d’écran

plate-where =
    { $side ->
        [left] à { $mm } mm à gauche du centre
        [right] à { $mm } mm à droite du centre
       *[centre] au centre
    }
plate-now =
    La plaque est { $where }, { $motion ->
        [left] elle se déplace vers la gauche
        [right] elle se déplace vers la droite
       *[rest] immobile
    }.
rollers-one =
    La plaque repose sur le seul rouleau de { $side ->
        [left] gauche
       *[right] droite
    } ({ $newtons } N).
rollers-same = Les deux rouleaux portent le même poids ({ $newtons } N chacun).
rollers-more =
    Le rouleau de { $more ->
        [left] gauche
       *[right] droite
    } porte la plus grande part de son poids : { $most } N contre { $least } N sur celui de { $more ->
        [left] droite
       *[right] gauche
    }.
period-said-done = La période de la simulation : T = { $period } s.
period-said-none = Aucune période mesurée pour l’instant.
period-said-so-far =
    La période jusqu’ici : T = { $period } s, sur { $periods ->
        [one] { $periods } période
       *[other] { $periods } périodes
    }.
set-up-said =
    Deux rouleaux à { $spacing } mm l’un de l’autre (l’entraxe l), leurs sommets tournant { $sense ->
        [inward] l’un vers l’autre
       *[outward] en s’éloignant l’un de l’autre
    } à { $rpm } tr/min, sous une plaque en { $material } longue de { $length } mm et de { $mass } g ; la plaque démarre { $start }. La période selon la théorie de la plaque mince : { $period } s.
moment-said =
    { $moment ->
        [paused] En pause à
        [over] La simulation est terminée à
       *[playing] En cours, à
    } t = { $t } s. { $motion }

## Le tableau de la classe (class.html)

class-back = Retour au labo
class-caption = Le réglage et le résultat de chaque session ouverte, comme le tableau I de l’article rempli par la classe :
class-asking = interrogation du labo
class-column-name = nom
class-column-scene = scène
class-column-material = matériau
class-column-temperature = température (K)
class-column-spacing = entraxe l (mm)
class-column-state = état
class-column-period = période T ± dT (s)
class-column-paper = μₖ de l’article
class-column-hide = masquer la ligne
class-show-hidden = Afficher les lignes masquées
class-show-hidden-count =
    { $hidden ->
        [one] Afficher la ligne masquée
       *[other] Afficher les { $hidden } lignes masquées
    }
class-hint = T ± dT : la moyenne des périodes retenues ± son erreur-type, arrondie à celle-ci (« ajustement du mouvement » : un dispositif sans capteur à effet Hall, dont la période est ajustée au mouvement de la plaque) ; μₖ ± dμₖ en quadrature avec le dl de l’entraxe ; le μₖ de l’article d’après son tableau I ; — là où il n’y en a pas encore. Actualisé toutes les 2 s. L’en-tête d’une colonne trie les lignes selon celle-ci (une seconde fois : dans l’autre sens). « Masquer » retire une ligne de cette page seulement (un élève parti, une simulation déjà notée), et elle le reste dans ce navigateur ; class.csv contient toutes les sessions ouvertes.
class-motion-fit = { $period } (ajustement du mouvement)
class-hide = Masquer
class-hide-named = Masquer la ligne de { $name }
class-hide-unnamed = Masquer la ligne de la session sans nom
class-no-session = Aucune session n’est ouverte.
class-all-hidden = Toutes les lignes sont masquées.
class-count =
    { $sessions ->
        [one] { $sessions } session
       *[other] { $sessions } sessions
    }
class-count-hidden =
    { $sessions ->
        [one] { $sessions } session
       *[other] { $sessions } sessions
    }, dont { $hidden ->
        [one] { $hidden } masquée
       *[other] { $hidden } masquées
    } ici
class-rig = Le dispositif réel : { $port }, { $state }, reçu : { $lines }
class-rig-no-port = aucun port
class-updated = mis à jour à { $time }
session-state =
    { $state ->
        [paused] en pause
        [playing] en cours
        [done] terminée
       *[other] { $state }
    }

## Les mots de la page sur le labo (là où la réponse du labo ne dit rien)

lab-no-json = le labo a répondu { $status } sans JSON
lab-answered = le labo a répondu { $status }
lab-busy = le labo est occupé : trop de requêtes depuis cet ordinateur ; réessayez dans quelques secondes
lab-busy-seconds = le labo est occupé : trop de requêtes depuis cet ordinateur ; réessayez dans { $seconds } s
lab-setup-problems = le réglage pose des problèmes
lab-full = le labo est complet : réessayez quand une session se terminera
lab-stopped = le labo s’est arrêté
lab-superseded = un réglage plus récent a pris la place de celui-ci
browser-lab-stopped = le labo de ce navigateur s’est arrêté : { $why }
browser-lab-worker-failed = son processus (worker) a échoué
browser-lab-no-class = le tableau de la classe est celui d’un serveur de classe (frictionlab serve) : ce labo tourne dans un seul navigateur
serial-choose = le navigateur demandera lequel
serial-missing = Ce navigateur ne peut pas ouvrir le port série du dispositif (Web Serial existe dans Chrome, Edge et Opera sur ordinateur) : enregistrez le journal du dispositif (le moniteur série de l’Arduino, ou frictionlab log) et choisissez le fichier sous « Votre mesure »
serial-no-baud = le labo n’a donné aucun débit (bauds) pour le port du dispositif
serial-none-chosen = aucun port choisi : appuyez de nouveau sur Connecter et choisissez l’Arduino du dispositif
serial-not-opened = le port n’a pas pu être ouvert ({ $why }) : fermez le moniteur série de l’IDE Arduino ou toute autre page qui l’utilise, puis connectez-vous de nouveau
serial-chosen-port = le port série choisi

## Le compte rendu (frictionlab report, « Compte rendu » de la page) : lu par le laboratoire
## lui-même, chaque message ici est du texte simple, avec seulement des { $variable }.

## Les messages du laboratoire lui-même : ce qu’il refuse et pourquoi.

check-must-be-positive = doit être une valeur positive, trouvé { $value }
check-must-be-positive-in = doit être une valeur positive, trouvé { $value } { $unit }
check-length-must-be-positive = doit être une valeur positive, trouvé { $value } m ({ $value_mm } mm)
check-must-be-finite = doit être fini
check-implausible = attendu { $what } de { $least } à { $most }{ $unit } (le montage de l’article : { $paper }), trouvé { $value }{ $unit }
check-implausible-value = { $why } ; vérifiez la valeur et son unité (un nombre sans unité est en SI)
check-tilt = doit être compris entre -30 et 30 degrés, trouvé { $degrees } ° (un angle sans unité est en radians)
check-solver-iterations = doit être compris entre 1 et 10000, trouvé { $iterations }
check-step-resolves = attendu un pas qui résout l’oscillation, plus court qu’un quart de sa période ({ $quarter } s pour la plaque mince), trouvé { $step } s ; prenez un pas de 1 ms
check-duration-one-step = doit durer au moins un pas de world.time_step ({ $step } s), trouvé { $duration } s : une simulation sans pas ne mesure rien
check-duration-steps = demande { $steps } pas, plus de 10⁹ ; prenez un world.time_step plus grand ou une durée plus courte
check-speed-not-negative = doit être positive ou nulle, trouvé { $speed } rad/s
check-duty = doit être compris entre 0 % et 100 %, trouvé { $duty_percent } %
check-rollers-overlap = les rouleaux se chevauchent : l = { $spacing_mm } mm ne dépasse pas la somme de leurs rayons, { $radii_mm } mm
check-no-oscillation = aucune oscillation n’existe : l = { $spacing_mm } mm ≤ 2 μk h_c = { $limit_mm } mm (μk = { $mu_k }, h_c = { $h_c_mm } mm) ; écartez les rouleaux, abaissez le centre de masse de la plaque ou diminuez μk
check-plate-too-short = la plaque ({ $length_mm } mm) est plus courte que l + 2 × amplitude = { $needed_mm } mm : elle quitterait un rouleau ; prenez une plaque plus longue ou un décalage initial plus petit
check-drive-coupling = l’engrenage de l’entraînement (une roue de { $roller_teeth } dents sur chaque rouleau et deux roues intermédiaires de { $idler_teeth } dents) permet un entraxe de { $least_mm } à { $most_mm } mm, trouvé { $spacing_mm } mm ; choisissez un entraxe dans cet intervalle, ou d’autres roues dans drive.coupling
check-sensor-in-magnet-path = le capteur se trouve dans le volume que balaie l’aimant { $magnet } quand la plaque bouge ; placez-le au-dessus du haut de l’aimant, à { $top_mm } mm
check-magnetometer-in-plate-path = téléphone { $phone } : le magnétomètre en [{ $x_mm } ; { $y_mm } ; { $z_mm }] mm se trouve dans le volume que balaie la plaque ; posez le téléphone à côté du montage (|y| au-delà de { $half_width_mm } mm)
check-magnetometer-in-magnet-path = téléphone { $phone } : le magnétomètre se trouve dans le volume que balaie l’aimant { $magnet } quand la plaque bouge ; posez le téléphone à côté du montage
check-not-negative = doit être positif ou nul, trouvé { $value }
check-not-negative-in = doit être positif ou nul, trouvé { $value } { $unit }
check-angles-finite = doivent être des angles finis
check-ramp-time = point { $point } : son instant { $time } s doit être ≥ 0 et après celui du point précédent
check-ramp-value = point { $point } : sa valeur { $value }{ $unit } doit être comprise entre { $least } et { $most }
check-ramp-times-match = les points du rouleau 1 doivent être aux instants de ceux du rouleau 0
check-ramp-with-drive = l’entraînement fixe la vitesse des rouleaux ; faites plutôt varier drive.motor.duty_ramp
check-two-radii-drive = deux rayons ne vont qu’avec l’entraînement idéal (l’engrenage de l’entraînement est conçu pour une seule taille de rouleau) ; donnez un seul rayon ou retirez l’entraînement
check-skew = doit être compris entre -10 et 10 degrés (des axes aussi loin d’être parallèles ne sont pas un défaut d’alignement d’un banc), trouvé { $degrees } degrés
check-rolling-resistance = doit être ≥ 0 et inférieur à la moitié du rayon du rouleau ({ $half_radius_mm } mm) : un centre de pression aussi loin devant le sommet n’est celui d’aucun rouleau, trouvé { $found_mm } mm
check-runout = doit être ≥ 0 et inférieur à la moitié du rayon du rouleau ({ $half_radius_mm } mm), trouvé { $found_mm } mm
check-warming-room = doit être plus chaude que les rouleaux au départ (friction.temperature, { $start_k } K), trouvé { $room_k } K
check-speed-1-not-negative = la vitesse du rouleau 1 doit être positive ou nulle, trouvé { $speed } rad/s
check-two-speeds-drive = deux vitesses [rouleau 0, rouleau 1] sont celles de l’entraînement idéal : un entraînement fait tourner les deux rouleaux par ses engrenages à une seule vitesse ; retirez l’entraînement ou donnez une seule vitesse
check-two-speeds-ramp = deux vitesses vont avec une vitesse constante, pas avec rollers.speed_ramp ; donnez-en une
check-payload-on-plate = doit se trouver sur la plaque, à moins d’une demi-longueur ({ $half_length_mm } mm) de son milieu, trouvé { $x_mm } mm
check-mu-k-positive = μk doit être positif, trouvé { $mu_k }
check-mu-s-at-least-mu-k = la limite statique μs doit être au moins μk = { $mu_k }, trouvé { $mu_s }
check-stribeck-v-s = une loi de Stribeck avec μs > μk demande friction.v_s, la vitesse sur laquelle le frottement passe de μs à μk (par exemple 10 mm/s)
check-beta-finite = β doit être fini, trouvé { $beta }
check-mu-negative = le μ(s) de la loi devient négatif ({ $mu_min } à la plus grande vitesse de glissement de la simulation, { $slip_speed } m/s) ; prenez un |β| plus petit ou un μk plus grand
check-magnet-size = aimant { $magnet } : diamètre, épaisseur et masse volumique doivent être positifs
check-magnet-remanence = aimant { $magnet } : la rémanence doit être non nulle
check-magnet-on-plate = l’aimant { $magnet } en x = { $x_mm } mm n’est pas sur la plaque (demi-longueur { $half_length_mm } mm)
check-axis-non-zero = doit être un vecteur non nul
check-adc-bits = doit être compris entre 1 et 16, trouvé { $bits }
check-jitter = doit être ≥ 0 et inférieur au quart de l’intervalle d’échantillonnage
check-clock-error = doit rester dans ±10 % (un résonateur s’écarte de 0,5 % au plus), trouvé { $error }
check-sensor-offset = doit être compris entre 0 V et la tension d’alimentation
check-sensor-above = le capteur doit être au-dessus du sommet des rouleaux (z > 0)
check-phone-rate = téléphone { $phone } : la fréquence doit être comprise entre 1 Hz et 10 kHz (phyphox enregistre à 50 à 500 Hz), trouvé { $rate } Hz
check-phone-noise = téléphone { $phone } : le bruit doit être positif ou nul, trouvé { $noise }
check-phone-turn = téléphone { $phone } : la rotation doit être finie
check-phone-earth-field = téléphone { $phone } : le champ terrestre doit être fini et d’au plus 1 mT (il vaut 25 à 65 µT), trouvé { $field_ut } µT
check-phone-position = téléphone { $phone } : la position doit être finie
check-phone-mass = téléphone { $phone } : la masse doit être positive, trouvé { $mass_kg } kg
check-phone-size = téléphone { $phone } : la taille (largeur, longueur, épaisseur) doit être positive
check-phone-height = téléphone { $phone } : la hauteur doit être positive ou nulle, trouvé { $height_mm } mm
check-phone-on-plate = téléphone { $phone } : x = { $x_mm } mm met le centre du téléphone hors de la plaque (demi-longueur { $half_length_mm } mm)
reading-expected = un en-tête nommant les colonnes du temps et du CAN (par exemple « t_us,adc », « t_s,adc » ou « time,value ») ou des lignes d’échantillons
reading-empty = l’enregistrement est vide : attendu { $expected }
reading-only-comments = l’enregistrement n’a que des lignes de commentaire : attendu { $expected }
reading-no-sample-line = aucune des { $lines } lignes de l’enregistrement n’est un en-tête ou un échantillon : attendu { $expected }, trouvé des lignes comme { $example }
reading-tried-one = { $problem } ; essayé { $tried } : cela ne donne aucune période d’un montage ; est-ce bien l’enregistrement du capteur à effet Hall du montage, capturé en entier ?
reading-tried = { $problem } ; essayé { $tried } : aucun ne donne une période d’un montage ; est-ce bien l’enregistrement du capteur à effet Hall du montage, capturé en entier ?
reading-no-samples-timed = aucun échantillon après l’en-tête : attendu des lignes de valeurs de { $time } et de { $value }
reading-no-samples = aucun échantillon après l’en-tête : attendu des lignes de valeurs de { $value }
estimate-no-pulse = aucune impulsion dans { $samples } échantillons sur { $duration_s } s (lignes { $first_line } à { $last_line }) : les valeurs du CAN restent entre { $low } et { $high } points ; { $why }
estimate-swing-too-small = une variation de { $swing } points est sous les { $needed } points qu’il faut à une impulsion : l’aimant passe-t-il devant le capteur ?
estimate-not-learned = le signal varie de { $swing } points, mais l’estimateur apprend la ligne de base et la polarité des deux premières impulsions et n’en a pas vu deux (entre les impulsions, le signal doit rester à sa ligne de base plus de la moitié du temps)
estimate-no-timing-level = le signal varie de { $swing } points, mais aucune impulsion n’a franchi le niveau de chronométrage
estimate-one-pulse = une seule impulsion en { $duration_s } s d’enregistrement (à t = { $at_s } s, après les deux dont le signal a été appris) : une période en demande au moins deux
estimate-few-pulses = seulement { $pulses } impulsions (intervalles { $intervals } s) : l’estimateur en demande cinq à la suite pour distinguer une impulsion par période d’une paire ; enregistrez plus de périodes
estimate-no-turning-points = { $pulses } impulsions, mais pas deux points de rebroussement : les intervalles entre impulsions ({ $intervals } s) ne correspondent ni à une impulsion par période (intervalles égaux) ni à une paire rapprochée par période (court et long en alternance, le court sous 0,6 fois le long) ; { $advice }
estimate-pulses-alternate = ils alternent court et long : deux impulsions par période (l’aimant passe devant le capteur à l’aller et au retour, capteur en deçà du point de rebroussement ou près du milieu de la course), une paire trop large pour être reconnue seule : indiquez { $geometry }
estimate-pulses-irregular = ils sont irréguliers (impulsions parasites, plaque qui saute, signal faible ou bruité) : { $plot } les montre
estimate-counts-one = { $pulses } impulsions ont donné { $periods } période, { $accepted } acceptée et { $discarded } écartée
estimate-counts =
    { $pulses } impulsions ont donné { $periods } périodes, { $accepted } { $accepted ->
        [one] acceptée
       *[other] acceptées
    } et { $discarded } { $discarded ->
        [one] écartée
       *[other] écartées
    }
estimate-look = { $plot } montre les impulsions et pourquoi chaque période a été écartée
estimate-more-discarded-none = { $counts } : plus d’écartées que d’acceptées, donc les impulsions ne gardent aucune période stable (l’estimateur d’un montage n’écarte une période qu’à une impulsion manquante, parasite ou déformée, et en accepte une à { $tolerance_percent } % de la médiane glissante, où tombent aussi de temps en temps des intervalles au hasard) ; aucune T n’est calculée : est-ce l’enregistrement du capteur à effet Hall, d’une plaque qui oscille ? Une plaque qui saute plus souvent qu’à son tour demande un montage plus stable ; { $look }
estimate-more-discarded = { $counts } : plus d’écartées que d’acceptées, donc les impulsions ne gardent aucune période stable (l’estimateur d’un montage n’écarte une période qu’à une impulsion manquante, parasite ou déformée, et en accepte une à { $tolerance_percent } % de la médiane glissante, où tombent aussi de temps en temps des intervalles au hasard) ; aucune T n’est calculée à partir des { $accepted } acceptées : est-ce l’enregistrement du capteur à effet Hall, d’une plaque qui oscille ? Une plaque qui saute plus souvent qu’à son tour demande un montage plus stable ; { $look }
estimate-too-few-accepted = { $counts } : T ± ΔT demande au moins { $least } périodes acceptées (l’article en moyennait 10 à 100) ; enregistrez plus longtemps
estimate-scatter = { $counts } : les périodes acceptées se dispersent de ΔT/T = { $scatter_percent } % (ΔT = { $spread_s } s autour de T = { $period_s } s), au-delà des { $most_percent } % de tout montage (les périodes de l’article : 0,5 à 8 %) : des périodes étalées sur toute la fenêtre de ±{ $tolerance_percent } % de l’estimateur ne sont celles d’aucune oscillation ; est-ce l’enregistrement du capteur à effet Hall ? { $look }
estimate-no-rig = T = { $period_s } s et μk = { $mu_k } ne sont ceux d’aucun montage ({ $why }) ; rien n’en est calculé
table-too-many-fields = attendu au plus { $named } champs, comme l’en-tête en nomme, trouvé { $found }
table-not-a-number = attendu un nombre dans la colonne « { $column } », trouvé « { $found } »
table-no-header = attendu un en-tête dont la première colonne nomme un temps (« t », « Time (s) »), trouvé aucun
reading-not-periodic = attendu un mouvement périodique, trouvé aucun dans { $column } de l’enregistrement ({ $instrument }) : sa fréquence la plus forte, { $frequency_hz } Hz (une période de { $period_s } s), se tient { $ratio } fois au-dessus de la médiane de son spectre, quand celle d’une plaque qui oscille s’y tient { $least_ratio } fois ou plus ; son bruit vaut { $noise } et il varie de { $swing } (dans l’unité de cette colonne). Est-ce un enregistrement du montage qui oscille, et non d’un téléphone posé immobile ou d’une autre expérience ?
column-named = « { $name } »
column-field-magnitude = |B|
column-plate-position = la position de la plaque ({ $unit })
# Ce qui a produit le fichier d’une mesure.
instrument-hall-sensor = capteur à effet Hall
instrument-phyphox-magnetometer = magnétomètre phyphox
instrument-phyphox-accelerometer = accéléromètre phyphox
instrument-phyphox-linear-accelerometer = accéléromètre phyphox (sans g)
instrument-tracker = Tracker
instrument-position-table = tableau position-temps
instrument-phyphox-location = localisation phyphox (GPS)
instrument-phyphox-audio = audio phyphox
instrument-phyphox-other = capteur phyphox d’un autre type
instrument-phyphox-export = export phyphox (zip)
instrument-excel = classeur Excel (.xlsx)
instrument-zip = archive zip
instrument-video = vidéo
# Le port série du montage.
port-not-there = ce port série n’existe pas (la carte est-elle branchée ? ls /dev/ttyACM* /dev/ttyUSB*)
port-not-allowed = l’utilisateur de cet ordinateur n’a pas le droit d’ouvrir le port série (ajoutez-vous au groupe dialout, puis reconnectez-vous)
port-busy = un autre programme a ouvert le port série : fermez le moniteur série
port-failed = impossible d’ouvrir { $port } : { $why }
port-log-full = l’enregistrement a atteint ses { $megabytes } Mo (environ { $minutes } minutes au 1 kHz du micrologiciel) : le port est fermé et l’enregistrement gardé ; reconnectez-vous pour en commencer un nouveau
port-unplugged = { $port } a disparu à { $time } (carte débranchée ?) : les { $lines } lignes reçues sont gardées, téléchargez-les ci-dessous ; rebranchez la carte et reconnectez-vous
# Les refus du serveur de la classe.
server-no-session = cette session n’existe pas (elle est finie ou n’a jamais commencé)
server-full = le labo est plein : il fait tourner { $sessions } sessions à la fois, sa limite ; réessayez quand l’une d’elles finit
server-reading-files = le labo lit les fichiers d’autres élèves : renvoyez le vôtre dans quelques secondes
server-too-many = trop de requêtes de { $address } : au plus { $per_second } par seconde ; attendez { $wait_s } s
quantity-spacing = l’entraxe des rouleaux l
quantity-mu-k = μk
quantity-h-c = la hauteur du centre de masse h_c
quantity-period = la période T
quantity-amplitude = l’amplitude A
quantity-gravity = la pesanteur g
quantity-roller-speed = la vitesse des rouleaux
quantity-roller-radius = le rayon des rouleaux
paper-spacing = 89 mm
paper-mu-k = 0,2 à 10
paper-h-c = quelques mm
paper-period = 0,3 à 1 s
paper-amplitude = 20 mm
paper-gravity = 9,81 m/s²
paper-roller-speed = 1600 tr/min
paper-roller-radius = 10 mm

report-title = Compte rendu : l’oscillateur à frottement
report-decimal-sign = ,
report-method = Méthode
report-method-text = Une plaque repose sur deux rouleaux distants de l, qui tournent en sens opposés, le haut de chacun vers l’autre. Le frottement cinétique à chaque contact vaut μk fois la part du poids de la plaque que porte le rouleau, et le rouleau le plus proche en porte davantage : la différence ramène la plaque vers le milieu avec une force proportionnelle à son décalage. La plaque oscille avec la période T = π √(2 l / (μk g)) ; une période mesurée donne donc μk = 2π² l / (g T²) ({ $citation }). Un capteur à effet Hall détecte les aimants aux extrémités de la plaque ; l’estimateur du montage chronomètre ses impulsions, garde chaque période à moins de 20 % de la médiane glissante, et en fait la moyenne.
report-simulation-title = Simulation : { $name }
report-measurement-title = Mesure : { $name }
report-set-up = Montage
report-data = Données
report-result = Résultat
report-periods = Les périodes
report-comparison = Comparaison
report-stopwatch = Chronométré à la main
report-setup-scene = scène
report-setup-spacing = entraxe des rouleaux l
report-setup-speed = vitesse des rouleaux
report-setup-plate = plaque
report-setup-mu-k-set = μk fixé dans la simulation
report-setup-h-c = hauteur du centre de masse de la plaque au-dessus des contacts, h_c
report-setup-mass = masse de la plaque
report-setup-duration = durée simulée
report-setup-time-step = pas de temps
report-setup-seed = graine (le bruit du capteur)
report-setup-instrument = instrument
report-setup-file = fichier
report-setup-gravity = g
report-setup-samples = échantillons, leur durée et leur fréquence
report-axis-time = t (s)
report-axis-position = x (mm)
report-axis-hall = capteur à effet Hall (points du CAN)
report-axis-start = début de la période (s)
report-axis-period = T (s)
report-position-caption = La position de la plaque x(t), sur toute la simulation (sa trajectoire).
report-hall-caption = Le signal du capteur à effet Hall, tel que l’Arduino du montage le lit : une impulsion à chaque passage d’un aimant au-dessus du capteur.
report-measurement-caption = La mesure, telle que lue : la voie que l’estimateur a chronométrée.
report-periods-plot = Chaque période selon son début
report-periods-caption = Chaque période à son début : la dispersion des périodes retenues est leur écart-type.
report-accepted = retenue
report-discarded = rejetée
report-no-period = L’estimateur n’a trouvé aucune période.
report-column-start = début (s)
report-column-end = fin (s)
report-column-accepted = retenue
report-yes = oui
report-no-beyond-median = non : à plus de 20 % de la médiane glissante
report-no-spread = pas de dispersion : une seule période
report-period-why = T est la moyenne des { $count } périodes retenues ; dT est leur erreur-type (leur écart-type, { $sd } s, divisé par la racine carrée de leur nombre).
report-mu-k-why = μk = 2π² l / (g T²), avec l = { $spacing } mm et g = { $gravity } m/s². Son incertitude combine en quadrature celle de l’entraxe, dl / l avec dl = { $dl } mm, et celle de la période, 2 σT / T où σT est l’écart-type des périodes, comme le calcule l’Arduino du montage ; additionnées au lieu d’être combinées, elles donnent ± { $worst }.
report-regime = Régime : { $regime }.
report-regime-oscillates = oscille
report-regime-clipped = écrêté
report-regime-stick-slip = adhérence-glissement
report-regime-grows = croît
report-regime-decays = décroît
report-regime-sticks = reste collée
report-regime-tips = bascule ou décolle d’un rouleau
report-regime-no-restoring-force = pas de force de rappel
report-regime-lost = perdue (hors du montage)
report-regime-numerically-failed = échec numérique
report-source = source
report-theory-row = Théorie pour le μk fixé, { $mu } : plaque mince, π √(2 l / (μk g)) ; avec l’épaisseur de la plaque
report-thick-row = { $name } : μk tiré de T par la formule de la plaque épaisse, 2π² l / (g T² + 4π² h_c), avec h_c la hauteur du centre de masse de la plaque au-dessus des contacts
report-paper-row = Tableau I de l’article : { $material }, { $kelvin } K
report-no-paper-row = Le tableau I de l’article n’a pas de ligne pour ce matériau à cette température.
report-column-periods = périodes
report-column-wall = temps réel (s)
report-column-simulated = temps simulé (s)
report-column-by-hand = T à la main (s)
report-stopwatch-why = Un appui sur le chronomètre est en avance ou en retard d’un temps de réaction, environ 0,2 s : sur dix périodes, cela fait 0,02 s sur T.
report-footer = Réalisé avec { $version } : la simulation et l’estimateur du code Arduino du montage ; la méthode de { $citation }.
