# Les libellés, boutons, notes et messages de la page, selon la partie de la page qui les affiche.
# Les nombres arrivent dans des variables, déjà écrits à la manière de la langue. Une variable nommée
# $reason, $warning, $description ou $label contient les mots du cœur de simulation, en anglais pour
# l’instant ; un scénario ($scenario), la clé d’un champ ($key), le nom d’un préréglage ($preset) ou
# une commande s’écrivent tels quels et ne se traduisent jamais.

## L’en-tête

page-title = IM Lab : commande sans capteur de vitesse du moteur asynchrone
page-name = IM Lab
page-skip-link = Aller aux tracés
page-intro = Commande sans capteur de vitesse du moteur asynchrone : observateur EKF et correcteur par backstepping en quatre étapes (Zhang, Wang, Bortoff et al., 2015), simulés à 20 kHz dans votre navigateur.
help-links =
    .aria-label = À propos / Aide
help-links-intro = À propos / Aide :
help-student-guide = Guide de l’étudiant
help-lecturer-guide = Guide de l’enseignant
help-all-guides = Tous les guides
language-menu = Langue

## Le chargement des leçons

lessons-not-loaded = Les textes des leçons n’ont pas pu être chargés : { $reason }. Rouvrez l’onglet Leçons pour réessayer.

## Les boutons communs à plusieurs endroits

shared-cancel = Annuler
shared-csv = CSV

## La barre de simulation : le préréglage, Lancer, la ligne d’état et les liens

run-preset = Préréglage
run-button = Lancer
run-settings = Réglages
run-unrun = Réglages modifiés, pas encore simulés : appuyez sur Lancer ou sur Entrée. L’adresse et « Copier le lien » décrivent la simulation affichée.
share-copy-link = Copier le lien
export-png = PNG
share-copy-embed = Intégrer
    .title = Copier un extrait iframe qui affiche les tracés visibles de l’onglet Trajectoires, pour ce scénario

## Les résultats : les onglets, la barre d’affichage et les indicateurs

results =
    .aria-label = Résultats
tabs =
    .aria-label = Vues
tab-plots = Trajectoires
tab-walkthrough = Parcours de conception
tab-lessons = Leçons
tab-analysis = Analyse
tab-challenge = Défi
present-button = Présentation
    .title = Texte et tracés plus grands pour un vidéoprojecteur ; les réglages passent dans un panneau escamotable
view-full-run = Simulation entière
    .title = Afficher toute la simulation sur chaque tracé (ou double-cliquer sur un tracé, ou Échap)
view-fit = Ajuster les axes y après le transitoire de démarrage
view-fit-from = Ajuster les axes y après le transitoire de démarrage (t ≥ { $ms } ms)
view-fit-why = Pourquoi cet instant ?
view-transient-reason = Transitoire de démarrage : { $reason }.
figures-all = Tous les indicateurs
figures-fewer = Moins d’indicateurs
figures-strip =
    .aria-label = Indicateurs de la simulation
plots-hint = Faites glisser la souris sur un tracé pour zoomer sur tous les tracés ; un double-clic, Échap ou « Simulation entière » revient à toute la simulation. La légende donne les valeurs enregistrées à l’échantillon sous le curseur ; cliquez sur un tracé pour inspecter chaque terme à cet instant.

## Les épingles et leur superposition (onglet Trajectoires)

pins-pin = Épingler cette simulation
pins-overlay = superposition
pins-column-omega = vitesse ω
pins-column-omega-hat = vitesse estimée ω̂
pins-column-flux = flux |φ|
pins-column-voltage = tension u_sa
pins-unpin = Désépingler
pins-item = épingle { $n } : { $legend }
pins-name = épingle { $n }
pins-current = actuelle
pins-difference = actuelle − épingle { $n }
pins-overlay-title = { $column } : simulation actuelle et simulations épinglées
pins-difference-title = { $column } : actuelle − épingle
pins-status-running = Simulation de l’épingle { $n } sur { $count } : { $percent } %
pins-status-done = Épinglage terminé
pins-status-cancelled = Épinglage annulé
pins-link-too-long = Les épingles de l’adresse n’ont pas été simulées : { $length } caractères, plus que les { $max } que peut contenir un fragment d’épingles.
pins-link-malformed = Épingle mal formée dans l’adresse, ignorée : { $pins }.
pins-link-dropped = Seules les { $sent } premières épingles de l’adresse ont été simulées ; les { $dropped } autres ont été laissées de côté.
pins-rejected-first = Impossible d’épingler { $scenario } : { $reason }
pins-rejected-next = impossible d’épingler { $scenario } : { $reason }
pins-rejected = { $list }.
pins-reason-unrun = non simulée : l’épinglage a été annulé
pins-reason-cancelled = annulée

## Les listes dans les messages

list-more = { $list } … et { $count } autres

## La ligne d’état de la simulation et ses messages

run-status-starting = Simulation de { $samples } échantillons…
run-status-progress = Simulation : { $done } échantillons sur { $total }
run-status-done = { $rows } échantillons en { $ms } ms
run-status-ran-away = Divergence : { $rows } échantillons en { $ms } ms
run-status-stopped = Arrêtée après { $rows } échantillons
run-status-cancelled = Annulée à { $percent } %
run-status-worker-failed = Arrêtée : le worker de simulation a échoué
run-stopped-early = La simulation s’est arrêtée prématurément : { $reason }. Les tracés montrent les { $rows } échantillons qui précèdent.
run-ran-away = { $warning } Les tracés montrent ce qu’a fait le moteur.
run-worker-not-started = Le worker de simulation n’a pas pu démarrer ({ $reason }). Rechargez la page pour réessayer.
run-worker-failed = Le worker de simulation a échoué ({ $reason }). Il a été redémarré ; appuyez sur Lancer pour réessayer.
run-worker-failed-pins = Le worker de simulation a échoué ({ $reason }). Il a été redémarré ; appuyez sur Lancer pour réessayer. Les simulations épinglées ont été abandonnées : { $pins }.
page-language-failed = La page n’a pas pu charger ses messages « { $language } » ({ $reason }) : elle s’affiche en anglais.
page-messages-failed = Le reste des textes de la page n’a pas pu être chargé ({ $reason }). Les outils, les leçons et le parcours en ont besoin : en utiliser un relance le chargement.
page-challenge-tools-failed = L’éditeur et la notation de l’onglet Défi n’ont pas pu être chargés : { $reason }. Rouvrez l’onglet pour réessayer.
page-lesson-map-failed = La carte de la leçon n’a pas été lue : { $reason }.
page-no-lesson = Aucune leçon nommée « { $lesson } ». Leçons : { $lessons }.
lesson-differences-refused = le cœur de simulation en a refusé certains ({ $reason })
lesson-differences-uncompared = ils n’ont pas pu lui être comparés

## Pourquoi le worker de simulation a échoué (le $reason des messages ci-dessus)

worker-unknown-error = erreur inconnue
worker-unreadable = un de ses messages n’a pas pu être lu
worker-crash-panic = { $error } ; panique Rust : { $panic }
worker-crash-memory = { $error } ; le cœur a très probablement manqué de mémoire
pool-worker-failed = un worker a échoué ({ $reason })
pool-worker-failed-restart = un worker a échoué ({ $reason }) ; la prochaine simulation en démarre un nouveau
worker-tools-not-loaded = Les outils n’ont pas pu être chargés ({ $reason }) : vérifiez la connexion et réessayez.
compare-failed = Échec de la comparaison : { $reason }
compare-running = Simulation avec les deux prédicteurs…

## Les exports

export-csv-starting = Export CSV…
export-csv-progress = Export CSV : { $rows } lignes sur { $total }
export-csv-done = CSV exporté : { $total } lignes
export-csv-cancelled = Export CSV annulé
export-csv-cancelled-by-run = L’export CSV a été annulé : une nouvelle simulation a démarré.
export-csv-stopped = Export CSV arrêté
export-csv-failed-status = Échec de l’export CSV
export-csv-failed = L’export CSV a échoué : { $reason }.
export-csv-gone = le worker ne détient plus cette simulation ; relancez-la
export-csv-refused = Le navigateur a refusé de conserver plus de { $megabytes } Mo de CSV ({ $error }). Exportez plutôt cette simulation en ligne de commande : { $command }
export-png-not-ready = Ces tracés sont encore en cours de dessin ; exportez-les dans un instant.

## Le partage

share-link-copied = Lien copié : il reproduit cette simulation bit pour bit.
share-copy-this-link = Copiez ce lien : { $link }
share-embed-title = IM Lab : { $preset }, { $plots }
share-embed-copied =
    Code d’intégration copié : { $count ->
        [one] le tracé
       *[other] les tracés
    } { $plots } de cette simulation (les tracés visibles de l’onglet Trajectoires). Collez-le dans une diapositive ou une page de cours.
share-embed-copy-this =
    Copiez ce code d’intégration pour { $count ->
        [one] le tracé
       *[other] les tracés
    } { $plots } de cette simulation (les tracés visibles de l’onglet Trajectoires) : { $code }
embed-unknown-plots = Aucun tracé nommé { $names } ; affichage de { $shown }. Tracés : { $plots }.

## Un résultat d’un scénario antérieur à celui des réglages ($scenario est ce scénario)


## La loi propre d’une étape (le formulaire des réglages et le parcours)

law-paper-default = Pas encore de loi propre : cette étape applique la v{ $step } de l’article.

## Le formulaire des réglages

settings-group-reference = Consigne
settings-group-controller = Correcteur : backstepping ou IFOC classique
settings-group-gains = Gains du backstepping
settings-group-observer = Observateur (EKF)
settings-group-noise = Bruit et graine
settings-group-plant = Moteur : la machine simulée
settings-group-model = Modèle : ce que supposent l’EKF et le correcteur
settings-group-load = Charge inconnue : un échelon ou un tableau de points
settings-group-limits = Limite de tension (carré), courant nominal, durée et pas de temps
settings-group-drive = Variateur : retard de calcul, limite de l’onduleur et PWM
settings-group-law = Vos propres lois pour les étapes du backstepping (vide : celles de l’article)
settings-allowed-formula = une formule des noms que liste « Écrire cette étape » dans le parcours ; vide : la loi de l’article
settings-allowed-range = { $min } { $op } { $key } ≤ { $max }
settings-allowed-table = jusqu’à { $points } points t:value, par exemple 0:0,0.1:100, instants croissants à partir de 0 ; valeurs de { $min } à { $max }
settings-allowed-whole = { $min } { $op } { $key } ≤ { $max }, nombre entier
settings-allowed = autorisé : { $values }
settings-link-rejected = Certains réglages de l’adresse ont été rejetés et laissés aux valeurs du préréglage : { $list }.
settings-link-refused = Le scénario de l’adresse a été rejeté : { $reason }. Affichage de { $preset } à la place.
settings-preset-changed = Préréglage { $preset } : { $description }. Cette simulation modifie { $fields } ; ce que la description du préréglage dit de sa simulation ne vaut donc pas forcément pour celle-ci.
settings-idle = { $changed } Réglages ignorés : { $idle }.
settings-idle-separator = {" ; "}

## Le bandeau des indicateurs et les indicateurs clés

figures-to-rated = { $value } ({ $ratio }× le courant nominal de { $rated } A)
figures-nis-inside = { $value } (bande à 95 % { $low }–{ $high } : à l’intérieur)
figures-nis-outside = { $value } (bande à 95 % { $low }–{ $high } : à l’extérieur)
figures-exact = valeur exacte : { $value } ; { $window }
figures-no-value = pas de valeur : { $reason } ; { $window }
figures-trend-settled = établie à la fin de la simulation
figures-trend-ran-away = la simulation a divergé : pas une valeur finale
figures-trend-drifting = dérive avec l’estimée en marche aléatoire que l’EKF fait de la charge ou de R_r : une simulation plus longue finit ailleurs
figures-trend-fluctuating = fluctue de ±{ $scatter } : le dernier échantillon n’est pas une valeur finale
figures-trend-changing = évolue encore : { $rate } par s à la fin ; simulez plus longtemps
figures-trend-changing-to-go = évolue encore : { $rate } par s à la fin ; simulez plus longtemps (il reste environ { $to-go })
figures-trend-fit = droite ajustée sur les { $ms } dernières ms : { $rate } par s, les échantillons dispersés de { $scatter } autour d’elle ; établie signifie que la droite se déplace de moins de { $tolerance } et que quatre fois la dispersion tient dans cette tolérance
figures-trend-fit-approach = droite ajustée sur les { $ms } dernières ms : { $rate } par s, les échantillons dispersés de { $scatter } autour d’elle ; les moyennes des trois derniers dixièmes tendent vers une valeur encore distante de { $to-go } ; établie signifie que la droite se déplace de moins de { $tolerance } et que quatre fois la dispersion tient dans cette tolérance
figures-key-peak = |i_s| crête { $value } ({ $ratio }× le nominal)
figures-key-final =
    erreur finale ω − ω_d { $value } ({ $trend ->
        [settled] établie
        [changing] évolue encore
        [drifting] dérive
        [fluctuating] fluctue
       *[ran-away] divergé
    })
figures-key-nis-inside = NIS moyen { $value } (dans sa bande à 95 %)
figures-key-nis-outside = NIS moyen { $value } (hors de sa bande à 95 %)
figures-caption = Indicateurs de cette simulation : { $figures }.

## Les tracés

plot-speed = Vitesse du rotor
plot-speed-reference = consigne ω_d
plot-speed-estimated = ω̂ estimé
plot-speed-true = ω réel
plot-speed-error = Erreur de poursuite en vitesse ω − ω_d
plot-flux = Module du flux rotorique
plot-flux-target = cible √ψ_d
plot-flux-estimated = |φ̂| estimé
plot-flux-true = |φ| réel
plot-current = Courants statoriques
plot-current-a-estimated = î_sa estimé
plot-current-b-estimated = î_sb estimé
plot-current-a-true = i_sa réel
plot-current-b-true = i_sb réel
plot-voltage = Tensions statoriques appliquées (après la limite)
plot-voltage-limit-high = +limite
plot-voltage-limit-low = −limite
plot-z13 = Erreurs de poursuite
plot-z13-flux = z3 = |φ̂|² − ψ_d (Wb², à droite)
plot-z24 = Erreurs de commande virtuelle
plot-z24-torque = z2 erreur de couple (rad/s²)
plot-z24-flux = z4 erreur de dérivée du flux (Wb²/s, à droite)
plot-est = Erreurs d’estimation
plot-est-flux = |φ| − |φ̂| (Wb, à droite)
plot-not-driving = { $title } (calculé à titre de comparaison ; ne pilote pas le moteur)
plot-caption = { $title }, en { $unit } en fonction du temps t en s. Signaux : { $signals }.
plot-caption-two-axes = { $title }, en { $unit } (à gauche) et en { $unit2 } (à droite) en fonction du temps t en s. Signaux : { $signals }.
plot-caption-keys = Sélectionnez le tracé et parcourez la simulation échantillon par échantillon avec les touches fléchées (Maj : 1 % de la fenêtre).

## L’onglet Analyse


## L’onglet Leçons


## L’onglet Défi


## The challenge panel's controls, built with the page

challenge-progress =
    .aria-label = Simulations du défi effectuées
challenge-cancel = Annuler la vérification
challenge-copy = Copier le lien de soumission
challenge-open-failed = Le défi n’a pas pu être ouvert : { $reason }. La page affiche à la place le scénario par défaut.
law-checking = Vérification de votre loi par rapport à la dynamique voulue…
law-verdict-failed = Le verdict sur votre loi n’a pas pu être calculé : { $reason }
walkthrough-load-failed = Le parcours n’a pas pu être chargé : vérifiez la connexion et rechargez la page.
lesson-panel =
    .aria-label = Leçon
challenge-panel =
    .aria-label = Défi
stale-back = Revenir à son scénario
