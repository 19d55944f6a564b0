# Les mots des outils pédagogiques affichés avant le chargement des leçons et du parcours : le
# panneau d’inspection, l’éditeur de la loi propre d’une étape (dans le parcours et dans les
# réglages) et les notes propres du parcours.

## Le panneau d’inspection (inspect-panel.js) : chaque terme de la conception à un échantillon

inspect-title = Inspection de l’échantillon k = { $k }, t = { $time } s
inspect-copy = Copier les valeurs exactes
inspect-copied = Copié
inspect-copy-failed = Échec de la copie : sélectionnez plutôt le tableau
inspect-close = Fermer (Échap)
inspect-exact = valeur exacte : { $value }
inspect-group-step = Étape { $step }
inspect-group-voltage = Tension (54) et limite
inspect-group-estimate = Estimée x̂ (k|k)
inspect-group-measured = Mesures et valeurs réelles
inspect-term = terme
inspect-value = valeur
inspect-unit = unité
inspect-meaning = signification
inspect-gain-caption = Gain de Kalman K_k (A⁻¹ × unité de l’état) et L = K_k/Ts (par seconde)
inspect-gain-row = ligne

## La loi propre d’une étape (law-editor.js)

law-write = Écrire cette étape
law-names = Les noms et les fonctions utilisables
law-names-name = nom
law-names-symbol = symbole
law-names-unit = unité
law-names-meaning = signification
law-names-functions = Avec + − * / ^ (ou · et −), des parenthèses, des nombres et les fonctions { $functions }.
law-error-at = Au caractère { $at } : { $reason }
law-stale = Ce n’est pas la loi saisie : la simulation affichée, ce verdict et le tracé du résidu portent sur { $output } = { $law }. { $verdict }
law-stale-after = Ce n’est pas la loi saisie : la simulation affichée, ce verdict et le tracé du résidu portent sur { $output } = { $law } après { $previous } = { $previousLaw }. { $verdict }

## Le parcours (walkthrough.js)

