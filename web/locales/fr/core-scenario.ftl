# Les messages du cœur de simulation sur un scénario : pourquoi un lien, un réglage ou une simulation
# a été refusé. La CLI les dit en anglais d’après le fichier anglais ; la page, dans la langue du
# lecteur. Les noms de champs, clés, valeurs, préréglages et réglages (v=1, preset=NAME, 'duration',
# 'ts', law.v2, pwm=1) sont les mots mêmes du lien : ils restent tels quels. Une saisie citée garde
# ses guillemets.

## Un scénario refusé

scenario-missing = le champ '{ $key }' manque (un scénario commence par v={ $version }&preset=NAME)
scenario-unsupported-version = champ 'v' = '{ $value }' : version de codec non prise en charge, autorisée : { $version }
scenario-unknown-preset = champ 'preset' = '{ $name }' : préréglage inconnu, autorisés : { $presets }
scenario-unknown-key = le champ '{ $key }' n’est pas un champ de scénario (le formulaire des réglages et `imlab describe` les listent)
scenario-duplicate-key = le champ '{ $key }' est donné plus d’une fois
scenario-malformed = '{ $piece }' n’est pas de la forme clé=valeur
scenario-bad-value = champ '{ $key }' = '{ $value }' : non valide, attendu : { $expected }
scenario-out-of-range = champ '{ $key }' = { $value } : hors plage, autorisé : { $allowed }
scenario-not-applicable = le champ '{ $key }' ne s’applique pas à la consigne '{ $reference }' (réglez d’abord ref=)
scenario-physics = { $which ->
        [plant] paramètres du moteur ({ $which })
       *[model] paramètres du modèle ({ $which })
    } : { $error }
scenario-bad-formula = champ '{ $key }' : { $error }
scenario-refused = champ '{ $key }' : { $why }
scenario-law-fw = une loi propre de l’étape 3 ou 4 est écrite pour une cible de flux constante, et fw=1 la déplace ; désactivez fw ou laissez la loi vide
scenario-design = champ 'design' = 'derived' : { $why }
design-no-voltage = la tension nominale laisse { $available } V au régime permanent, et le flux nominal avec le courant nominal demande { $needed } V même à l’arrêt
scenario-too-long = le scénario fait { $bytes } octets, plus que les { $max } octets ({ $kib } Kio) autorisés

## Ce qu’accepte un champ

scenario-expected-formula = une formule, en UTF-8 encodé-pourcent
scenario-expected-one-of = l’une des valeurs { $options }
scenario-expected-number = un nombre décimal
scenario-expected-table = des points t:value séparés par des virgules, par exemple 0:0,0.1:100, tous en nombres décimaux
scenario-expected-table-length = au plus { $max } points ; ce tableau en a { $count }
scenario-expected-table-rising = des instants croissants d’un point à l’autre ; { $after } s n’est pas après { $before } s
scenario-expected-table-time = des instants de 0 à { $max } s ; { $t } s est en dehors
scenario-expected-table-slope = une variation d’au plus { $max } { $unit } par seconde entre les points ; de { $before } s à { $after } s, elle est plus rapide
scenario-allowed-choice = { $options }
scenario-allowed-formula = une formule des noms que l’étape { $step } peut utiliser (`imlab describe` les liste), ou vide
scenario-allowed-table = jusqu’à { $max } points t:value, instants croissants de 0 à { $duration } s, valeurs { $values } ; en ligne droite entre les points, maintenu avant le premier et après le dernier
scenario-allowed-range = { $min } { $below } { $key } ≤ { $max }
scenario-allowed-unit = { $range } ({ $unit })
scenario-allowed-whole = { $range }, nombre entier
scenario-allowed-pwm = pwm=1 avec vlimit=circle ou hex : un onduleur à deux niveaux ne peut pas produire les coins du carré

## Une simulation trop grande

scenario-too-many-samples = 'duration'/'ts' = { $duration } s / { $ts } s = { $samples } échantillons, plus que les { $max } autorisés ; raccourcissez 'duration' ou augmentez 'ts'
scenario-shorter-than-sample = 'duration' = { $duration } s est plus court qu’un échantillon, 'ts' = { $ts } s
scenario-too-much-work = le travail de la simulation, { $samples } échantillons ('duration'/'ts' = { $duration } s / { $ts } s) × { $per_sample } pas RK4 du moteur par échantillon ({ $how }) = { $work } pas, dépasse les { $max } autorisés ; réduisez 'substeps' ou 'duration', ou augmentez 'ts'{ $pwm ->
        [yes] , ou désactivez 'pwm'
       *[no] {""}
    }
scenario-work-substeps = 'substeps' = { $substeps }
scenario-work-substeps-pwm = 'substeps' = { $substeps } sur chacun des 7 intervalles PWM
scenario-work-prediction = { $plant }, et { $substeps } pour la prédiction de l’observateur parfait ('delay.comp')
scenario-law-work = le travail des lois, { $samples } échantillons ('duration'/'ts' = { $duration } s / { $ts } s) × { $per_sample } opérations par échantillon ({ $parts }) = { $work }, dépasse les { $max } autorisées (un sinus ou un cosinus compte pour 64 opérations, une puissance pour 32, exp, ln, tanh et atan2 pour 12 chacune) ; écrivez des lois qui prennent au plus { $fits } opérations par échantillon, ou raccourcissez 'duration' à { $duration_fit } s ou portez 'ts' à { $ts_fit } s
scenario-law-work-step = law.v{ $step } { $work }
scenario-law-work-rates = les dérivées des lois propres v1 et v3 { $work }
scenario-trace-too-large = enregistrer { $rows } échantillons × { $columns } colonnes demande { $mib } Mio, plus que les { $max } Mio autorisés ; raccourcissez 'duration' ou augmentez 'ts'{ $fewer ->
        [yes] , ou gardez moins d’échantillons (un 'every' plus grand)
       *[no] {""}
    }
sweep-run-too-large = chaque simulation du balayage garde ses { $samples } échantillons, { $mib } Mio, plus que les { $max } Mio autorisés ; raccourcissez la durée des simulations du balayage ou augmentez 'ts'

## Des paramètres du moteur qui ne sont pas physiques

param-not-positive = { $name } = { $value } doit être un nombre fini > 0
param-negative = { $name } = { $value } doit être un nombre fini ≥ 0
param-sigma = l’inductance de fuite σ = Ls − M²/Lr = { $sigma } H doit être > 0 (M = { $m }, Ls = { $ls }, Lr = { $lr }) : M² doit être inférieur à Ls·Lr
scenario-allowed-every = 1 ≤ every

## La simulation d’un balayage refusée

sweep-allowed-amp = 0 < sine.amp pour un balayage
sweep-allowed-nyquist = sous la fréquence de Nyquist 1/(2·Ts) = { $nyquist } Hz
sweep-allowed-period = au moins une période dans la fenêtre d’ajustement : freq ≥ { $least } Hz pour une simulation de { $duration } s
sweep-allowed-measurable = une amplitude que le balayage peut mesurer : { $reason } ; augmentez l’amplitude
sweep-unresolved = l’ajustement de ω_d lui-même sur la fenêtre d’ajustement donne { $found } rad/s, à plus de { $tolerance } % de l’attendu (le carré de l’amplitude passe sous le plus petit flottant représentable, ou décalage + amplitude s’arrondit au décalage { $offset } rad/s)
sweep-too-small = à { $freq } Hz, la réponse se lit { $name } = { $value }, trop petite pour l’ajustement

## Les listes

core-list-separator = {", "}
field-idle = { $key } n’a pas d’effet avec { $because }
