# Las palabras del núcleo sobre una ejecución: qué significa cada ajuste, qué muestra cada
# preajuste, las cifras de una ejecución y la parte que abarca cada una, las advertencias sin las
# que no deben leerse, dónde termina el transitorio de arranque y por qué se detuvo una ejecución.
# La CLI los dice en inglés (`imlab describe`, `imlab presets`, `imlab metrics`); la página, en el
# idioma del lector. Las claves y nombres de campo (k1, law.v1, ekf.q), los valores de un campo
# (euler, rk4, box), los símbolos (ω_d, φa², Rs, |i_s|), las unidades, las fórmulas y los números
# de ecuación y de figura del artículo ((38), Fig 2) se mantienen tal cual.

## A time

# Un tiempo en milisegundos o en segundos, con hasta 4 cifras significativas.
time-ms = { $ms } ms
time-s = { $s } s

## What each setting means (its key, unit and range are the codec's own)

# (0/1) marca un interruptor: 0 desactivado, 1 activado.

field-design = diseño: paper (artículo, valores fijados) o derived (de los datos del motor)
field-ref = tipo de referencia de velocidad
field-ref-value = velocidad constante
field-sine-amp = amplitud del seno
field-sine-freq = frecuencia del seno
field-sine-offset = constante sumada al seno
field-step-size = amplitud del escalón
field-step-time = instante del escalón
field-step-wn = frecuencia natural ωn del filtro del escalón
field-ramp-start = instante de inicio de la rampa
field-ramp-level = nivel de la meseta de la rampa
field-ramp-slope = pendiente de la rampa, en valor absoluto
field-ramp-hold = duración de la meseta de la rampa
field-rev-start = inicio de la subida de la inversión
field-rev-level = velocidad invertida, de +level a −level
field-rev-slope = pendiente de la inversión, en valor absoluto
field-rev-hold = tiempo en +level antes de invertir
field-ref-table = referencia como tabla de puntos t:ω_d, en línea recta entre ellos
field-psi_d = consigna de flujo para φa² + φb²
field-fw = debilitamiento de campo por encima de la velocidad base (0/1)
field-fw-base = velocidad base del debilitamiento de campo
field-k1 = tasa del error de velocidad k1
field-k2 = tasa del error de par k2 = a7 + a8 + k2s1
field-k3 = tasa del error de flujo k3
field-k4 = tasa del error de la derivada del flujo k4
field-robust = aplicar los términos robustos (38) y (53) (0/1)
field-eps2 = ε2 de (38): la cota de z2·(v2s2 + d̃2)
field-h2 = h2 de (38): cota de |d̃2|
field-eps4 = ε4 de (53): la cota de z4·(v4s2 + d̃4)
field-h4 = h4 de (53): cota de |d̃4|
field-law-v1 = tu paso 1: el control virtual v1 (vacío: la (26) del artículo)
field-law-v2 = tu paso 2: v2 (vacío: la (34) del artículo)
field-law-v3 = tu paso 3: el control virtual v3 (vacío: la (45) del artículo)
field-law-v4 = tu paso 4: v4 (vacío: la (49) del artículo)
# backstepping e ifoc son los valores del campo: se mantienen tal cual.
field-controller = backstepping (artículo) o ifoc (base de comparación clásica: FOC sin sensor)
field-ifoc-bw_i = ancho de banda del lazo de corriente del IFOC
field-ifoc-bw_w = ancho de banda del lazo de velocidad del IFOC
field-ifoc-bw_mras = ancho de banda del estimador de velocidad MRAS del IFOC
field-ifoc-i_max = límite de la corriente q del IFOC
field-ifoc-ff = prealimentación de par del IFOC J·ω̇_d + T0 + Cf·ω_d (0/1)
# euler y rk4 son los valores del campo: se mantienen tal cual.
field-ekf = predictor del EKF: euler (artículo) o rk4
field-ekf-q = ruido de proceso Q = q·Ts·I, un mismo número para todos los estados: A²/s para las corrientes, (rad/s)²/s para ω, Wb²/s para los flujos
field-ekf-q_speed = ruido de proceso añadido solo al estado de velocidad, Q_ωω = (q + q_speed)·Ts
field-ekf-r_std = ruido de corriente supuesto, R = r_std²·I
field-ekf-load = estimar la carga a2 = T_L0/J como estado del EKF (0/1)
field-ekf-q_load = intensidad del paseo aleatorio del par de carga
field-ekf-load_std = desviación típica inicial de la estimación de la carga
field-ekf-rr = estimar la resistencia rotórica R_r como estado del EKF (0/1)
field-ekf-q_rr = intensidad del paseo aleatorio de la resistencia rotórica
field-ekf-rr_std = desviación típica inicial de la estimación de R_r
field-init_err = error relativo inicial de la estimación
field-start = estado inicial: paper (2 A, 2 A, 0,5 Wb, 0,5 Wb) o magnetized (en la consigna de flujo)
field-perfect = observador perfecto: el controlador recibe el estado real (0/1)
field-noise = desviación típica del ruido de medida de corriente
field-seed = semilla del ruido
# Los parámetros del motor simulado, los de la planta; los del modelo, lo que suponen el
# controlador y el observador, se leen igual.
field-motor = motor de la planta y del modelo a la vez, con su corriente nominal
field-plant-rs = resistencia estatórica Rs
field-plant-rr = resistencia rotórica Rr
field-plant-m = inductancia mutua M
field-plant-ls = inductancia estatórica Ls
field-plant-lr = inductancia rotórica Lr
field-plant-j = inercia del rotor J
field-plant-np = pares de polos np
field-plant-t0 = par de carga constante T0
field-plant-cf = fricción viscosa Cf
field-model-rs = { field-plant-rs }
field-model-rr = { field-plant-rr }
field-model-m = { field-plant-m }
field-model-ls = { field-plant-ls }
field-model-lr = { field-plant-lr }
field-model-j = { field-plant-j }
field-model-np = { field-plant-np }
field-model-t0 = { field-plant-t0 }
field-model-cf = { field-plant-cf }
field-load-time = instante del escalón de carga desconocido
field-load-torque = amplitud del escalón de carga desconocido
field-load-table = par de carga desconocido como tabla de puntos t:torque, en línea recta entre ellos (en lugar del escalón)
field-vmax = límite de tensión por componente
field-duration = tiempo simulado
field-ts = periodo de muestreo Ts
field-substeps = subpasos RK4 de la planta por muestra
field-i_rated = corriente nominal: amplitud |i_s| de la corriente de fase nominal
field-rated-v = tensión nominal, eficaz entre líneas
field-rated-f = frecuencia nominal
field-delay = retardo de cálculo: u_k se aplica una muestra después (0/1)
field-delay-comp = compensación del retardo: control a partir de la predicción a un paso x̂(k+1|k) (0/1)
# box, circle y hex son los valores del campo: se mantienen tal cual.
field-vlimit = límite de tensión: box (±vmax por componente, el artículo), circle (|u| ≤ vdc/√3) o hex (inversor de dos niveles)
field-vdc = tensión del bus de continua de los límites circle y hex y de la PWM
field-pwm = inversor de dos niveles, PWM simétrica a la frecuencia de muestreo (0/1; vlimit circle o hex)

## What each preset shows (preset-NAME: the preset NAME)

# El nombre de un preajuste en una descripción (sine200, load-step, rr-mismatch) es el del enlace:
# se mantiene tal cual.

preset-sine200 = Fig. 2 del artículo: seguimiento de 0,5 sin(2π·200 t) rad/s con el EKF; los picos de corriente superan la corriente nominal del motor
preset-step = Fig. 3 del artículo: escalón de 0 → 0,5 rad/s a los 50 ms, filtrado por un filtro de 200 Hz críticamente amortiguado
preset-ramp = Fig. 4 del artículo: trapecio hasta 100 rad/s a ±400 rad/s², meseta y vuelta
preset-sine200-1rad = 1 rad/s a 200 Hz: satura el límite de 400 V, y su error de seguimiento es más del triple del de sine200
preset-sine200-rk4 = La Fig. 2 con un predictor RK4 en el EKF en lugar del Euler del artículo
preset-rr-mismatch = Mantiene 50 rad/s con la resistencia rotórica del motor un 10 % por encima de la del modelo: la velocidad real se recupera del arranque a lo largo de segundos y se establece por encima de la referencia (ejecútalo durante 6 s para ver el final)
preset-load-step = Mantiene 50 rad/s; un escalón de carga desconocido de 2 N m a los 0,15 s que el EKF de 5 estados no puede ver
preset-decay = Observador perfecto, sin ruido, ω_d ≡ 0: los errores decaen a la tasa diseñada de 1200/s y después se detienen en un suelo que se reduce con el periodo de muestreo
preset-ifoc-step = Base de comparación clásica: IFOC sin sensor con un MRAS, escalón hasta 40 rad/s (el MRAS es ciego cerca de la velocidad cero)
preset-load-step-est = load-step con la carga a2 como estado del EKF (predictor RK4): la velocidad se mantiene durante el escalón desconocido con un modelo exacto, pero no con la R_r del motor un 3 % por debajo de la del modelo
preset-rr-mismatch-est = rr-mismatch (discrepancia de R_r) con R_r como estado del EKF (predictor RK4): sin transitorio lento, y R̂_r se mantiene cerca del valor del motor
preset-sine200-drive = ¿Aguanta los 200 Hz un accionamiento real? sine200 con un retardo de cálculo de una muestra, el hexágono del inversor con 540 V y PWM
preset-high-gain = Ganancias de 3000/s (2,5× las del artículo): los errores de predicción del EKF de Euler, a través de las ganancias, saturan el límite de 400 V

## The figures of a run (`imlab metrics` names them by the part after figure-)

figure-transient_end = fin del transitorio de arranque
figure-tracking_rms = RMS de ω − ω_d
figure-tracking_peak = |ω − ω_d| de pico
figure-settling_time = tiempo de establecimiento al 2 % de ω tras el escalón
figure-saturated_share = fracción de muestras en el límite de tensión
figure-mean_nis = NIS medio
figure-mean_nis_low = NIS medio, extremo inferior de la banda del 95 % de un filtro consistente
figure-mean_nis_high = NIS medio, extremo superior de la banda del 95 % de un filtro consistente
figure-current_peak = corriente estatórica de pico |i_s|
figure-current_rms = corriente estatórica RMS |i_s|
figure-current_rated = corriente nominal |i_s| (i_rated)
figure-ripple_peak = rizado de corriente PWM de pico
figure-ripple_rms = RMS, sobre los periodos, del rizado de corriente PWM de pico
figure-flux_error_final = error final de flujo |φ_r| − √ψ_d
figure-speed_error_final = error final de velocidad ω − ω_d
figure-speed_estimate_error_final = error final de la estimación de velocidad ω − ω̂
figure-law_residual = mayor residuo de la dinámica diseñada de tus leyes, a lo largo de la ejecución y en los estados sorteados del veredicto, relativo a la ley del artículo
# No está entre las cifras de la ejecución: un reto puede nombrarla.
figure-load_recovery_time = tiempo de recuperación tras el escalón de carga

## The part of the run a figure covers

# $time es un tiempo (time-ms o time-s): donde termina el transitorio de arranque.
window-after-transient = t ≥ { $time }
window-start-up = arranque, t < { $time }
# $time es el instante del escalón de la referencia.
window-from-step = desde el escalón, a los { $time }
window-rating = el valor nominal del motor
# $time es el instante de la última muestra de la ejecución.
window-last-sample = última muestra, t = { $time }
window-law-residual = toda la ejecución y los estados sorteados del veredicto

## A figure the run had not reached by its end, said in place of its value

# $time es el instante de la última muestra de la ejecución.
unreached-not-settled = no establecido al final de la ejecución (t = { $time })

## What a run's figures must not be read without

# $speed es ω − ω_d al final de la ejecución; $estimate, ω̂ − ω; $flux, el módulo del flujo, y
# $target, su consigna √ψ_d.
warning-runaway = La ejecución se desbocó: al final, la velocidad real está a { $speed } rad/s de la referencia, la estimación de velocidad a { $estimate } rad/s de la velocidad real, y el flujo en { $flux } Wb frente a su consigna de { $target } Wb. El controlador regula las estimaciones del EKF; el teorema 4.6 acota el lazo cerrado solo mientras los errores de estimación se mantienen acotados, y cuando no es así (un error de arranque contenido solo por el límite de tensión, un modelo erróneo a baja velocidad) nada acota el motor.
# $low y $high son los extremos de la banda.
warning-inconsistent-above = El EKF es inconsistente en esta ejecución: su NIS medio es { $nis }, muy por encima de la banda del 95 % { $low }–{ $high } de un filtro con un modelo correcto. Sus estimaciones, y la velocidad sobre la que actúa el controlador, pueden estar lejos de la realidad por estrechas que parezcan sus bandas.
warning-inconsistent-below = El EKF es inconsistente en esta ejecución: su NIS medio es { $nis }, muy por debajo de la banda del 95 % { $low }–{ $high } de un filtro con un modelo correcto. Supone más ruido del que hay, así que sigue las mediciones más despacio de lo que podría.
# $figure es el nombre de la cifra (law_residual); $cause dice por qué no es un número.
warning-not-following = La velocidad no sigue a su referencia: desde t = { $since } hasta el final de la ejecución, ω − ω_d queda fuera de ±({ $share } % de |ω_d| + { $margin } rad/s), y termina en { $error } rad/s con ω_d = { $reference } rad/s.
warning-not-following-window = La velocidad no sigue a su referencia: en toda la ventana de las cifras, desde t = { $since } hasta el final de la ejecución, ω − ω_d queda fuera de ±({ $share } % de |ω_d| + { $margin } rad/s), y termina en { $error } rad/s con ω_d = { $reference } rad/s.
warning-not-finite = { $figure } no es un número finito: { $cause }.

## Where the start-up transient ends, and why there

transient-nothing-recorded = aún no se ha registrado nada
# En lugar de un tiempo: el criterio no se cumplió nunca en la primera mitad de la ejecución.
transient-never = nunca en la primera mitad (no se usa)
# $k es la menor de las ganancias k1..k4 (1/s); $time, el arranque del controlador.
transient-backstepping = 5 constantes de tiempo de la tasa de error diseñada más lenta (1/{ $k } s) = { $time }
# $bw es el ancho de banda del lazo de corriente del IFOC, ifoc.bw_i (Hz); $time, el arranque del
# controlador.
transient-ifoc = 5 constantes de tiempo de los lazos de corriente del IFOC (1/(2π·{ $bw } Hz)) = { $time }
# $controller es transient-backstepping o transient-ifoc; $observer, $estimates, $flux y $speed son
# tiempos, o transient-never; $end es event cuando el transitorio se cortó en el primer evento del
# escenario (el escalón o el escalón de carga), half cuando se limitó a la mitad de la ejecución, y
# si no, none; $at es el instante de ese evento o de la mitad de la ejecución.
transient-reason = { $controller }, contadas desde el arranque del observador. Covarianza de la innovación del EKF establecida (banda de 2σ a menos del 10 % de su valor final): { $observer }; estimaciones del EKF convergidas (NIS medio sobre 2 ms como mucho el doble de su nivel en la segunda mitad, durante 5 ms): { $estimates }; estimación de flujo con un error de como mucho 1,5 veces su RMS posterior (durante 5 ms): { $flux }; estimación de velocidad con un error de como mucho el doble de su RMS posterior (ventanas de 5 ms, durante 5 ms): { $speed }{ $end ->
        [event] ; cortado en el primer evento del escenario, a los { $at }
        [half] ; limitado a la mitad de la ejecución registrada ({ $at })
       *[none] {""}
    }

## Why a run stopped

# $t es el instante de la muestra (s); $signal, el estado que salió de sus cotas (omega, i_sa,
# phi_a…); $value, su valor, en notación científica (1.2e5, NaN).
sim-diverged = divergió en t = { $t } s: { $signal } = { $value } salió de sus cotas
# $column es una columna del CSV de la ejecución; $value es inf, -inf o NaN.
sim-not-finite = se detuvo en t = { $t } s: la columna '{ $column }' registraría { $value }, que no es un número finito
# $error es un mensaje control-*.
sim-control = el controlador falló en t = { $t } s: { $error }
# $formula es la ley del estudiante tal como se escribió; $value es inf, -inf o NaN; $reading es
# sim-law-reads-nothing o sim-law-reads.
sim-law = tu law.v{ $step } = { $formula } dio { $value } en t = { $t } s, { $reading }
sim-law-reads-nothing = sin leer ninguna señal
# $signals enumera los nombres que lee la ley con sus valores ahí (x1h = 52.3, z1 = 0.01).
sim-law-reads = con { $signals }
# $flux y $min en notación científica (Wb²).
control-singular = la matriz de desacoplo (55) es singular: el flujo estimado x̂4² + x̂5² = { $flux } Wb² está por debajo de { $min } Wb²
control-law = la ley del paso { $step } dio { $value }, que no es un número finito
pin-room-full = se pueden fijar como máximo { $max } ejecuciones; quita una primero
pin-legend-same = mismo escenario
overlay-ts-differs = la ejecución fijada { $scenario } muestrea con Ts = { $pinned } s y la actual con { $current } s: las superposiciones necesitan el mismo Ts
