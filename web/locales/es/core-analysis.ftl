sweep-not-settled = no establecido: en los últimos { $periods } periodos, de la primera mitad a la segunda, la ganancia de ω cambió en { $gain } dB y su fase en { $phase }° (establecido: dentro de ±{ $gain-bound } dB y ±{ $phase-bound }°)

## Los ejes y las semillas de un mapa de errores de modelo: por qué se rechazan, y el nombre de un eje.
map-axis-form = eje '{ $axis }': se esperaba KEY=LO..HI:N, p. ej., plant.rr=-10%..+10%:11 o k1=-20%..+20%:5
map-axis-unknown = eje '{ $axis }': { $key } no es un campo del escenario
map-axis-not-numeric = eje '{ $axis }': { $key } no es un número; un mapa varía campos numéricos
map-axis-whole = eje '{ $axis }': { $key } solo admite números enteros; usa en el mapa un campo continuo
map-axis-inactive = eje '{ $axis }': { $key } no tiene efecto en este escenario, así que todas las celdas se ejecutarían igual
map-axis-end = eje { $key }: { $end } '{ $text }': se esperaba un número o un porcentaje como -10%
map-axis-mixed = eje '{ $axis }': LO y HI deben ser ambos valores o ambos porcentajes
map-axis-count = eje { $key }: N '{ $text }': se esperaba un número entero de 1 a { $max }
map-axis-zero = eje '{ $axis }': { $other } es 0, así que un error relativo respecto a él también es 0; da { $key } en valores
map-axis-order = eje { $key }: LO ({ $lo }) es mayor que HI ({ $hi })
map-axis-against-model = { $key } respecto al modelo (%)
map-axis-against-motor = { $key } respecto al motor (%)
map-axis-against-base = { $key } respecto al valor base (%)
map-axis-unit = { $key } ({ $unit })
map-seeds-form = semillas '{ $seeds }': se esperaba A..B, números enteros de 0 a { $max }
map-seeds-order = semillas '{ $seeds }': la primera semilla es mayor que la última
map-seeds-many = semillas '{ $seeds }': { $count } semillas, más de las { $max } que ejecuta un mapa
map-seeds-twice = las semillas se dan dos veces: dalas solo una vez
map-axes-count = { $count } ejes: un mapa tiene uno o dos
map-axes-repeated = ambos ejes varían { $key }: varía dos campos distintos
map-axes-sides = los ejes varían { $first } y { $second }, los dos lados de un mismo parámetro: varía un solo lado, en valores o como error relativo respecto al otro
map-no-seeds = ninguna semilla: un mapa ejecuta al menos una
map-runs-many = el mapa necesita { $runs } ejecuciones ({ $cells } celdas × { $seeds } semillas), más de las { $max } permitidas; usa menos puntos o semillas
map-cell-refused = { $key }={ $value }: { $reason }
map-work = el mapa necesita { $work } pasos de la planta ({ $cells } celdas × { $seeds } semillas × los pasos de una ejecución), más de los { $max } permitidos; usa menos puntos o semillas, o una 'duration' más corta
map-law-work = las leyes propias del mapa requieren { $work } operaciones ({ $cells } celdas × { $seeds } semillas × hasta { $per-run } por ejecución), más de las { $max } permitidas; usa como mucho { $runs } ejecuciones (celdas × semillas), una 'duration' más corta o leyes menos costosas
