# Los textos de las herramientas docentes que se muestran antes de cargar las lecciones y el
# recorrido por el diseño: el panel de inspección, el editor de la ley propia de un paso y las notas
# del propio recorrido.

## The inspect panel (inspect-panel.js): every term of the design at one sample

inspect-title = Inspeccionar la muestra k = { $k }, t = { $time } s
inspect-copy = Copiar los valores exactos
inspect-copied = Copiado
inspect-copy-failed = No se pudo copiar: selecciona la tabla
inspect-close = Cerrar (Esc)
inspect-exact = exacto: { $value }
inspect-group-step = Paso { $step }
inspect-group-voltage = Tensión (54) y límite
inspect-group-estimate = Estimación x̂ (k|k)
inspect-group-measured = Medido y real
inspect-term = término
inspect-value = valor
inspect-unit = unidad
inspect-meaning = significado
inspect-gain-caption = Ganancia de Kalman K_k (A⁻¹ × unidad del estado) y L = K_k/Ts (por segundo)
inspect-gain-row = fila

## A step's own law (law-editor.js)

law-write = Escribir este paso
law-names = Los nombres y funciones que puedes usar
law-names-name = nombre
law-names-symbol = símbolo
law-names-unit = unidad
law-names-meaning = significado
law-names-functions = Con + − * / ^ (o · y −), paréntesis, números y las funciones { $functions }.
law-error-at = En el carácter { $at }: { $reason }
law-stale = No es la ley escrita: la ejecución mostrada, este veredicto y la gráfica del residuo corresponden a { $output } = { $law }. { $verdict }
law-stale-after = No es la ley escrita: la ejecución mostrada, este veredicto y la gráfica del residuo corresponden a { $output } = { $law } tras { $previous } = { $previousLaw }. { $verdict }

## The walkthrough (walkthrough.js)

