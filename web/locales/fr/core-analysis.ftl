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
