# Los mensajes del núcleo sobre los retos de diseño y su calificación: por qué se rechazó un enlace
# de reto o de entrega, la tarea en texto, el veredicto de cada criterio y la calificación de una
# clase. La CLI los dice en inglés; la página, en el idioma del lector; el CSV de calificaciones los
# guarda en inglés. Las claves, campos, cifras y ajustes (c=1, allow.FIELD, need.FIGURE=OP,
# seeds:A..B, try.FIELD, mean_nis, load.torque = 0) son las propias palabras del enlace: se
# mantienen tal cual. La entrada citada conserva sus comillas.

## A challenge or submission link refused

# $key es la clave del enlace (title, vary, try.k1…); $value, el texto que contiene.
challenge-not-percent-encoded = campo '{ $key }' = '{ $value }': no es UTF-8 válido codificado por porcentajes
challenge-too-long = el reto ocupa { $bytes } bytes, más de los { $max } bytes ({ $kib } KiB) permitidos
# $names enumera los nombres de los retos incorporados.
challenge-unknown = '{ $name }' no es ni un enlace de reto ni un reto incorporado ({ $names })
challenge-unsupported-version = campo 'c' = '{ $value }': versión del reto no admitida; se admite: { $version }
# $fields enumera las claves que puede contener un enlace de reto.
challenge-unknown-key = '{ $key }' no es un campo del reto ({ $fields })
challenge-missing = falta el campo '{ $key }'
# $name es el nombre del reto incorporado.
challenge-builtin-extra = el campo '{ $key }' no puede seguir a challenge={ $name }: el enlace de un reto incorporado solo contiene challenge=NAME y las partes try.FIELD del estudiante
# $stray son los caracteres escritos antes de c=; $count, cuántos son.
challenge-stray = el enlace empieza con { $count ->
        [one] el carácter suelto
       *[other] los caracteres sueltos
    } '{ $stray }' antes de su c={ $version }: { $count ->
        [one] quítalo
       *[other] quítalos
    }
challenge-version-missing = falta el campo 'c' (un reto empieza por c={ $version })
challenge-title-too-long = el campo 'title' tiene { $chars } caracteres, más de los { $max } permitidos
# $error dice por qué se rechazó el escenario base (un mensaje scenario-*).
challenge-bad-base = campo 'base': { $error }
challenge-no-criteria = no hay criterios: añade al menos un need.FIGURE=OP
challenge-too-many-criteria = { $count } criterios, más de los { $max } permitidos
challenge-vary-unused = campo 'vary': ningún criterio usa las variantes (nombra en robust= las cifras de los criterios)
challenge-robust-without-vary = campo 'robust': no hay variantes (añade vary=)
# $key es allow.FIELD; $field, el campo del escenario que nombra.
challenge-allow-unknown-field = campo '{ $key }': '{ $field }' no es un campo del escenario
challenge-allow-formula = campo '{ $key }' = '{ $value }': la ley de un paso se permite como allow.{ $field }=formula
challenge-allow-range = campo '{ $key }' = '{ $value }': se esperaba LO..HI, dos números con LO ≤ HI
# $error dice por qué un extremo del rango no es un valor del campo (un mensaje scenario-*).
challenge-allow-refused = campo '{ $key }' = '{ $value }': { $error }
# $options enumera los nombres del campo, separados por |.
challenge-allow-choice = campo '{ $key }' = '{ $value }': se esperaban nombres de { $options }, sin repetir y separados por |
# $key es need.FIGURE; $figures enumera las cifras que puede nombrar un criterio.
challenge-need-unknown-figure = campo '{ $key }': '{ $figure }' no es una cifra ({ $figures })
challenge-need-band = campo '{ $key }' = 'band': solo mean_nis tiene banda
challenge-need-op = campo '{ $key }' = '{ $value }': se esperaba max:B, min:B, abs:B o band
challenge-need-no-load-step = campo '{ $key }': la base no tiene escalón de carga (load.torque = 0, o en su lugar una tabla de carga)
challenge-vary-seeds = campo 'vary' = '{ $value }': se esperaba seeds:A..B, números enteros con A ≤ B ≤ { $max_seed } y como mucho { $max } semillas
challenge-vary-too-many = campo 'vary': { $count } variantes, más de las { $max } permitidas
# $number cuenta las variantes desde 1; $error dice qué falla en ella (un mensaje scenario-*).
challenge-vary-variant-refused = campo 'vary', variante { $number }: { $error }
challenge-vary-variant-empty = campo 'vary': la variante { $number } está vacía
# $overrides son los ajustes de la variante (seed=2); $error dice por qué no se aplican.
challenge-variant-refused = variante '{ $overrides }': { $error }
# $value es la lista de robust=; $figure, el nombre de ella que no es la cifra de un criterio.
challenge-robust-unknown = campo 'robust' = '{ $value }': '{ $figure }' no es la cifra de ningún criterio (o aparece dos veces)
challenge-is-submission = campo 'try.{ $key }': esto es una entrega, no un reto (califícala frente a su reto)
challenge-another = la entrega pertenece a otro reto (el texto de su reto es distinto)
challenge-try-not-allowed = el campo '{ $field }' no está permitido
challenge-try-not-number = campo 'try.{ $field }' = '{ $value }': no es un número
# $setting es el ajuste del estudiante (k1=6000); $range, el permitido (300..5000).
challenge-try-outside = { $setting } está fuera de { $range }
# $options enumera los nombres permitidos, separados por |.
challenge-try-not-option = { $setting } no está entre { $options }
challenge-compose-range-and-options = campo '{ $key }': indica LO y HI (un rango) u opciones (choices), no ambas cosas
challenge-judge-runs = el reto tiene { $runs ->
        [one] { $runs } ejecución
       *[other] { $runs } ejecuciones
    } (la nominal y { $variants ->
        [one] { $variants } variante
       *[other] { $variants } variantes
    }), { $measured ->
        [one] { $measured } medida
       *[other] { $measured } medidas
    }

## The task in words

challenge-untitled = Reto de diseño
# El título del reto, tal como lo escribió su autor.
challenge-title = { $title }
# $base es la cadena del escenario.
challenge-brief-start = Parte del escenario { $base }
challenge-brief-nothing-allowed = No se puede cambiar nada: la base se evalúa tal como está.
challenge-brief-allowed = Solo puedes cambiar:
# Un campo que el estudiante puede cambiar: $field, su nombre (rellenado hasta una columna); $range,
# lo que puede valer (un mensaje challenge-brief-range, -one-of o -formula); $now, el valor de la
# base; $doc, el campo en palabras.
challenge-brief-allow = { $field } { $range } (ahora { $now }) — { $doc }
# $hi lleva su unidad, si la tiene.
challenge-brief-range = de { $lo } a { $hi }
# $options enumera los nombres.
challenge-brief-one-of = uno de { $options }
challenge-brief-formula = una fórmula propia
challenge-brief-formula-unit = una fórmula propia, en { $unit }
challenge-brief-needs = Tu diseño debe cumplir:
# Un criterio: $number los cuenta desde 1; $label es la cifra en palabras; $figure, su nombre;
# $bound, un mensaje challenge-brief-at-most, -at-least, -within o -band; $settled es yes para un
# valor final, que debe haberse establecido; $robust es yes cuando debe cumplirse también en cada
# variante.
challenge-brief-need = { $number }. { $label } ({ $figure }): { $bound }{ $settled ->
        [yes] , y ya establecido al final de la ejecución
       *[no] {""}
    }{ $robust ->
        [yes] {" "}— en la ejecución nominal y en cada variante
       *[no] {""}
    }
# $bound lleva su unidad, si la tiene.
challenge-brief-at-most = como máximo { $bound }
challenge-brief-at-least = como mínimo { $bound }
challenge-brief-within = dentro de ±{ $bound }
challenge-brief-band = dentro de la banda del 95 % de un filtro consistente (de mean_nis_low a mean_nis_high)
# $first y $last son la primera y la última semilla de ruido (seed=2…).
challenge-brief-variants-seeds = Variantes (aplicadas sobre tus ajustes; cuenta la peor ejecución): semillas de ruido { $first } a { $last }
# $overrides enumera los ajustes de cada variante, separados por punto y coma.
challenge-brief-variants = Variantes (aplicadas sobre tus ajustes; cuenta la peor ejecución): { $overrides }
challenge-brief-load-recovery = Tiempo de recuperación tras el escalón de carga: el tiempo desde el escalón de carga (t = { $time } s) hasta que |ω − ω_d| queda, hasta el final de la ejecución, dentro del mayor de estos dos valores: el 1 % de |ω_d| en el escalón o 0,5 rad/s (aquí { $band } rad/s, con ω_d = { $speed } rad/s); si al final sigue fuera, no se ha recuperado.
challenge-brief-settled = Un valor final solo cuenta si se ha establecido: un valor que aún cambie en la última décima de la ejecución no supera el criterio.
# Un número y su unidad: "0.004 s".
challenge-quantity = { $value } { $unit }

## A criterion's bound and why it fails

# $bound lleva su unidad, si la tiene: "≤ 0.004 s".
challenge-bound-max = ≤ { $bound }
challenge-bound-min = ≥ { $bound }
challenge-bound-abs = |·| ≤ { $bound }
challenge-bound-band = dentro de su banda del 95 %
# $failure dice por qué falló la ejecución (en inglés hasta que se traduzcan los mensajes de la
# simulación).
challenge-run-unfinished = la ejecución no terminó
challenge-reason-run-failed = la ejecución falló: { $failure }
# $cause dice por qué la cifra no es un número (en inglés hasta que se traduzca el informe de la
# ejecución).
challenge-reason-not-finite = { $cause }
challenge-reason-before-load-step = sin medir: la ejecución termina antes del escalón de carga
challenge-reason-not-measured = sin medir en esta ejecución (p. ej., un escalón que nunca se establece dentro del 2 %)
challenge-reason-no-band = sin medir: no hay banda de NIS en esta ejecución
challenge-reason-above-bound = por encima de la cota
challenge-reason-below-bound = por debajo de la cota
challenge-reason-beyond-bound = fuera de la cota
challenge-reason-below-band = por debajo de la banda
challenge-reason-above-band = por encima de la banda
challenge-reason-not-recovered = sin recuperar al final de la ejecución
challenge-reason-still-changing = aún cambiando

## A class's grading: each submission's status (in the grades' CSV too) and the class's file

grade-row-ok = correcta
# $reason dice por qué el enlace no es una entrega bien formada.
grade-row-malformed = mal formada: { $reason }
# $reason nombra el campo que fijó el estudiante y que no está permitido o está fuera de su rango.
grade-row-refused = rechazada: { $reason }
grade-row-another = otro reto
# $reason dice por qué falló una ejecución (en inglés hasta que se traduzcan los mensajes de la
# simulación).
grade-row-run-failed = la ejecución falló: { $reason }
grade-internal-error = error interno
# $encoding es el nombre de la codificación con que se leyó el archivo (UTF-8, windows-1252…).
grade-line-undecoded = la línea { $line } no es { $encoding } válido
grade-line-unclosed = línea { $line }: un campo entre comillas no se cierra antes del final del archivo
grade-line-fields = la línea { $line } tiene { $fields ->
        [one] { $fields } campo
       *[other] { $fields } campos
    }, y la cabecera, { $header }
grade-no-link = sin enlace
# $error dice por qué se rechazó el reto.
grade-challenge-refused = reto: { $error }
grade-file-not-text = el archivo no es de texto (contiene bytes NUL: ¿una hoja de cálculo o un documento?); guárdalo como archivo de texto con los enlaces, uno por línea, o como CSV
grade-file-utf16 = el archivo está en UTF-16 sin marca de orden de bytes; guárdalo en UTF-8
grade-file-header-undecoded = la línea { $line }, la cabecera del CSV, no es { $encoding } válido
# $columns enumera los encabezados de columna del archivo, cada uno entre comillas.
grade-file-no-link-column = no hay ninguna columna de enlaces en esta exportación CSV (sus columnas: { $columns }); pon a la columna de enlaces el encabezado 'link'
grade-file-links-everywhere = todas las columnas { $columns } contienen enlaces; pon el encabezado 'link' a la que hay que calificar
grade-file-link-headers = las columnas { $columns } tienen todas encabezado de enlaces; deja solo una

## Resuming an interrupted grading (imlab grade --resume): why its earlier output is refused

grade-resume-not-utf8 = no es texto UTF-8, así que no contiene las calificaciones de esta clase
# $header es la línea de cabecera del CSV que escribe esta calificación.
grade-resume-header = su primera línea no es la cabecera de esta calificación, '{ $header }': contiene las calificaciones de otro reto o de otro archivo de la clase
grade-resume-too-many-rows = contiene más filas que entregas tiene el archivo de la clase ({ $rows })
grade-resume-row = su fila { $row } no es la de la línea { $line } ('{ $link }') del archivo de la clase: contiene las calificaciones de otro archivo de la clase
# $what es uno de los mensajes grade-kept-*.
grade-kept-differs = su fila { $row } (línea { $line } del archivo de la clase) no coincide con lo que da calificarla de nuevo: { $what }; se editó después de calificarse, o la calificó otra versión de imlab
# $column es el nombre de la columna del CSV (status, settling_time_pass…).
grade-kept-cell = su columna { $column } contiene '{ $found }', no '{ $expected }'
grade-kept-extra = tiene '{ $extra }' tras su última columna
grade-kept-short = le faltan sus columnas a partir de { $column }
