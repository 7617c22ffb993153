# Les messages de frictionlab en français : ceux de la page et du compte rendu.

language-name = Français

## Le compte rendu (frictionlab report, « Compte rendu » de la page) : lu par le laboratoire
## lui-même, chaque message ici est du texte simple, avec seulement des { $variable }.

report-title = Compte rendu : l'oscillateur à frottement
report-decimal-sign = ,
report-method = Méthode
report-method-text = Une plaque repose sur deux rouleaux distants de l, qui tournent en sens opposés, le haut de chacun vers l'autre. Le frottement cinétique à chaque contact vaut μk fois la part du poids de la plaque que porte le rouleau, et le rouleau le plus proche en porte davantage : la différence ramène la plaque vers le milieu avec une force proportionnelle à son décalage. La plaque oscille avec la période T = π √(2 l / (μk g)) ; une période mesurée donne donc μk = 2π² l / (g T²) ({ $citation }). Un capteur à effet Hall détecte les aimants aux extrémités de la plaque ; l'estimateur du montage chronomètre ses impulsions, garde chaque période à moins de 20 % de la médiane glissante, et en fait la moyenne.
report-simulation-title = Simulation : { $name }
report-measurement-title = Mesure : { $name }
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
report-hall-caption = Le signal du capteur à effet Hall, tel que l'Arduino du montage le lit : une impulsion à chaque passage d'un aimant au-dessus du capteur.
report-measurement-caption = La mesure, telle que lue : la voie que l'estimateur a chronométrée.
report-periods-plot = Chaque période selon son début
report-periods-caption = Chaque période à son début : la dispersion des périodes retenues est leur écart-type.
report-accepted = retenue
report-discarded = écartée
report-no-period = L'estimateur n'a trouvé aucune période.
report-column-start = début (s)
report-column-end = fin (s)
report-column-accepted = retenue
report-yes = oui
report-no-beyond-median = non : à plus de 20 % de la médiane glissante
report-no-spread = pas de dispersion : une seule période
report-period-why = T est la moyenne des { $count } périodes retenues ; dT est leur erreur-type (leur écart-type, { $sd } s, divisé par la racine carrée de leur nombre).
report-mu-k-why = μk = 2π² l / (g T²), avec l = { $spacing } mm et g = { $gravity } m/s². Son incertitude combine en quadrature celle de l'entraxe, dl / l avec dl = { $dl } mm, et celle de la période, 2 σT / T où σT est l'écart-type des périodes, comme le calcule l'Arduino du montage ; additionnées au lieu d'être combinées, elles donnent ± { $worst }.
report-regime = Régime : { $regime }.
report-regime-oscillates = oscille
report-regime-clipped = écrêté
report-regime-stick-slip = adhérence-glissement
report-regime-grows = croît
report-regime-decays = décroît
report-regime-sticks = reste collée
report-regime-tips = bascule ou décolle d'un rouleau
report-regime-no-restoring-force = pas de force de rappel
report-regime-lost = perdue (hors du montage)
report-regime-numerically-failed = échec numérique
report-source = source
report-theory-row = Théorie pour le μk fixé, { $mu } : plaque mince, π √(2 l / (μk g)) ; avec l'épaisseur de la plaque
report-thick-row = { $name } : μk tiré de T par la formule de la plaque épaisse, 2π² l / (g T² + 4π² h_c), avec h_c la hauteur du centre de masse de la plaque au-dessus des contacts
report-paper-row = Tableau I de l'article : { $material }, { $kelvin } K
report-no-paper-row = Le tableau I de l'article n'a pas de ligne pour ce matériau à cette température.
report-column-periods = périodes
report-column-wall = temps réel (s)
report-column-simulated = temps simulé (s)
report-column-by-hand = T à la main (s)
report-stopwatch-why = Un appui sur le chronomètre est en avance ou en retard d'un temps de réaction, environ 0,2 s : sur dix périodes, cela fait 0,02 s sur T.
report-footer = Réalisé avec { $version } : la simulation et l'estimateur du code Arduino du montage ; la méthode de { $citation }.
