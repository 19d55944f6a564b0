# Los textos de las herramientas de análisis y de retos: la pestaña «Análisis» (barridos, bandas de
# semillas, mapa de errores de modelo), el panel del reto que ve el estudiante y la pestaña «Reto»
# que usa el profesor (el editor, su comprobación y la calificación de una clase).

## Frequency-response sweep: the Bode plots and the table (web/analysis/analysis.js)

sweep-plot-magnitude = Módulo de ω/ω_d
sweep-plot-phase = Fase de ω respecto a ω_d
sweep-axis-degrees = grados
sweep-series-unsettled = { $variant }, no establecido
sweep-unsettled =
    { $count ->
        [one] { $count } punto no se había establecido (marcadores huecos): el ancho de banda y la fase a 200 Hz nunca se leen en él. Con ejecuciones más largas puede establecerse.
       *[other] { $count } puntos no se habían establecido (marcadores huecos): el ancho de banda y la fase a 200 Hz nunca se leen en ellos. Con ejecuciones más largas pueden establecerse.
    }
sweep-unsettled-point = { $variant }, { $frequency }: { $reason }
sweep-hz = { $value } Hz
sweep-degrees = { $value } °
sweep-head-variant = variante
sweep-head-bandwidth = ancho de banda a −3 dB
sweep-head-phase = fase a 200 Hz
sweep-head-saturation = peor saturación
sweep-head-failed = puntos fallidos
sweep-head-unsettled = puntos no establecidos
sweep-head-peak = |i_s| de pico (A)
sweep-bandwidth-unsettled = no se indica: dependería de un punto que no se había establecido
sweep-bandwidth-below = por debajo de la frecuencia más baja
sweep-not-reached = no se alcanza en la malla
sweep-phase-not-reached-settled = no la alcanzan los puntos establecidos
sweep-unsettled-cell = { $count }: { $frequencies }
sweep-peak-none = sin medir
sweep-peak = { $peak } (nominal { $rated })
sweep-peak-over = { $peak } (nominal { $rated }); por encima del valor nominal en { $count }: { $frequencies }

## Seed bands: the plots (web/analysis/analysis.js)

seeds-plot-error = Error de velocidad ω − ω_d según las semillas (media, mínimo, máximo)
seeds-plot-estimate = Error de estimación ω − ω̂ según las semillas (media, mínimo, máximo)
seeds-series-mean = media
seeds-series-min = mín.
seeds-series-max = máx.

## Frequency-response sweep: the form's run, status line and link (web/analysis/sweeps.js)

sweep-workers-invalid = workers = { $value }: se esperaba un número entero de 1 a 8.
sweep-status-checking = Comprobando el barrido…
sweep-refused = { $reason }.
sweep-not-run = El barrido no se ejecutó: los ajustes no son válidos o no se admiten aquí; el mensaje de arriba indica por qué.
sweep-status-running = Ejecutando el barrido…
sweep-status-done =
    { $workers ->
        [one] { $variants } × { $points } ejecuciones en { $ms } ms con { $workers } hilo de cálculo.
       *[other] { $variants } × { $points } ejecuciones en { $ms } ms con { $workers } hilos de cálculo.
    }
sweep-status-cancelled = Barrido cancelado.
sweep-status-failed = El barrido falló: { $reason }
sweep-link-refused = El barrido de la dirección ({ $link }) no se ejecutó: { $reason }.

## Seed runs: the form's run and status line (web/analysis/seeds.js)

seeds-count-invalid = seeds = { $value }: se esperaba un número entero de semillas de 1 a 1000.
seeds-not-run = Las semillas no se ejecutaron: los ajustes no son válidos o no se admiten aquí; el mensaje de arriba indica por qué.
seeds-status-starting = Ejecutando las semillas…
seeds-status-running = Ejecutando las semillas: { $percent } %
seeds-status-done = Completadas { $runs } de { $seeds } semillas ({ $first } a { $last }).
seeds-status-cancelled = Ejecución de las semillas cancelada.
seeds-status-failed = El barrido de semillas falló: { $reason }

## Model-error map: its run and status line (web/analysis/robust.js)

map-status-starting = Ejecutando { $cells } celdas × { $seeds } semillas…
map-status-running = Ejecutando el mapa: { $done } de { $total } ejecuciones.
map-refused = El mapa no se ejecutó: { $reason }.
map-not-run = El mapa no se ejecutó: los ajustes no son válidos o no se admiten aquí; el mensaje de arriba indica por qué.
map-failed = El mapa falló: { $reason }
map-status-cancelled = Mapa cancelado: se muestran las { $finished } de { $cells } celdas terminadas; las demás no se ejecutaron.
map-status-done = { $cells } celdas × { $seeds } semillas ({ $first }–{ $last }) en { $seconds } s.
map-link-refused = El mapa de la dirección ({ $link }) no se ejecutó: { $reason }.

## Model-error map: the plot over one axis (web/analysis/map-plot.js)

map-plot-title = { $figure } según las semillas: mediana y banda mín.–máx.
map-series-min = mín.
map-series-median = mediana
map-series-max = máx.
map-gap = { $value } ({ $ranAway } de { $runs } semillas)
map-gap-percent = { $value } % ({ $ranAway } de { $runs } semillas)
map-gaps = No se dibujan, porque algunas semillas se desbocaron ahí: { $cells }.

## Model-error map: the table and its key (web/analysis/map-table.js, map-colours.js)

map-figure-unit = { $figure } ({ $unit })
map-cell-not-run = sin ejecutar
map-cell-title = { $scenario }: { $ranAway } de { $runs } semillas desbocadas, { $inconsistent } inconsistentes, { $overRating } por encima de la corriente nominal, { $unsettled } con el error de velocidad sin establecer al final; { $figure } de { $min } a { $max }
map-grid-corner = { $rows } ↓ / { $columns } →
map-head-median = mediana
map-head-range = mín. – máx.
map-range = { $min } – { $max }
map-key = { $figure }, mediana de las semillas que no se desbocaron ({ $seeds } semillas); color: { $colours }. ✕ k/N: la ejecución se desbocó en k de las N semillas (lo indica la propia página de la ejecución, o el motor o la estimación salieron de sus cotas), nunca se colorea como un valor; ⚠ el EKF fue inconsistente; I↑ k/H: de las H semillas que se mantuvieron, k consumieron más corriente que la nominal del motor tras el arranque; ~ k/H: k terminaron con el error de velocidad sin establecer (ambas con contorno y coloreadas según su mediana). Haz clic en una celda para ejecutarla (semilla { $seed }).
map-scale-diverging = de azul −{ $max } a rojo { $max }, pasando por blanco en 0
map-scale-log = escala logarítmica de claro { $min } a oscuro { $max }
map-scale-linear = escala lineal de claro { $min } a oscuro { $max }
map-scale-none = ninguna

## Challenge panel: what a student sees of a challenge link (web/challenge/challenge.js)

challenge-heading = Reto
challenge-link-rejected = Este enlace de reto se ha rechazado: { $reason }. La página muestra en su lugar el escenario por defecto.
challenge-submission-another = Este enlace de entrega pertenece a otro reto (se editó su parte del reto): no se ha calificado.
challenge-submission-refused = Este enlace de entrega no se ha admitido: { $reason }. No se ha calificado; la tarea parte de sus ajustes base.
challenge-submission-rejected = Este enlace de entrega se ha rechazado: { $reason }. No se ha calificado; la tarea parte de sus ajustes base.
challenge-run = Ejecutar y comprobar
challenge-settings = Tus ajustes
challenge-settings-hint = Solo se pueden cambiar { $fields }; el reto bloquea los demás ajustes.
challenge-checklist = Lista de comprobación
challenge-task = La tarea completa
challenge-verdict-pending = Aún sin comprobar: se está calculando la primera ejecución.
challenge-need-pending = { $label } ({ $figure }): aún sin comprobar
challenge-verdict-link-refused = ✗ Sin calificar: los ajustes del enlace no se admitieron (véase arriba). Cambia los ajustes permitidos y ejecuta.
challenge-verdict-cancelled = ✗ Comprobación cancelada: sin calificar. Ejecuta de nuevo para comprobar.
challenge-verdict-failed = ✗ La comprobación falló: { $reason }. Sin calificar.
challenge-verdict-edited = Este no es el reto incorporado { $name }: sus condiciones se han editado.
challenge-verdict-rerun = La ejecución en pantalla no es la calificada (difiere un ajuste bloqueado): la ejecución nominal se ha repetido con los ajustes del reto y los permitidos que has elegido.
challenge-checking =
    Comprobando: { $done } de { $runs ->
        [one] { $runs } ejecución
       *[other] { $runs } ejecuciones
    } (la ejecución nominal y { $variants ->
        [one] { $variants } variante
       *[other] { $variants } variantes
    })…
challenge-refusal-not-run = Tus ajustes no son una respuesta válida: { $reason }. No se han ejecutado.
challenge-verdict-not-run = ✗ Sin ejecutar. Tus ajustes no son una respuesta válida: { $reason }.
challenge-refusal-not-graded = Tus ajustes no son una respuesta válida: { $reason }. No se han calificado.
challenge-verdict-not-graded = ✗ Sin calificar. Tus ajustes no son una respuesta válida: { $reason }.
challenge-copied = Enlace de entrega copiado: reproduce estas ejecuciones bit a bit.
challenge-copy-by-hand = Copia este enlace de entrega: { $url }

## Challenge panel: the checklist and its controls (web/challenge/checklist.js)

checklist-not-measured = sin medir
checklist-never = nunca (∞)
checklist-value-unit = { $value } { $unit }
checklist-passed =
    { $criteria ->
        [one] ✓ Superado: se cumple el criterio.
       *[other] ✓ Superado: se cumplen los { $criteria } criterios.
    }
checklist-passed-variants =
    { $criteria ->
        [one] ✓ Superado: se cumple el criterio (la ejecución nominal y { $variants ->
            [one] { $variants } variante
           *[other] { $variants } variantes
        }).
       *[other] ✓ Superado: se cumplen los { $criteria } criterios (la ejecución nominal y { $variants ->
            [one] { $variants } variante
           *[other] { $variants } variantes
        }).
    }
checklist-failed = ✗ No superado: { $met } de { $criteria } criterios cumplidos.
checklist-failed-variants =
    ✗ No superado: { $met } de { $criteria } criterios cumplidos (la ejecución nominal y { $variants ->
        [one] { $variants } variante
       *[other] { $variants } variantes
    }).
checklist-pass = ✓ supera
checklist-fail = ✗ no supera
checklist-criterion = { $label }: { $value }, requiere { $bound }
checklist-criterion-worst = { $label }: { $value }, requiere { $bound } (peor ejecución: { $run })
checklist-reason = — { $reason }

## Challenge panel: the knobs of the allowed settings (web/challenge/knobs.js)

challenge-knob-doc = { $doc } ({ $unit })
challenge-allowed-choice = permitido: uno de { $options }
challenge-allowed-formula = permitido: una fórmula propia ({ $unit }; «Escribir este paso», en el recorrido por el diseño, enumera los nombres)
challenge-allowed-range = permitido: de { $lo } a { $hi }
challenge-allowed-range-unit = permitido: de { $lo } a { $hi } { $unit }

## Challenge panel: the header, where the challenge comes from (web/challenge/origin.js)

challenge-kind = Reto
challenge-origin-builtin = Reto incorporado
challenge-origin-mine = Creado por ti en este navegador, que compuso exactamente este reto (cotas y título sin cambios)
challenge-origin-other = No es un reto que hayas creado en este navegador
challenge-origin-unknown = Este navegador no guarda registro de los retos que ha compuesto
challenge-fingerprint = Huella
challenge-edited = Editado: este enlace lleva el título del reto incorporado { $name }, pero no sus condiciones. Se califica como el reto que es, no como { $name }.

## The built-in challenges, in the Lessons tab (web/challenge/builtins.js)

builtins-open = Abrir el reto { $name }
builtins-failed = No se pudieron listar los retos incorporados.

## Challenge tab: composing a challenge (web/challenge/challenge-compose.js)

compose-intro = El reto parte del escenario de los ajustes (su base); el estudiante solo puede cambiar los campos indicados aquí, dentro de sus rangos, y supera el reto cuando se cumplen todos los criterios. Configura antes el escenario y ejecútalo: los criterios se rellenan a partir de sus cifras, un 20 % más estrictos que esta ejecución.
compose-base = Base:
compose-title = Título
compose-title-default = Reto: { $preset }
compose-make = Crear el enlace del reto
compose-no-run = No hay ninguna ejecución terminada de este escenario de la que tomar las cifras: ejecútalo y pulsa de nuevo «Rellenar desde el escenario actual».
compose-invalid = El reto no es válido: { $reason }
compose-link = Enlace del reto
compose-kept = Este navegador guarda registro de que compuso este reto: el enlace, abierto aquí, dice «Creado por ti en este navegador»; una copia con otra cota u otro título, no.
compose-not-kept = Este navegador no guarda registro de los retos que compone (su almacenamiento o Web Crypto no están disponibles aquí): el enlace, abierto aquí, no puede indicar que lo creaste tú.
compose-copy-link = Copiar enlace del reto
compose-link-copied = Enlace del reto copiado.
compose-link-not-copied = Selecciona el enlace del reto de arriba y cópialo.
compose-open = Abrir como estudiante
compose-brief = La tarea en texto (para una diapositiva o la página del curso)
compose-copy-brief = Copiar la tarea
compose-brief-copied = Tarea copiada.
compose-brief-not-copied = Selecciona la tarea de arriba y cópiala.

## Challenge tab: the composer's rows (web/challenge/compose-rows.js)

compose-allow-legend = Campos que el estudiante puede cambiar
compose-field = Campo
compose-field-option = { $field } — { $doc }
compose-add = Añadir
compose-remove = Quitar
    .aria-label = Quitar { $field }
compose-allow-formula = una fórmula propia del estudiante ({ $unit })
compose-allow-choices = { $field }: opciones (a|b)
compose-allow-from = de
compose-allow-to = a
compose-allow-now-unit = { $unit } (ahora { $value })
compose-allow-now = (ahora { $value })
compose-need-legend = Criterios: las cifras de esta ejecución
compose-need-hint = Con «todas las ejecuciones», el criterio debe cumplirse también en cada variante (cuenta la peor ejecución).
compose-need = { $label } ({ $figure })
compose-need-now = { $label } ({ $figure }) — ahora { $value }
compose-need-now-unit = { $label } ({ $figure }) — ahora { $value } { $unit }
compose-need-op = { $figure }: tipo de cota
compose-need-bound = { $figure }: cota
compose-need-bound-unit = { $figure }: cota en { $unit }
compose-op-max = como máximo
compose-op-min = como mínimo
compose-op-abs = |valor| como máximo
compose-op-band = dentro de su banda del 95 %
compose-bound-none = ninguna
compose-need-all-runs = todas las ejecuciones
compose-vary-legend = Variantes de robustez (opcional)
compose-vary = Variantes: seeds:A..B (las semillas de A a B), o ajustes aplicados sobre los del estudiante, separados por |
    .placeholder = seeds:2..10  o  model.j=0.016|model.j=0.024
compose-vary-seeds = Semillas de 2 a 10

## Challenge tab: the check that a design passes (web/challenge/compose-check.js)

compose-check-progress =
    .aria-label = Comprobación del reto: ejecuciones completadas
compose-check-cancel = Cancelar comprobación
compose-check-starting = Comprobando si algún diseño dentro de los rangos permitidos supera el reto…
compose-check-running =
    Comprobando si algún diseño dentro de los rangos permitidos supera el reto: { $done } de { $runs ->
        [one] { $runs } ejecución
       *[other] { $runs } ejecuciones
    } ({ $designs ->
        [one] { $designs } diseño
       *[other] { $designs } diseños
    })…
compose-check-cancelled = Comprobación cancelada: no se sabe si algún diseño dentro de los rangos permitidos supera el reto. Vuelve a crear el enlace para comprobarlo.
compose-check-failed = La comprobación falló: { $reason }.
compose-check-base-design = la base, sin cambiar ningún campo
compose-check-failure = { $figure }: { $value } frente a { $bound }
compose-check-failure-changing = { $figure }: { $value } frente a { $bound }, aún cambiando
compose-check-unmeasured = { $figure }: { $reason }
compose-check-base-passes = La base supera el reto tal como está: un estudiante que no cambie nada lo supera.
compose-check-base-fails = La base (sin cambiar ningún campo) no supera el reto: { $failures }.
compose-check-tried =
    La comprobación probó { $designs ->
        [one] { $designs } diseño
       *[other] { $designs } diseños
    } en { $runs ->
        [one] { $runs } ejecución
       *[other] { $runs } ejecuciones
    } (como mucho { $budget } ejecuciones): primero la base y después los que cambian menos campos, desde los extremos de los rangos hacia dentro (todas las combinaciones, cuando caben).
compose-check-solvable = ✓ Un diseño dentro de los rangos permitidos supera el reto: { $design } (lo superan { $passing } de los { $tried } diseños probados).
compose-check-unsolved = ✗ Ninguno de los { $tried } diseños probados supera el reto: puede que las cotas sean inalcanzables; el más cercano fue { $design } ({ $failures }).

## Challenge tab: grading a class (web/challenge/grade.js)

grade-refused = Sin calificar: { $reason }.
grade-no-challenge = indica un reto: el nombre de uno incorporado o un enlace de reto
grade-no-file = elige un archivo de la clase o pega los enlaces, uno por línea
grade-no-submission = el archivo no contiene ninguna entrega
grade-read-as = El archivo de la clase se ha leído como { $encoding } (no está en UTF-8).
grade-status-reading = Leyendo el archivo de la clase…
grade-status-grading = Calificando { $total } entregas…
grade-status-grading-kept = Calificando { $total } entregas, { $kept } conservadas de la calificación anterior…
grade-count = Calificadas { $done } de { $total }
grade-status-done = Calificadas { $total } de { $total }: { $passed } superan el reto.
grade-not-stored = El almacenamiento del navegador no ha admitido esta calificación: descárgala ahora.
grade-status-cancelled-kept = Cancelado: { $graded } de { $total } calificadas, guardadas en este navegador; «Calificar» continúa desde ahí.
grade-status-cancelled-lost = Cancelado: { $graded } de { $total } calificadas, sin guardar (el almacenamiento del navegador las rechazó).
grade-status-stopped-kept = La calificación se detuvo: { $reason }. { $graded } de { $total } calificadas, guardadas en este navegador; «Calificar» continúa desde ahí.
grade-status-stopped-lost = La calificación se detuvo: { $reason }. { $graded } de { $total } calificadas, sin guardar (el almacenamiento del navegador las rechazó).
grade-status-cancelled-reading = Cancelado mientras se leía el archivo de la clase: no se ha calificado nada.
grade-downloaded-partial = Descargadas las primeras { $rows } de { $total } filas, en orden: «Calificar» continúa desde donde se detuvo, y { $command } puede completar el archivo.

## Challenge tab: the class's table (web/challenge/grade-table.js)

grade-pending = aún sin calificar
grade-pass = ✓ supera
grade-fail = ✗ no supera
grade-head-line = línea
grade-head-verdict = veredicto
grade-head-link = enlace
grade-value-reason = { $value }: { $reason }
grade-worst-run = { $text } (peor ejecución: { $run })

motor-intro = Estima el circuito equivalente de un motor a partir de la resistencia estatórica en corriente continua, el ensayo en vacío a tensión nominal y el ensayo a rotor bloqueado (IEEE Std 112), como hace imlab motor, e indica qué valores son estimaciones. Después ejecuta el motor como planta y como modelo a la vez, con el diseño derivado de él. Cada ensayo es una lectura: tensión entre líneas, corriente de línea, potencia absorbida y frecuencia, separadas por comas.
motor-rs = resistencia estatórica por fase, ensayo en corriente continua
motor-no-load = ensayo en vacío
motor-locked = ensayo a rotor bloqueado
# La letra de diseño NEMA reparte la dispersión a rotor bloqueado entre estátor y rotor.
motor-nema = letra de diseño NEMA
motor-rated = placa de características: tensión, frecuencia, corriente
motor-j = inercia del rotor
motor-np = pares de polos
motor-run-button = Estimar el circuito
motor-example-button = Rellenar con un ejemplo
motor-example-filled = El formulario contiene una máquina de 2,2 kW y 400 V tal como la anotaría un laboratorio: su placa de características y las lecturas que da su circuito (un laboratorio simulado, no un motor de catálogo).
motor-open = Ejecutar este motor con su diseño derivado
