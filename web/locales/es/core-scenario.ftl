# Los mensajes del núcleo sobre un escenario: por qué se rechazó un enlace, un ajuste o una
# ejecución. La CLI los dice en inglés a partir del archivo en inglés; la página, en el idioma del
# lector. Los nombres de campo, claves, valores, preajustes y ajustes (v=1, preset=NAME, 'duration',
# 'ts', law.v2, pwm=1) son las propias palabras del enlace: se mantienen tal cual. La entrada citada
# conserva sus comillas.

## A scenario refused

scenario-missing = falta el campo '{ $key }' (un escenario empieza por v={ $version }&preset=NAME)
scenario-unsupported-version = campo 'v' = '{ $value }': versión del códec no admitida; se admite: { $version }
# $presets enumera los nombres de los preajustes.
scenario-unknown-preset = campo 'preset' = '{ $name }': preajuste desconocido; se admiten: { $presets }
scenario-unknown-key = '{ $key }' no es un campo del escenario (el formulario de ajustes y `imlab describe` los enumeran)
scenario-duplicate-key = el campo '{ $key }' aparece más de una vez
scenario-malformed = '{ $piece }' no tiene la forma clave=valor
# $expected es uno de los mensajes scenario-expected-*.
scenario-bad-value = campo '{ $key }' = '{ $value }': no válido; se esperaba { $expected }
# $allowed es uno de los mensajes scenario-allowed-*.
scenario-out-of-range = campo '{ $key }' = { $value }: fuera de rango; se admite: { $allowed }
# $reference es el tipo de referencia del escenario (step, sine, ramp…).
scenario-not-applicable = el campo '{ $key }' no se aplica a la referencia '{ $reference }' (fija antes ref=)
# $which es "plant" o "model", el prefijo de los campos; $error es un mensaje param-*.
scenario-physics = { $which ->
        [plant] parámetros de la planta ({ $which })
       *[model] parámetros del modelo ({ $which })
    }: { $error }
# $error dice dónde y por qué se rechazó la fórmula.
scenario-bad-formula = campo '{ $key }': { $error }
scenario-refused = campo '{ $key }': { $why }
scenario-law-fw = una ley propia del paso 3 o 4 está escrita para una consigna de flujo constante, y fw=1 la mueve; desactiva fw o deja la ley vacía
scenario-design = campo 'design' = 'derived': { $why }
design-no-voltage = la tensión nominal deja { $available } V para el régimen permanente, y el flujo nominal con la corriente nominal necesita { $needed } V incluso en reposo
scenario-too-long = el escenario ocupa { $bytes } bytes, más de los { $max } bytes ({ $kib } KiB) permitidos

## What a field takes

scenario-expected-formula = una fórmula, codificada por porcentajes en UTF-8
scenario-expected-one-of = uno de { $options }
scenario-expected-number = un número decimal
# Una tabla de puntos: una referencia o un par de carga dados como pares t:value.
scenario-expected-table = puntos t:value separados por comas, como 0:0,0.1:100, cada número en forma decimal
scenario-expected-table-length = como mucho { $max } puntos; esta tabla tiene { $count }
scenario-expected-table-rising = tiempos que crezcan de un punto al siguiente; { $after } s no es posterior a { $before } s
scenario-expected-table-time = tiempos de 0 a { $max } s; { $t } s queda fuera
# $unit es la unidad de los valores (rad/s); $before y $after son los tiempos de los dos puntos.
scenario-expected-table-slope = un cambio de como mucho { $max } { $unit } por segundo entre puntos; de { $before } s a { $after } s es más rápido
scenario-allowed-choice = { $options }
scenario-allowed-formula = una fórmula con los nombres que puede usar el paso { $step } (`imlab describe` los enumera), o vacío
# $values es el rango de los valores (scenario-allowed-unit).
scenario-allowed-table = hasta { $max } puntos t:value, con tiempos crecientes de 0 a { $duration } s y valores { $values }; en línea recta entre los puntos, y constante antes del primero y después del último
# El rango de un campo: "0 < k1 ≤ 1000000"; $below es < o ≤.
scenario-allowed-range = { $min } { $below } { $key } ≤ { $max }
# $range es el rango anterior, seguido de su unidad: "0 < k1 ≤ 1000000 (1/s)".
scenario-allowed-unit = { $range } ({ $unit })
scenario-allowed-whole = { $range }, número entero
scenario-allowed-pwm = pwm=1 con vlimit=circle o hex: un inversor de dos niveles no puede generar los vértices de la caja

## A run too large

scenario-too-many-samples = 'duration'/'ts' = { $duration } s / { $ts } s = { $samples } muestras, más de las { $max } permitidas; acorta 'duration' o aumenta 'ts'
scenario-shorter-than-sample = 'duration' = { $duration } s es más corto que una muestra, 'ts' = { $ts } s
# $how es uno de los mensajes scenario-work-*; $pwm es yes cuando la ejecución tiene PWM.
scenario-too-much-work = el trabajo de la ejecución, { $samples } muestras ('duration'/'ts' = { $duration } s / { $ts } s) × { $per_sample } pasos RK4 de la planta por muestra ({ $how }) = { $work } pasos, supera los { $max } permitidos; reduce 'substeps' o 'duration', o aumenta 'ts'{ $pwm ->
        [yes] , o desactiva 'pwm'
       *[no] {""}
    }
scenario-work-substeps = 'substeps' = { $substeps }
scenario-work-substeps-pwm = 'substeps' = { $substeps } en cada uno de los 7 intervalos PWM
scenario-work-prediction = { $plant }, y { $substeps } para la predicción del observador perfecto ('delay.comp')
# $parts enumera mensajes scenario-law-work-step y scenario-law-work-rates.
scenario-law-work = el trabajo de las leyes, { $samples } muestras ('duration'/'ts' = { $duration } s / { $ts } s) × { $per_sample } operaciones por muestra ({ $parts }) = { $work }, supera las { $max } permitidas (un seno o un coseno cuenta 64 operaciones, una potencia 32, y exp, ln, tanh y atan2, 12 cada una); escribe leyes que usen como mucho { $fits } operaciones por muestra, o acorta 'duration' a { $duration_fit } s o aumenta 'ts' a { $ts_fit } s
scenario-law-work-step = law.v{ $step } { $work }
scenario-law-work-rates = las derivadas de los v1 y v3 propios { $work }
# $fewer es yes cuando quien llama puede conservar una de cada n muestras.
scenario-trace-too-large = registrar { $rows } muestras × { $columns } columnas necesita { $mib } MiB, más de los { $max } MiB permitidos; acorta 'duration' o aumenta 'ts'{ $fewer ->
        [yes] , o conserva menos muestras (un 'every' mayor)
       *[no] {""}
    }
sweep-run-too-large = cada ejecución del barrido conserva sus { $samples } muestras, { $mib } MiB, más de los { $max } MiB permitidos; acorta la duración de las ejecuciones del barrido o aumenta 'ts'

## Motor parameters that are not physical

param-not-positive = { $name } = { $value } debe ser un número finito > 0
param-negative = { $name } = { $value } debe ser un número finito ≥ 0
param-sigma = la dispersión σ = Ls − M²/Lr = { $sigma } H debe ser > 0 (M = { $m }, Ls = { $ls }, Lr = { $lr }): M² debe ser menor que Ls·Lr
scenario-allowed-every = 1 ≤ every

## A sweep's run refused

sweep-allowed-amp = 0 < sine.amp en un barrido
sweep-allowed-nyquist = por debajo de la frecuencia de Nyquist 1/(2·Ts) = { $nyquist } Hz
sweep-allowed-period = al menos un periodo en la ventana de ajuste: freq ≥ { $least } Hz para una ejecución de { $duration } s
# $reason es sweep-unresolved o sweep-too-small.
sweep-allowed-measurable = una amplitud que el barrido pueda medir: { $reason }; aumenta la amplitud
sweep-unresolved = el ajuste de la propia ω_d en la ventana de ajuste da { $found } rad/s, con un error de más del { $tolerance } % (el cuadrado de la amplitud se queda por debajo del mínimo representable, u offset + amplitud se redondea al offset { $offset } rad/s)
# $name es el nombre de columna de una cifra; $value, su valor (NaN o inf).
sweep-too-small = a { $freq } Hz la respuesta da { $name } = { $value }, demasiado pequeña para el ajuste

## Lists

# Lo que separa los elementos de una lista que da el núcleo ("law.v1 12, law.v2 40").
core-list-separator = {", "}
field-idle = { $key } no tiene efecto con { $because }
