# Les mots des outils d’analyse et des défis : l’onglet Analyse (balayages, bandes sur les graines,
# carte d’erreur de modèle), le panneau de défi que voit l’étudiant et l’onglet Défi de
# l’enseignant (l’éditeur, sa vérification, la notation d’une classe).

## Balayage en fréquence : les diagrammes de Bode et le tableau (web/analysis/analysis.js)

sweep-plot-magnitude = Module de ω/ω_d
sweep-plot-phase = Phase de ω par rapport à ω_d
sweep-axis-degrees = degrés
sweep-series-unsettled = { $variant }, non établi
sweep-unsettled =
    { $count ->
        [one] { $count } point ne s’était pas établi (marqueurs creux) : la bande passante et la phase à 200 Hz n’y sont jamais lues. Des simulations plus longues peuvent l’établir.
       *[other] { $count } points ne s’étaient pas établis (marqueurs creux) : la bande passante et la phase à 200 Hz n’y sont jamais lues. Des simulations plus longues peuvent les établir.
    }
sweep-unsettled-point = { $variant }, { $frequency } : { $reason }
sweep-hz = { $value } Hz
sweep-degrees = { $value } °
sweep-head-variant = variante
sweep-head-bandwidth = bande passante à −3 dB
sweep-head-phase = phase à 200 Hz
sweep-head-saturation = pire saturation
sweep-head-failed = points en échec
sweep-head-unsettled = points non établis
sweep-head-peak = |i_s| crête (A)
sweep-bandwidth-unsettled = non donnée : elle reposerait sur un point non établi
sweep-bandwidth-below = sous la fréquence la plus basse
sweep-not-reached = non atteinte dans la grille
sweep-phase-not-reached-settled = non atteinte par les points établis
sweep-unsettled-cell = { $count } : { $frequencies }
sweep-peak-none = aucun mesuré
sweep-peak = { $peak } (nominal { $rated })
sweep-peak-over = { $peak } (nominal { $rated }) ; au-delà du courant nominal en { $count } points : { $frequencies }

## Bandes sur les graines : les tracés (web/analysis/analysis.js)

seeds-plot-error = Erreur de vitesse ω − ω_d sur les graines (moyenne, min, max)
seeds-plot-estimate = Erreur d’estimation ω − ω̂ sur les graines (moyenne, min, max)
seeds-series-mean = moyenne
seeds-series-min = min
seeds-series-max = max

## Balayage en fréquence : lancement, ligne d’état et lien (web/analysis/sweeps.js)

sweep-workers-invalid = workers = { $value } : un nombre entier de 1 à 8 est attendu.
sweep-status-checking = Vérification du balayage…
sweep-refused = { $reason }.
sweep-not-run = Le balayage n’a pas été lancé : les réglages ne sont pas valides ou pas autorisés ici ; le message en haut de la page en donne la raison.
sweep-status-running = Balayage en cours…
sweep-status-done =
    { $workers ->
        [one] { $variants } × { $points } simulations en { $ms } ms sur { $workers } worker.
       *[other] { $variants } × { $points } simulations en { $ms } ms sur { $workers } workers.
    }
sweep-status-cancelled = Balayage annulé.
sweep-status-failed = Échec du balayage : { $reason }
sweep-link-refused = Le balayage de l’adresse ({ $link }) n’a pas été lancé : { $reason }.

## Graines : lancement et ligne d’état (web/analysis/seeds.js)

seeds-count-invalid = seeds = { $value } : le nombre de graines doit être un entier de 1 à 1000.
seeds-not-run = Les graines n’ont pas été lancées : les réglages ne sont pas valides ou pas autorisés ici ; le message en haut de la page en donne la raison.
seeds-status-starting = Lancement des graines…
seeds-status-running = Graines en cours : { $percent } %
seeds-status-done = { $runs } graines sur { $seeds } ({ $first } à { $last }) menées à terme.
seeds-status-cancelled = Simulations des graines annulées.
seeds-status-failed = Échec du balayage des graines : { $reason }

## Carte d’erreur de modèle : lancement et ligne d’état (web/analysis/robust.js)

map-status-starting = Calcul de { $cells } cases × { $seeds } graines…
map-status-running = Calcul de la carte : { $done } simulations sur { $total }.
map-refused = La carte n’a pas été calculée : { $reason }.
map-not-run = La carte n’a pas été calculée : les réglages ne sont pas valides ou pas autorisés ici ; le message en haut de la page en donne la raison.
map-failed = Échec de la carte : { $reason }
map-status-cancelled = Carte annulée : { $finished } cases sur { $cells } sont terminées et affichées ; les autres n’ont pas été calculées.
map-status-done = { $cells } cases × { $seeds } graines ({ $first }–{ $last }) en { $seconds } s.
map-link-refused = La carte de l’adresse ({ $link }) n’a pas été calculée : { $reason }.

## Carte d’erreur de modèle : le tracé selon un axe (web/analysis/map-plot.js)

map-plot-title = { $figure } sur les graines : médiane et bande min–max
map-series-min = min
map-series-median = médiane
map-series-max = max
map-gap = { $value } ({ $ranAway } graines sur { $runs })
map-gap-percent = { $value } % ({ $ranAway } graines sur { $runs })
map-gaps = Non tracé, parce que des graines y ont divergé : { $cells }.

## Carte d’erreur de modèle : le tableau et sa légende (web/analysis/map-table.js, map-colours.js)

map-figure-unit = { $figure } ({ $unit })
map-cell-not-run = non calculée
map-cell-title = { $scenario } : { $ranAway } graines sur { $runs } ont divergé, { $inconsistent } avec un EKF incohérent, { $overRating } au-delà du courant nominal, { $unsettled } avec l’erreur de vitesse non établie à la fin ; { $figure } de { $min } à { $max }
map-grid-corner = { $rows } ↓ / { $columns } →
map-head-median = médiane
map-head-range = min – max
map-range = { $min } – { $max }
map-key = { $figure }, médiane sur les graines qui n’ont pas divergé ({ $seeds } graines) ; couleur : { $colours }. ✕ k/N : la simulation a divergé sur k des N graines (sa propre page le signale, ou elle a divergé numériquement), jamais colorée comme une valeur ; ⚠ l’EKF était incohérent ; I↑ k/H : sur les H graines qui ont tenu, k ont appelé plus que le courant nominal du moteur après le démarrage ; ~ k/H : k ont fini avec l’erreur de vitesse non établie (les deux sont entourées, et colorées selon leur médiane). Cliquez sur une case pour la simuler (graine { $seed }).
map-scale-diverging = du bleu (−{ $max }) au rouge ({ $max }) en passant par le blanc (0)
map-scale-log = échelle logarithmique, du clair ({ $min }) au foncé ({ $max })
map-scale-linear = échelle linéaire, du clair ({ $min }) au foncé ({ $max })
map-scale-none = aucune

## Panneau de défi : ce que voit l’étudiant d’un lien de défi (web/challenge/challenge.js)

challenge-heading = Défi
challenge-link-rejected = Ce lien de défi a été rejeté : { $reason }. La page affiche à la place le scénario par défaut.
challenge-submission-another = Ce lien de soumission appartient à un autre défi (sa partie défi a été modifiée) : il n’a pas été noté.
challenge-submission-refused = Ce lien de soumission a été refusé : { $reason }. Il n’a pas été noté ; l’exercice part de ses réglages de base.
challenge-submission-rejected = Ce lien de soumission a été rejeté : { $reason }. Il n’a pas été noté ; l’exercice part de ses réglages de base.
challenge-run = Lancer et vérifier
challenge-settings = Vos réglages
challenge-settings-hint = Seuls { $fields } peuvent être modifiés ; les autres réglages sont verrouillés par le défi.
challenge-checklist = Liste de contrôle
challenge-task = L’énoncé complet
challenge-verdict-pending = Pas encore vérifié : la première simulation est en cours de calcul.
challenge-need-pending = { $label } ({ $figure }) : pas encore vérifié
challenge-verdict-link-refused = ✗ Non noté : les réglages du lien ont été refusés (voir ci-dessus). Modifiez les réglages autorisés et lancez.
challenge-verdict-cancelled = ✗ Vérification annulée : non noté. Relancez pour vérifier.
challenge-verdict-failed = ✗ La vérification a échoué : { $reason }. Non noté.
challenge-verdict-edited = Ce n’est pas le défi intégré { $name } : ses conditions ont été modifiées.
challenge-verdict-rerun = La simulation affichée n’est pas celle qui a été notée (un réglage verrouillé diffère) : la simulation nominale a été relancée avec les réglages du défi et vos réglages autorisés.
challenge-checking =
    Vérification : { $done } / { $runs ->
        [one] { $runs } simulation
       *[other] { $runs } simulations
    } (la simulation nominale et { $variants ->
        [one] { $variants } variante
       *[other] { $variants } variantes
    })…
challenge-refusal-not-run = Vos réglages ne sont pas une réponse valide : { $reason }. Non lancé.
challenge-verdict-not-run = ✗ Non lancé. Vos réglages ne sont pas une réponse valide : { $reason }.
challenge-refusal-not-graded = Vos réglages ne sont pas une réponse valide : { $reason }. Non noté.
challenge-verdict-not-graded = ✗ Non noté. Vos réglages ne sont pas une réponse valide : { $reason }.
challenge-copied = Lien de soumission copié : il rejoue ces simulations bit pour bit.
challenge-copy-by-hand = Copiez ce lien de soumission : { $url }

## Panneau de défi : la liste de contrôle et ses commandes (web/challenge/checklist.js)

checklist-not-measured = non mesuré
checklist-never = jamais (∞)
checklist-value-unit = { $value } { $unit }
checklist-passed =
    { $criteria ->
        [one] ✓ Réussi : le critère est rempli.
       *[other] ✓ Réussi : les { $criteria } critères sont remplis.
    }
checklist-passed-variants =
    { $criteria ->
        [one] ✓ Réussi : le critère est rempli (la simulation nominale et { $variants ->
            [one] { $variants } variante
           *[other] { $variants } variantes
        }).
       *[other] ✓ Réussi : les { $criteria } critères sont remplis (la simulation nominale et { $variants ->
            [one] { $variants } variante
           *[other] { $variants } variantes
        }).
    }
checklist-failed = ✗ Non réussi : { $met } critères remplis sur { $criteria }.
checklist-failed-variants =
    ✗ Non réussi : { $met } critères remplis sur { $criteria } (la simulation nominale et { $variants ->
        [one] { $variants } variante
       *[other] { $variants } variantes
    }).
checklist-pass = ✓ réussi
checklist-fail = ✗ échoué
checklist-criterion = { $label } : { $value }, exigé { $bound }
checklist-criterion-worst = { $label } : { $value }, exigé { $bound } (pire simulation : { $run })
checklist-reason = — { $reason }

## Panneau de défi : les commandes des réglages autorisés (web/challenge/knobs.js)

challenge-knob-doc = { $doc } ({ $unit })
challenge-allowed-choice = autorisé : l’une des valeurs { $options }
challenge-allowed-formula = autorisé : une formule de votre choix ({ $unit } ; « Écrire cette étape » dans le parcours liste les noms)
challenge-allowed-range = autorisé : de { $lo } à { $hi }
challenge-allowed-range-unit = autorisé : de { $lo } à { $hi } { $unit }

## Panneau de défi : l’en-tête, d’où vient le défi (web/challenge/origin.js)

challenge-kind = Défi
challenge-origin-builtin = Défi intégré
challenge-origin-mine = Créé par vous dans ce navigateur : il a composé exactement ce défi (bornes et titre inchangés)
challenge-origin-other = Pas un défi que vous avez créé dans ce navigateur
challenge-origin-unknown = Ce navigateur ne garde aucune trace des défis qu’il a composés
challenge-fingerprint = Empreinte
challenge-edited = Modifié : ce lien porte le titre du défi intégré { $name }, mais pas ses conditions. Il est noté comme le défi qu’il est, et non comme { $name }.

## Les défis intégrés, dans l’onglet Leçons (web/challenge/builtins.js)

builtins-open = Ouvrir le défi { $name }
builtins-failed = Les défis intégrés n’ont pas pu être listés.

## Onglet Défi : composer un défi (web/challenge/challenge-compose.js)

compose-intro = Le défi part du scénario des réglages (sa base) ; l’étudiant ne peut modifier que les champs listés ici, dans leurs plages, et réussit lorsque chaque critère est rempli. Préparez d’abord le scénario et lancez-le : les critères sont préremplis d’après ses indicateurs, 20 % plus stricts que cette simulation.
compose-base = Base :
compose-title = Titre
compose-title-default = Défi sur le préréglage { $preset }
compose-make = Créer le lien du défi
compose-no-run = Aucune simulation terminée de ce scénario dont tirer les indicateurs : lancez-le, puis appuyez à nouveau sur « Remplir à partir du scénario actuel ».
compose-invalid = Le défi n’est pas valide : { $reason }
compose-link = Lien du défi
compose-kept = Ce navigateur garde une trace de la composition de ce défi : le lien, ouvert ici, affiche « Créé par vous dans ce navigateur » ; une copie avec une autre borne ou un autre titre, non.
compose-not-kept = Ce navigateur ne garde aucune trace des défis qu’il a composés (son stockage ou Web Crypto n’est pas disponible ici) : le lien, ouvert ici, ne peut pas indiquer que vous l’avez créé.
compose-copy-link = Copier le lien du défi
compose-link-copied = Lien du défi copié.
compose-link-not-copied = Sélectionnez le lien du défi ci-dessus et copiez-le.
compose-open = Ouvrir en tant qu’étudiant
compose-brief = L’énoncé en toutes lettres (pour une diapositive ou la page du cours)
compose-copy-brief = Copier l’énoncé
compose-brief-copied = Énoncé copié.
compose-brief-not-copied = Sélectionnez l’énoncé ci-dessus et copiez-le.

## Onglet Défi : les lignes de l’éditeur (web/challenge/compose-rows.js)

compose-allow-legend = Champs que l’étudiant peut modifier
compose-field = Champ
compose-field-option = { $field } — { $doc }
compose-add = Ajouter
compose-remove = Retirer
    .aria-label = Retirer { $field }
compose-allow-formula = une formule propre à l’étudiant ({ $unit })
compose-allow-choices = { $field } : choix (a|b)
compose-allow-from = de
compose-allow-to = à
compose-allow-now-unit = { $unit } (actuellement { $value })
compose-allow-now = (actuellement { $value })
compose-need-legend = Critères : les indicateurs de cette simulation
compose-need-hint = « Toutes les simulations » impose aussi le critère à chaque variante (la pire simulation compte).
compose-need = { $label } ({ $figure })
compose-need-now = { $label } ({ $figure }) — actuellement { $value }
compose-need-now-unit = { $label } ({ $figure }) — actuellement { $value } { $unit }
compose-need-op = { $figure } : type de borne
compose-need-bound = { $figure } : borne
compose-need-bound-unit = { $figure } : borne { $unit }
compose-op-max = au plus
compose-op-min = au moins
compose-op-abs = |valeur| au plus
compose-op-band = dans sa bande à 95 %
compose-bound-none = aucune
compose-need-all-runs = toutes les simulations
compose-vary-legend = Variantes de robustesse (facultatif)
compose-vary = Variantes : seeds:A..B (graines A à B), ou réglages appliqués par-dessus ceux de l’étudiant, séparés par |
    .placeholder = seeds:2..10 (graines)  ou  model.j=0.016|model.j=0.024
compose-vary-seeds = Graines 2 à 10

## Onglet Défi : la vérification qu’une solution réussit (web/challenge/compose-check.js)

compose-check-progress =
    .aria-label = Vérification du défi : simulations effectuées
compose-check-cancel = Annuler la vérification
compose-check-starting = Vérification qu’une solution dans les plages autorisées réussit…
compose-check-running =
    Vérification qu’une solution dans les plages autorisées réussit : { $done } / { $runs ->
        [one] { $runs } simulation
       *[other] { $runs } simulations
    } ({ $designs ->
        [one] { $designs } solution
       *[other] { $designs } solutions
    })…
compose-check-cancelled = Vérification annulée : on ne sait pas si une solution dans les plages autorisées réussit. Créez à nouveau le lien pour vérifier.
compose-check-failed = La vérification a échoué : { $reason }.
compose-check-base-design = la base, sans champ modifié
compose-check-failure = { $figure } : { $value } contre { $bound }
compose-check-failure-changing = { $figure } : { $value } contre { $bound }, évolue encore
compose-check-unmeasured = { $figure } : { $reason }
compose-check-base-passes = La base réussit telle quelle : un étudiant qui ne change rien réussit.
compose-check-base-fails = La base (sans champ modifié) échoue : { $failures }.
compose-check-tried =
    La vérification a essayé { $designs ->
        [one] { $designs } solution
       *[other] { $designs } solutions
    } en { $runs ->
        [one] { $runs } simulation
       *[other] { $runs } simulations
    } (au plus { $budget } simulations) : la base d’abord, puis celles qui modifient le moins de champs, des extrémités des plages vers l’intérieur (toutes les combinaisons, quand elles tiennent dans ce budget).
compose-check-solvable = ✓ Une solution dans les plages autorisées réussit : { $design } ({ $passing } des { $tried } solutions essayées réussissent).
compose-check-unsolved = ✗ Aucune des { $tried } solutions essayées ne réussit : les bornes sont peut-être hors d’atteinte ; la plus proche était { $design } ({ $failures }).

## Onglet Défi : noter une classe (web/challenge/grade.js)

grade-refused = Non noté : { $reason }.
grade-no-challenge = indiquez un défi : le nom d’un défi intégré ou un lien de défi
grade-no-file = choisissez un fichier de classe, ou collez les liens, un par ligne
grade-no-submission = le fichier ne contient aucune soumission
grade-read-as = Le fichier de classe a été lu en { $encoding } (il n’est pas en UTF-8).
grade-status-reading = Lecture du fichier de classe…
grade-status-grading = Notation de { $total } soumissions…
grade-status-grading-kept = Notation de { $total } soumissions, dont { $kept } conservées de la dernière notation…
grade-count = { $done } notées sur { $total }
grade-status-done = { $total } notées sur { $total } : { $passed } réussies.
grade-not-stored = Le stockage du navigateur n’a pas accepté cette notation : téléchargez-la maintenant.
grade-status-cancelled-kept = Annulé : { $graded } notées sur { $total }, conservées dans ce navigateur ; « Noter » reprend à partir de là.
grade-status-cancelled-lost = Annulé : { $graded } notées sur { $total }, non conservées (le stockage du navigateur les a refusées).
grade-status-stopped-kept = La notation s’est arrêtée : { $reason }. { $graded } notées sur { $total }, conservées dans ce navigateur ; « Noter » reprend à partir de là.
grade-status-stopped-lost = La notation s’est arrêtée : { $reason }. { $graded } notées sur { $total }, non conservées (le stockage du navigateur les a refusées).
grade-status-cancelled-reading = Annulé pendant la lecture du fichier de classe : rien n’a été noté.
grade-downloaded-partial = Les { $rows } premières lignes sur { $total } ont été téléchargées, dans l’ordre : « Noter » reprend là où la notation s’est arrêtée, et { $command } peut compléter le fichier.

## Onglet Défi : le tableau de la classe (web/challenge/grade-table.js)

grade-pending = pas encore noté
grade-pass = ✓ réussi
grade-fail = ✗ échoué
grade-head-line = ligne
grade-head-verdict = verdict
grade-head-link = lien
grade-value-reason = { $value } : { $reason }
grade-worst-run = { $text } (pire simulation : { $run })

motor-intro = Estime le schéma équivalent d’un moteur à partir de la résistance statorique mesurée en courant continu, de l’essai à vide sous tension nominale et de l’essai à rotor bloqué (IEEE Std 112), comme le fait imlab motor, et indique quelles valeurs sont des estimées. Le moteur sert ensuite à la fois de machine simulée et de modèle, avec la conception qui en est dérivée. Chaque essai est une mesure : tension entre phases, courant de ligne, puissance absorbée et fréquence, séparés par des virgules.
motor-rs = résistance statorique par phase, essai en courant continu
motor-no-load = essai à vide
motor-locked = essai à rotor bloqué
motor-nema = lettre de classe NEMA
motor-rated = plaque signalétique : tension, fréquence, courant
motor-j = inertie du rotor
motor-np = paires de pôles
motor-run-button = Estimer le schéma
motor-example-button = Remplir avec un exemple
motor-example-filled = Le formulaire contient une machine de 2,2 kW sous 400 V telle qu’un laboratoire la noterait : sa plaque signalétique et les mesures que donne son schéma (un laboratoire simulé, pas le moteur d’un catalogue).
motor-open = Simuler ce moteur avec la conception qui en est dérivée
