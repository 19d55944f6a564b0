# Las etiquetas, botones, notas y mensajes de la página, según la parte de la página que los muestra.
# Los números llegan en variables, ya escritos a la manera del idioma. Una variable llamada $reason,
# $warning, $description o $label contiene las propias palabras del núcleo de simulación, por ahora
# en inglés; un escenario ($scenario), la clave de un campo ($key), el nombre de un preajuste
# ($preset) o una orden se escriben tal cual y nunca se traducen.

## The header

# El título de la pestaña del navegador.
page-title = IM Lab: control sin sensor de velocidad del motor de inducción
# El nombre de la aplicación, en el encabezado de la página.
page-name = IM Lab
page-skip-link = Ir a las gráficas
page-intro = Control sin sensor de velocidad del motor de inducción: observador EKF y controlador backstepping en cuatro pasos (Zhang, Wang, Bortoff et al., 2015), simulado a 20 kHz en tu navegador.
help-links =
    .aria-label = Acerca de / Ayuda
# Va delante de los enlaces a las guías.
help-links-intro = Acerca de / Ayuda:
help-student-guide = Guía del estudiante
help-lecturer-guide = Guía del profesor
help-all-guides = Todas las guías
language-menu = Idioma

## Loading the lessons

# $reason es el motivo que da el navegador, con sus palabras.
lessons-not-loaded = No se pudieron cargar los textos de las lecciones: { $reason }. Vuelve a abrir la pestaña «Lecciones» para reintentarlo.

## Buttons shared by several places

shared-cancel = Cancelar
# Descarga una tabla como archivo CSV.
shared-csv = CSV

## The run bar: the preset, Run, the status line and the links

run-preset = Preajuste
run-button = Ejecutar
run-settings = Ajustes
run-unrun = Ajustes cambiados, aún sin ejecutar: pulsa «Ejecutar» o Intro. La dirección y «Copiar enlace» describen la ejecución en pantalla.
share-copy-link = Copiar enlace
# Descarga una imagen de las gráficas.
export-png = PNG
share-copy-embed = Copiar código para insertar
    .title = Copia un fragmento iframe que muestra las gráficas visibles de «Trayectorias», para este escenario

## The results: the tabs, the view bar and the figures

results =
    .aria-label = Resultados
tabs =
    .aria-label = Vistas
tab-plots = Trayectorias
tab-walkthrough = Recorrido por el diseño
tab-lessons = Lecciones
tab-analysis = Análisis
tab-challenge = Reto
present-button = Modo presentación
    .title = Texto y gráficas más grandes para un proyector; los ajustes pasan a un panel lateral
view-full-run = Ejecución completa
    .title = Muestra la ejecución entera en todas las gráficas (también con doble clic en una gráfica, o Escape)
view-fit = Ajustar los ejes y tras el transitorio de arranque
# $ms es el instante en que termina el transitorio de arranque, en milisegundos (8,5).
view-fit-from = Ajustar los ejes y tras el transitorio de arranque (t ≥ { $ms } ms)
view-fit-why = ¿Por qué este instante?
# $reason es la explicación del núcleo de dónde termina el transitorio de arranque.
view-transient-reason = Transitorio de arranque: { $reason }.
figures-all = Todas las cifras
figures-fewer = Menos cifras
figures-strip =
    .aria-label = Cifras de la ejecución
plots-hint = Arrastra sobre una gráfica para ampliarlas todas; el doble clic, Escape o «Ejecución completa» vuelven a la ejecución entera. La leyenda lee los valores registrados en la muestra bajo el cursor; haz clic en una gráfica para inspeccionar todos los términos en ese instante.

## The pins and their overlay (Trajectories tab)

pins-pin = Fijar esta ejecución
# Etiqueta el menú de la columna que compara la superposición.
pins-overlay = superposición
pins-column-omega = velocidad ω
pins-column-omega-hat = velocidad estimada ω̂
pins-column-flux = flujo |φ|
pins-column-voltage = tensión u_sa
pins-unpin = Quitar
# Una ejecución fijada en la lista: $n es su número (1), $legend en qué difieren sus ajustes de los de la ejecución actual (k1=600).
pins-item = fijada { $n }: { $legend }
# El nombre de una ejecución fijada en la leyenda de la superposición; $n es su número (1).
pins-name = fijada { $n }
# La ejecución actual, en la leyenda de la superposición.
pins-current = actual
# La diferencia entre la ejecución actual y la fijada $n, en la leyenda de la superposición.
pins-difference = actual − fijada { $n }
# El título de la superposición; $column es la columna comparada, como la nombra el menú (velocidad ω).
pins-overlay-title = { $column }: ejecución actual y ejecuciones fijadas
pins-difference-title = { $column }: actual − fijada
# $n es la ejecución fijada en curso (2), $count cuántas se ejecutan (3), $percent cuánto lleva hecho (45).
pins-status-running = Ejecutando la fijada { $n } de { $count }: { $percent } %
pins-status-done = Fijación completada
pins-status-cancelled = Fijación cancelada
# $length es la longitud de la parte de fijadas de la dirección, en caracteres; $max, la máxima permitida.
pins-link-too-long = Las ejecuciones fijadas de la dirección no se ejecutaron: { $length } caracteres, más de los { $max } que admite un fragmento de fijadas.
# $pins enumera las fijadas que no se pudieron leer, cada una entre comillas; $count es cuántas son.
pins-link-malformed = Se ha ignorado lo que no se pudo leer de las ejecuciones fijadas de la dirección: { $pins }.
# $sent es cuántas fijadas se ejecutaron (5); $dropped, cuántas más contenía la dirección.
pins-link-dropped = Solo se ejecutaron las primeras { $sent } ejecuciones fijadas de la dirección; se omitieron { $dropped } más.
# Una ejecución que no se pudo fijar: la primera de una lista (las demás siguen con pins-rejected-next,
# separadas por punto y coma). $scenario es su escenario; $reason, el motivo.
pins-rejected-first = No se pudo fijar { $scenario }: { $reason }
pins-rejected-next = no se pudo fijar { $scenario }: { $reason }
# La frase de las ejecuciones que no se pudieron fijar; $list las contiene (pins-rejected-first, pins-rejected-next).
pins-rejected = { $list }.
# Por qué no se fijó una ejecución: la fijación se canceló antes de empezar, o mientras se ejecutaba.
pins-reason-unrun = sin ejecutar: se canceló la fijación
pins-reason-cancelled = cancelada

## Lists in messages

# Una lista cortada tras sus primeros elementos; $list los contiene, $count es cuántos más hay.
list-more = { $list }… y { $count } más

## The run's status line and messages

# $samples es el número de muestras que calcula la ejecución.
run-status-starting = Ejecutando { $samples } muestras…
run-status-progress = Ejecutando: { $done } de { $total } muestras
# $ms es cuánto tardó la ejecución, en milisegundos.
run-status-done = { $rows } muestras en { $ms } ms
run-status-ran-away = Desbocada: { $rows } muestras en { $ms } ms
run-status-stopped = Detenida tras { $rows } muestras
# $percent es cuánto de la ejecución se completó (45).
run-status-cancelled = Cancelada al { $percent } %
run-status-worker-failed = Detenida: falló el hilo de simulación
# $reason es la explicación del núcleo de por qué se detuvo la ejecución; $rows, las muestras calculadas antes.
run-stopped-early = La ejecución se detuvo antes de tiempo: { $reason }. Las gráficas muestran las { $rows } muestras anteriores.
# $warning es la frase del núcleo que dice que la ejecución se desbocó.
run-ran-away = { $warning } Las gráficas muestran lo que hizo el motor.
run-worker-not-started = No se pudo iniciar el hilo de simulación ({ $reason }). Vuelve a cargar la página para reintentarlo.
run-worker-failed = El hilo de simulación falló ({ $reason }). Se ha reiniciado; pulsa «Ejecutar» para reintentarlo.
# $pins enumera los escenarios de las ejecuciones fijadas, separados por punto y coma.
run-worker-failed-pins = El hilo de simulación falló ({ $reason }). Se ha reiniciado; pulsa «Ejecutar» para reintentarlo. Se descartaron las ejecuciones fijadas: { $pins }.
# $language es el código del idioma solicitado (de).
page-language-failed = La página no pudo cargar sus mensajes para el idioma { $language } ({ $reason }): se muestra en inglés.
page-messages-failed = No se pudo cargar el resto de los textos de la página ({ $reason }). Las herramientas, las lecciones y el recorrido los necesitan: al usar una se vuelve a intentar.
page-challenge-tools-failed = No se pudieron cargar el editor y la calificación de la pestaña «Reto»: { $reason }. Vuelve a abrir la pestaña para reintentarlo.
page-lesson-map-failed = No se leyó el mapa de la lección: { $reason }.
# $lesson es el nombre que pedía la dirección; $lessons enumera los nombres de las lecciones.
page-no-lesson = No hay ninguna lección llamada '{ $lesson }'. Lecciones: { $lessons }.
# Por qué no se pudo comparar el enlace de una lección con la ejecución de la lección: completan la
# frase del panel de la lección «Este enlace contiene ajustes propios, …: …».
lesson-differences-refused = el núcleo rechazó algunos de ellos ({ $reason })
lesson-differences-uncompared = no se pudieron comparar con ella

## Why the simulation worker failed (the $reason of the messages above)

worker-unknown-error = error desconocido
worker-unreadable = no se pudo leer uno de sus mensajes
# $error es el error del navegador; $panic, el mensaje propio del núcleo.
worker-crash-panic = { $error }; pánico de Rust: { $panic }
worker-crash-memory = { $error }; lo más probable es que el núcleo se quedara sin memoria
# Falló un hilo del conjunto de los análisis; $reason dice por qué.
pool-worker-failed = falló un hilo de cálculo ({ $reason })
pool-worker-failed-restart = falló un hilo de cálculo ({ $reason }); la próxima ejecución arranca uno nuevo
# $reason es el error del navegador.
worker-tools-not-loaded = No se pudieron cargar las herramientas ({ $reason }): comprueba la conexión y vuelve a intentarlo.
# $reason es el error del núcleo.
compare-failed = La comparación falló: { $reason }
compare-running = Ejecutando ambos predictores…

## Exports

export-csv-starting = Exportando CSV…
export-csv-progress = Exportando CSV: { $rows } de { $total } filas
export-csv-done = CSV exportado: { $total } filas
export-csv-cancelled = Exportación CSV cancelada
export-csv-cancelled-by-run = Se canceló la exportación CSV: empezó una nueva ejecución.
export-csv-stopped = Exportación CSV detenida
export-csv-failed-status = La exportación CSV falló
# $reason es el error del núcleo, o export-csv-gone.
export-csv-failed = La exportación CSV falló: { $reason }.
export-csv-gone = el hilo de simulación ya no conserva esta ejecución; ejecútala de nuevo
# $megabytes es cuánto CSV llegó a guardar el navegador; $error, el nombre del error del navegador;
# $command, la orden que exporta la ejecución (no se traduce).
export-csv-refused = El navegador se negó a guardar más de { $megabytes } MB de CSV ({ $error }). Exporta esta ejecución con la línea de órdenes: { $command }
export-png-not-ready = Estas gráficas aún se están dibujando; expórtalas dentro de un momento.

## Sharing

share-link-copied = Enlace copiado: reproduce esta ejecución bit a bit.
# $link es la dirección de la página.
share-copy-this-link = Copia este enlace: { $link }
# El título de un marco insertado, que leen los lectores de pantalla: $preset es el nombre del preajuste; $plots, los identificadores de las gráficas (speed, flux).
share-embed-title = IM Lab: { $preset }, { $plots }
# $plots enumera los identificadores de las gráficas (speed, flux); $count es cuántas son.
share-embed-copied =
    Código para insertar copiado: { $count ->
        [one] la gráfica
       *[other] las gráficas
    } { $plots } de esta ejecución (las gráficas visibles de «Trayectorias»). Pégalo en una diapositiva o en la página de un curso.
# $code es el código HTML que hay que copiar.
share-embed-copy-this =
    Copia este código para insertar { $count ->
        [one] la gráfica
       *[other] las gráficas
    } { $plots } de esta ejecución (las gráficas visibles de «Trayectorias»): { $code }
# $names enumera los identificadores de gráfica desconocidos que pedía la dirección, cada uno entre comillas, y $count cuántos son;
# $shown, las gráficas que se muestran en su lugar; $plots, los identificadores de todas las gráficas.
embed-unknown-plots = No hay ninguna gráfica llamada { $names }; se muestran { $shown }. Gráficas: { $plots }.

## A result of an earlier scenario than the settings' ($scenario is that scenario)


## A step's own law (the settings form and the walkthrough)

# $step es el número del paso (de 1 a 4); v{ $step } nombra su ley de control (v1).
law-paper-default = Aún no hay una ley propia: este paso ejecuta el v{ $step } del artículo.

## The settings form

settings-group-reference = Referencia
settings-group-controller = Controlador: backstepping o IFOC clásico
settings-group-gains = Ganancias del backstepping
settings-group-observer = Observador (EKF)
settings-group-noise = Ruido y semilla
settings-group-plant = Planta: el motor simulado
settings-group-model = Modelo: lo que suponen el EKF y el controlador
settings-group-load = Carga desconocida: un escalón o una tabla de puntos
settings-group-limits = Límite de tensión (caja), valor nominal, duración y temporización
settings-group-drive = Accionamiento: retardo de cálculo, límite del inversor y PWM
settings-group-law = Tus propias leyes para los pasos del backstepping (vacío: las del artículo)
# Los valores que admite un campo, bajo él y en su información emergente (settings-allowed).
settings-allowed-formula = una fórmula con los nombres que enumera «Escribir este paso» del recorrido por el diseño; vacío: la ley del artículo
# $min y $max son el valor mínimo y el máximo ($max con la unidad del campo: 20 s), $op es < o ≤,
# $key la clave del campo (duration).
settings-allowed-range = { $min } { $op } { $key } ≤ { $max }
# Una tabla de puntos: como mucho $points puntos; $min y $max acotan los valores ($max con su unidad).
settings-allowed-table = hasta { $points } puntos t:value, como 0:0,0.1:100, con tiempos crecientes desde 0; valores de { $min } a { $max }
settings-allowed-whole = { $min } { $op } { $key } ≤ { $max }, número entero
# $values es lo que admite el campo (settings-allowed-range, o sus opciones: euler | rk4).
settings-allowed = permitido: { $values }
# $list contiene los motivos del núcleo, separados por punto y coma.
settings-link-rejected = Se rechazaron algunos ajustes de la dirección y se dejaron con los valores del preajuste: { $list }.
# $preset es el preajuste que se muestra en su lugar.
settings-link-refused = Se rechazó el escenario de la dirección: { $reason }. Se muestra { $preset } en su lugar.
# $description es la descripción del preajuste que da el núcleo; $fields enumera las claves de los ajustes cambiados (k1, duration).
settings-preset-changed = Preajuste { $preset }: { $description }. Esta ejecución cambia { $fields }, así que lo que la descripción del preajuste dice de su ejecución no tiene por qué cumplirse en esta.
settings-idle = { $changed } Ajustes ignorados: { $idle }.
settings-idle-separator = {"; "}

## The figures strip and the key figures

# Una corriente como múltiplo de la corriente nominal del motor: $value es la corriente (20,33 A),
# $ratio el múltiplo (5,08), $rated la corriente nominal (4).
figures-to-rated = { $value } ({ $ratio }× los { $rated } A nominales)
# El NIS medio ($value) y su banda del 95 %, de $low a $high.
figures-nis-inside = { $value } (banda del 95 % { $low }–{ $high }: dentro)
figures-nis-outside = { $value } (banda del 95 % { $low }–{ $high }: fuera)
# La información emergente de una cifra: $value es su valor exacto con su unidad; $window, las palabras del núcleo para la parte de la ejecución que abarca.
figures-exact = exacto: { $value }; { $window }
# La información emergente de una cifra que la ejecución no alcanzó: $reason son las palabras del núcleo para ello.
figures-no-value = sin valor: { $reason }; { $window }
# Si un valor final se había establecido al terminar la ejecución. $rate, $scatter, $tolerance y $to-go
# son valores con su unidad (0,5 rad/s).
figures-trend-settled = establecido al final de la ejecución
figures-trend-ran-away = la ejecución se desbocó: no es un valor final
figures-trend-drifting = a la deriva con la estimación de la carga o de R_r que el EKF modela como paseo aleatorio: una ejecución más larga termina en otro valor
figures-trend-fluctuating = fluctúa en ±{ $scatter }: la última muestra no es un valor final
figures-trend-changing = aún cambiando: { $rate } por s al final; ejecuta durante más tiempo
figures-trend-changing-to-go = aún cambiando: { $rate } por s al final; ejecuta durante más tiempo (faltan unos { $to-go })
# La información emergente de la tendencia de un valor final: $ms es la longitud del final de la ejecución al que se ajusta la recta.
figures-trend-fit = recta por los últimos { $ms } ms: { $rate } por s, con una dispersión de las muestras de { $scatter } a su alrededor; establecido significa que la recta se mueve menos de { $tolerance } y que cuatro veces la dispersión cabe en ese margen
figures-trend-fit-approach = recta por los últimos { $ms } ms: { $rate } por s, con una dispersión de las muestras de { $scatter } a su alrededor; las medias de las tres últimas décimas se acercan a un valor que está a { $to-go }; establecido significa que la recta se mueve menos de { $tolerance } y que cuatro veces la dispersión cabe en ese margen
# La fila de cifras clave: $value es un valor con su unidad; $ratio, un múltiplo de la corriente nominal.
figures-key-peak = |i_s| de pico { $value } ({ $ratio }× la nominal)
figures-key-final =
    ω − ω_d final { $value } ({ $trend ->
        [settled] establecido
        [changing] aún cambiando
        [drifting] a la deriva
        [fluctuating] fluctuante
       *[ran-away] desbocada
    })
figures-key-nis-inside = NIS medio { $value } (dentro de su banda del 95 %)
figures-key-nis-outside = NIS medio { $value } (fuera de su banda del 95 %)
# La alternativa textual de las gráficas lleva las cifras: $figures las enumera, separadas por punto y coma.
figures-caption = Cifras de esta ejecución: { $figures }.

## The plots

plot-speed = Velocidad del rotor
plot-speed-reference = ω_d referencia
plot-speed-estimated = ω̂ estimada
plot-speed-true = ω real
plot-speed-error = Error de seguimiento de velocidad ω − ω_d
plot-flux = Módulo del flujo rotórico
plot-flux-target = √ψ_d consigna
plot-flux-estimated = |φ̂| estimado
plot-flux-true = |φ| real
plot-current = Corrientes estatóricas
plot-current-a-estimated = î_sa estimada
plot-current-b-estimated = î_sb estimada
plot-current-a-true = i_sa real
plot-current-b-true = i_sb real
plot-voltage = Tensiones estatóricas aplicadas (tras el límite)
# Las líneas del límite de tensión en la gráfica de tensión.
plot-voltage-limit-high = +límite
plot-voltage-limit-low = −límite
plot-z13 = Errores de seguimiento
# «dcha.»: la serie se lee en el eje derecho de la gráfica.
plot-z13-flux = z3 = |φ̂|² − ψ_d (Wb², dcha.)
plot-z24 = Errores de control virtual
plot-z24-torque = z2 error de par (rad/s²)
plot-z24-flux = z4 error de la derivada del flujo (Wb²/s, dcha.)
plot-est = Errores de estimación
plot-est-flux = |φ| − |φ̂| (Wb, dcha.)
# El título de una gráfica del backstepping ($title) cuando el IFOC clásico acciona el motor.
plot-not-driving = { $title } (calculado para comparar; no acciona el motor)
# La alternativa textual de una gráfica: $title es su título, $unit la unidad de su eje, $signals los nombres de sus series.
plot-caption = { $title }, en { $unit } frente al tiempo t en s. Señales: { $signals }.
plot-caption-two-axes = { $title }, en { $unit } (izquierda) y { $unit2 } (derecha) frente al tiempo t en s. Señales: { $signals }.
plot-caption-keys = Da el foco a la gráfica y usa las teclas de flecha para inspeccionar la ejecución muestra a muestra (Mayús: 1 % de la ventana).

## The Analysis tab


## The Lessons tab


## The Challenge tab


## The challenge panel's controls, built with the page

challenge-progress =
    .aria-label = Ejecuciones del reto completadas
challenge-cancel = Cancelar comprobación
challenge-copy = Copiar enlace de entrega
challenge-open-failed = No se pudo abrir el reto: { $reason }. La página muestra en su lugar el escenario por defecto.
law-checking = Comprobando tu ley frente a la dinámica diseñada…
law-verdict-failed = No se pudo calcular el veredicto sobre tu ley: { $reason }
walkthrough-load-failed = No se pudo cargar el recorrido por el diseño: comprueba la conexión y vuelve a cargar la página.
lesson-panel =
    .aria-label = Lección
challenge-panel =
    .aria-label = Reto
stale-back = Volver a su escenario
