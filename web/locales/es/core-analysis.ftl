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

## El diseño derivado (design=derived): la regla detrás de cada valor, con su razón.
# $voltage: tensión nominal entre líneas (V eficaces); $frequency: frecuencia nominal (Hz).
design-rule-vdc = √2 × { $voltage } V, la tensión de línea rectificada; vlimit=circle, así que el límite de tensión es la amplitud de la tensión de fase nominal, vdc/√3
design-rule-flux = el flujo rotórico a { $voltage } V, { $frequency } Hz y en vacío, M·V/|Rs + jωLs|: la magnetización propia del motor
design-rule-flux-capped = limitado a M·i_rated/√2 (el flujo en vacío a { $voltage } V, { $frequency } Hz pide más): la corriente magnetizante deja la mitad de i_rated² para el par
design-rule-psi = el cuadrado del flujo, la consigna de φa² + φb²
design-rule-id = corriente magnetizante, flux/M
# $i_rated: la amplitud de la corriente nominal (A).
design-rule-iq = corriente de par, √({ $i_rated }² − i_d²): el resto de la corriente nominal
design-rule-torque = par a corriente y flujo nominales, (3/2)·np·(M/Lr)·flux·i_q
design-rule-accel = aceleración nominal, torque/J: la pendiente de inversión que el motor logra a corriente nominal
# $share: porcentaje del límite de tensión.
design-rule-base = velocidad base: el flujo nominal y la corriente de par nominal necesitan ahí el { $share } % del límite de tensión en régimen permanente; por encima, fw=1 reduce el flujo como base/ω, lo que mantiene la fuerza contraelectromotriz, y el resto de la tensión es el margen de los lazos de corriente
# $kts: k·Ts; $share: porcentaje del límite de tensión; $sigma: inductancia de dispersión σ (H).
design-rule-gain-ts = k2 = k3 = k4 = { $kts }/Ts: cada error puede caer en { $kts } veces su valor por muestra, como los 1200/s del artículo a 20 kHz; la cota de tensión, el { $share } % del límite entre σ·i_rated (σ = { $sigma } H), es mayor
design-rule-gain-voltage = k2 = k3 = k4 = { $share } % del límite de tensión entre σ·i_rated (σ = { $sigma } H): cerrar a ese ritmo un error del tamaño de la corriente nominal pide una cuarta parte de la tensión; la cota de muestreo { $kts }/Ts es mayor
# $ratio: k1 entre k2.
design-rule-k1 = k1 = { $ratio } × k2: el lazo de velocidad es más lento que la corriente que ordena
design-rule-q = ruido de proceso: el modelo es el motor, integrado como la planta, así que Q es solo un mínimo que mantiene viva la ganancia del filtro; el 1e-3 del artículo dejaría el NIS de estos motores por debajo de su banda
design-rule-r = el ruido del sensor de corriente: R coincide con él
design-rule-r-none = sin ruido del sensor: r_std = i_rated/1000, para que la ganancia del filtro siga siendo finita
# $time: segundos.
design-rule-q-load = torque²/{ $time } s: la carga puede variar en su par nominal en { $time } s
design-rule-load-std = torque/4: la carga empieza desconocida hasta un cuarto del par nominal
# Bajo la descripción del preajuste cuando el escenario tiene design=derived.
design-derived-heading = El diseño derivado del motor y la regla detrás de cada valor
# $reason: por qué el núcleo no pudo derivarlo.
design-failed = No se pudo mostrar el diseño derivado: { $reason }

## Un motor a partir de su placa de características y sus ensayos de laboratorio (`imlab motor`, la pestaña Análisis)

# $key es el campo (rs, no-load, locked, nema, rated, j, np); $value, lo que se escribió.
identify-bad-field = '{ $key }' = '{ $value }': se esperaba { $expected }
identify-expect-positive = un número positivo
identify-expect-whole = un número entero mayor o igual que 1
identify-expect-nema = A, B, C o D
identify-expect-rated = V,F,I: la tensión nominal entre líneas (V eficaces), la frecuencia nominal (Hz) y la corriente nominal (A eficaces), positivas y separadas por comas
identify-expect-reading = V,I,P,F: tensión entre líneas (V eficaces), corriente de línea (A eficaces), potencia absorbida (W) y frecuencia (Hz), separadas por comas; la potencia puede ser 0, las demás son positivas
# $what es la magnitud de una lectura tal como la nombra el código (voltage, current, frequency, power, rs).
identify-not-positive = { $what } debe ser un número positivo
# $test es el campo del ensayo: no-load o locked.
identify-power-too-high = '{ $test }': la potencia del ensayo supera lo que √3·V·I puede aportar, así que su resistencia superaría su impedancia
identify-no-rotor-resistance = 'locked': la resistencia por fase a rotor bloqueado, { $locked } Ω, no supera la resistencia estatórica, { $rs } Ω, así que no queda resistencia rotórica
identify-no-magnetising = 'no-load': la reactancia en vacío no supera la reactancia de dispersión estatórica, así que no queda reactancia magnetizante
# $stator y $rotor son las partes de la dispersión (0.5 y 0.5); $letter, la letra de diseño NEMA.
identify-heading = el circuito equivalente a partir de los ensayos en vacío y a rotor bloqueado (IEEE Std 112), con la dispersión del ensayo a rotor bloqueado repartida { $stator }/{ $rotor } entre estátor y rotor (diseño NEMA { $letter })
identify-how-rs = ensayo en corriente continua
identify-how-rr = estimación: resistencia a rotor bloqueado menos rs, llevada a resistencia rotórica a través de la rama magnetizante
identify-how-m = estimación: reactancia en vacío menos la dispersión estatórica
identify-how-ls = estimación: m más la parte estatórica de la dispersión a rotor bloqueado
identify-how-lr = estimación: m más la parte rotórica de la dispersión a rotor bloqueado
identify-how-given = dado
identify-link-heading = el motor en el preajuste step, como planta y como modelo a la vez, con sus valores nominales y el diseño derivado:
