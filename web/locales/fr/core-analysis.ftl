sweep-not-settled = non établi : sur les { $periods } dernières périodes, de la première moitié à la seconde, le gain de ω a varié de { $gain } dB et sa phase de { $phase }° (établi : à ±{ $gain-bound } dB et ±{ $phase-bound }° près)

## Les axes et les graines d’une carte d’erreur de modèle : pourquoi ils sont refusés, et le nom d’un axe.
map-axis-form = axe '{ $axis }' : attendu KEY=LO..HI:N, par exemple plant.rr=-10%..+10%:11 ou k1=-20%..+20%:5
map-axis-unknown = axe '{ $axis }' : { $key } n’est pas un champ de scénario
map-axis-not-numeric = axe '{ $axis }' : { $key } n’est pas un nombre ; une carte fait varier des champs numériques
map-axis-whole = axe '{ $axis }' : { $key } ne prend que des nombres entiers ; choisissez pour la carte un champ continu
map-axis-inactive = axe '{ $axis }' : { $key } n’a aucun effet dans ce scénario, donc toutes les cases donneraient la même simulation
map-axis-end = axe { $key } : { $end } '{ $text }' : attendu un nombre ou un pourcentage comme -10%
map-axis-mixed = axe '{ $axis }' : LO et HI doivent être tous deux des valeurs ou tous deux des pourcentages
map-axis-count = axe { $key } : N '{ $text }' : attendu un nombre entier de 1 à { $max }
map-axis-zero = axe '{ $axis }' : { $other } vaut 0, donc une erreur relative par rapport à lui vaut 0 aussi ; donnez { $key } en valeurs
map-axis-order = axe { $key } : LO ({ $lo }) est supérieur à HI ({ $hi })
map-axis-against-model = { $key } par rapport au modèle (%)
map-axis-against-motor = { $key } par rapport au moteur (%)
map-axis-against-base = { $key } par rapport à la valeur de base (%)
map-axis-unit = { $key } ({ $unit })
map-seeds-form = graines '{ $seeds }' : attendu A..B, des nombres entiers de 0 à { $max }
map-seeds-order = graines '{ $seeds }' : la première graine est supérieure à la dernière
map-seeds-many = graines '{ $seeds }' : { $count } graines, plus que les { $max } qu’une carte simule
map-seeds-twice = les graines sont données deux fois : donnez-les une seule fois
map-axes-count = { $count } axes : une carte en a un ou deux
map-axes-repeated = les deux axes font varier { $key } : faites varier deux champs différents
map-axes-sides = les axes font varier { $first } et { $second }, les deux côtés d’un même paramètre : faites varier un seul côté, en valeurs ou en erreur relative par rapport à l’autre
map-no-seeds = aucune graine : une carte en simule au moins une
map-runs-many = la carte demande { $runs } simulations ({ $cells } cases × { $seeds } graines), plus que les { $max } autorisées ; utilisez moins de points ou de graines
map-cell-refused = { $key }={ $value } : { $reason }
map-work = la carte demande { $work } pas du moteur ({ $cells } cases × { $seeds } graines × les pas d’une simulation), plus que les { $max } autorisés ; utilisez moins de points ou de graines, ou une 'duration' plus courte
map-law-work = les lois propres de la carte demandent { $work } opérations ({ $cells } cases × { $seeds } graines × jusqu’à { $per-run } par simulation), plus que les { $max } autorisées ; utilisez au plus { $runs } simulations (cases × graines), une 'duration' plus courte ou des lois moins coûteuses

## La conception dérivée (design=derived) : la règle derrière chaque valeur, avec sa raison.
# $voltage : tension nominale entre phases (V efficaces) ; $frequency : fréquence nominale (Hz).
design-rule-vdc = √2 × { $voltage } V, la tension de ligne redressée ; vlimit=circle, donc la limite de tension est l’amplitude vdc/√3 de la tension de phase nominale
design-rule-flux = le flux rotorique à { $voltage } V, { $frequency } Hz et à vide, M·V/|Rs + jωLs| : la magnétisation propre du moteur
design-rule-flux-capped = plafonné à M·i_rated/√2 (le flux à vide à { $voltage } V, { $frequency } Hz demande plus) : le courant magnétisant laisse la moitié de i_rated² au couple
design-rule-psi = le carré du flux, la cible de φa² + φb²
design-rule-id = courant magnétisant, flux/M
# $i_rated : l’amplitude du courant nominal (A).
design-rule-iq = courant de couple, √({ $i_rated }² − i_d²) : le reste du courant nominal
design-rule-torque = couple au courant et au flux nominaux, (3/2)·np·(M/Lr)·flux·i_q
design-rule-accel = accélération nominale, torque/J : la pente d’inversion que permet le couple au courant nominal
# $share : pourcentage de la limite de tension.
design-rule-base = vitesse de base : le flux nominal et le courant de couple nominal y demandent { $share } % de la limite de tension en régime permanent ; au-delà, fw=1 abaisse le flux comme base/ω, ce qui maintient la force contre-électromotrice, et le reste de la tension est la marge des boucles de courant
# $kts : k·Ts ; $share : pourcentage de la limite de tension ; $sigma : inductance de fuite σ (H).
design-rule-gain-ts = k2 = k3 = k4 = { $kts }/Ts : chaque erreur peut baisser de { $kts } fois sa valeur par échantillon, comme les 1200/s de l’article à 20 kHz ; la borne en tension, { $share } % de la limite divisés par σ·i_rated (σ = { $sigma } H), est plus haute
design-rule-gain-voltage = k2 = k3 = k4 = { $share } % de la limite de tension divisés par σ·i_rated (σ = { $sigma } H) : résorber à ce taux une erreur égale au courant nominal demande un quart de la tension ; la borne d’échantillonnage { $kts }/Ts est plus haute
# $ratio : k1 divisé par k2.
design-rule-k1 = k1 = { $ratio } × k2 : la boucle de vitesse est plus lente que le courant qu’elle commande
design-rule-q = bruit de processus : le modèle est le moteur, intégré comme le moteur simulé, donc Q n’est qu’un plancher qui garde en vie le gain du filtre ; le 1e-3 de l’article maintiendrait le NIS de ces moteurs sous sa bande
design-rule-r = le bruit du capteur de courant : R lui correspond
design-rule-r-none = pas de bruit de capteur : r_std = i_rated/1000, pour que le gain du filtre reste fini
# $time : secondes.
design-rule-q-load = torque²/{ $time } s : la charge peut varier de son couple nominal en { $time } s
design-rule-load-std = torque/4 : la charge est d’abord inconnue à un quart du couple nominal près
# Sous la description du préréglage quand le scénario a design=derived.
design-derived-heading = La conception dérivée du moteur, et la règle derrière chaque valeur
# $reason : pourquoi le cœur n’a pas pu la dériver.
design-failed = La conception dérivée n’a pas pu être affichée : { $reason }

## Un moteur d’après sa plaque signalétique et ses essais (`imlab motor`, l’onglet Analyse)

# $key : le champ (rs, no-load, locked, nema, rated, j, np) ; $value : ce qui a été saisi.
identify-bad-field = '{ $key }' = '{ $value }' : attendu { $expected }
identify-expect-positive = un nombre positif
identify-expect-whole = un nombre entier supérieur ou égal à 1
identify-expect-nema = A, B, C ou D
identify-expect-rated = V,F,I : la tension nominale entre phases (V efficaces), la fréquence nominale (Hz) et le courant nominal (A efficaces), positifs et séparés par des virgules
identify-expect-reading = V,I,P,F : tension entre phases (V efficaces), courant de ligne (A efficaces), puissance absorbée (W) et fréquence (Hz), séparés par des virgules ; la puissance peut valoir 0, les autres sont positifs
# $what : la grandeur d’une mesure, telle que le code la nomme (voltage, current, frequency, power, rs).
identify-not-positive = { $what } doit être un nombre positif
# $test : le champ de l’essai, no-load ou locked.
identify-power-too-high = '{ $test }' : la puissance de l’essai dépasse ce que √3·V·I peut fournir, donc sa résistance dépasserait son impédance
identify-no-rotor-resistance = 'locked' : la résistance par phase à rotor bloqué, { $locked } Ω, ne dépasse pas la résistance statorique, { $rs } Ω, il ne reste donc aucune résistance rotorique
identify-no-magnetising = 'no-load' : la réactance à vide ne dépasse pas la réactance de fuite statorique, il ne reste donc aucune réactance magnétisante
# $stator et $rotor : les parts de la fuite (0.5 et 0.5) ; $letter : la lettre de classe NEMA.
identify-heading = le schéma équivalent d’après l’essai à vide et l’essai à rotor bloqué (IEEE Std 112), la fuite à rotor bloqué étant répartie { $stator }/{ $rotor } entre stator et rotor (classe NEMA { $letter })
identify-how-rs = essai en courant continu
identify-how-rr = estimée : résistance à rotor bloqué moins rs, ramenée à la résistance rotorique à travers la branche magnétisante
identify-how-m = estimée : réactance à vide moins la fuite statorique
identify-how-ls = estimée : m plus la part statorique de la fuite à rotor bloqué
identify-how-lr = estimée : m plus la part rotorique de la fuite à rotor bloqué
identify-how-given = donnée
identify-link-heading = le moteur dans le préréglage step, à la fois machine simulée et modèle, avec ses valeurs nominales et la conception dérivée :
