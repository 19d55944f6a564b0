map-heading = Mapa de errores de modelo
# La introducción del mapa se corta en torno a tres fragmentos de código: plant.*, model.* y un eje
# de ejemplo, plant.rr=-10%..+10%:11. map-intro-start va delante de «plant.*», map-intro-model entre
# «plant.*» y «model.*», map-intro-axes entre «model.*» y el ejemplo, map-intro-example tras él.
map-intro-start = ¿Hasta dónde se mantiene un resultado cuando el motor no es el que suponen el EKF y el controlador? Ejecuta el escenario actual sobre uno o dos parámetros del motor (
map-intro-model = ) o del modelo (
map-intro-axes = ), cada valor con todas las semillas, y muestra la mediana y el rango de cada cifra según las semillas. Escribe un eje como CLAVE=MIN..MAX:N, en valores o como errores relativos respecto al otro lado:{ " " }
map-intro-example = { " " }es la resistencia rotórica del motor desde un 10 % por debajo hasta un 10 % por encima de la del modelo. Cualquier otro campo numérico, como una ganancia (k1=-20%..+20%:5), el ajuste del EKF o la consigna de flujo, se lee respecto al valor propio del escenario.
map-axis = eje
map-second-axis = segundo eje (opcional)
map-seeds = semillas
map-run-button = Ejecutar mapa
sweep-heading = Respuesta en frecuencia en lazo cerrado
sweep-intro = Barre referencias de velocidad senoidales ω_d = offset + A·sin(2πft) sobre el escenario actual, ajusta la fundamental de ω (y de la estimación de velocidad del controlador) tras la primera mitad de cada ejecución y lee el ancho de banda a −3 dB y la fase a 200 Hz. Mantén A lo bastante pequeña para que las tensiones no lleguen al límite; la tabla indica la saturación. El IFOC clásico necesita una velocidad de funcionamiento (su MRAS es ciego cerca de la velocidad cero) y ejecuciones más largas (su lazo de velocidad es de 10 Hz).
# Los campos del barrido: de … Hz, a … Hz, puntos, offset … rad/s, duración … s, hilos.
sweep-from = de
sweep-to = a
sweep-points = puntos
sweep-offset = offset
sweep-run-length = duración
sweep-workers = hilos
sweep-variants = variantes
sweep-variant-euler = EKF Euler (artículo)
sweep-variant-rk4 = EKF RK4
sweep-variant-perfect = observador perfecto
sweep-variant-delay = EKF Euler, retardo de una muestra
sweep-variant-ifoc = IFOC clásico, prealimentación de par
sweep-variant-ifocpi = IFOC clásico, solo PI
sweep-run-button = Ejecutar barrido
seeds-heading = Barrido de semillas
seeds-intro = Ejecuta el escenario actual con N semillas de ruido en paralelo y muestra, en cada muestra, la media y la banda mín.–máx. del error de velocidad y del error de estimación.
# Etiqueta el número de semillas.
seeds-count = semillas
seeds-run-button = Ejecutar semillas
motor-heading = Un motor propio, a partir de su placa de características y sus ensayos de laboratorio
lessons-heading = Lecciones
lessons-intro = Cada lección carga un preajuste, lo ejecuta y abre junto a las gráficas un panel con qué observar, la pregunta, una pista y la respuesta. Las cifras que hay sobre las gráficas responden a la mayoría de las preguntas.
challenges-heading = Retos de diseño
challenges-intro = Un reto es una tarea de diseño en un enlace: el estudiante solo puede cambiar algunos ajustes y lo supera cuando se cumplen todos los criterios, en la ejecución nominal y en sus variantes. Los enlaces de abajo abren los retos incorporados; la pestaña «Reto» compone otros nuevos.
compose-heading = Componer un reto
grade-heading = Calificar una clase
# La introducción de la calificación se corta en torno a la orden «imlab grade»: grade-intro-start va delante de ella, grade-intro-end detrás.
grade-intro-start = Califica cada enlace de entrega de un archivo de la clase frente a un reto, en este navegador: nada sale de él. El archivo de la clase tiene un enlace por línea, o es la exportación CSV de una plataforma de cursos con una columna de enlaces (sus demás columnas, como el nombre del estudiante, pasan al resultado). El CSV es el mismo que{ " " }
grade-intro-end = { " " }escribe para los mismos archivos, byte a byte. Una calificación cancelada o interrumpida se guarda en este navegador hasta la siguiente, y «Calificar» continúa desde donde se detuvo.
grade-challenge-input =
    .placeholder = el nombre de uno incorporado o un enlace de reto
grade-class-file = Archivo de la clase
# Etiqueta el menú de la cifra que muestra el mapa.
map-figure = cifra
map-progress =
    .aria-label = Ejecuciones del mapa completadas
sweep-csv = CSV (primera variante)
seeds-progress =
    .aria-label = Ejecuciones de semillas completadas
compose-fill = Rellenar desde el escenario actual
grade-challenge = Reto
grade-paste = o pega los enlaces, uno por línea
grade-run = Calificar
grade-csv = Descargar CSV
grade-progress =
    .aria-label = Entregas calificadas
grade-table =
    .aria-label = Calificaciones de la clase
stale-map = Este mapa es de un escenario anterior ({ $scenario }), no de los ajustes actuales. Pulsa «Ejecutar mapa» para actualizarlo. Su CSV indica el escenario para el que se ejecutó.
stale-sweep = Estos diagramas de Bode y esta tabla son de un escenario anterior ({ $scenario }), no de los ajustes actuales. Pulsa «Ejecutar barrido» para actualizarlos. Su CSV, que no indica su escenario, queda desactivado hasta entonces.
stale-seeds = Estas bandas de semillas son de un escenario anterior ({ $scenario }), no de los ajustes actuales. Pulsa «Ejecutar semillas» para actualizarlas. Su CSV, que no indica su escenario, queda desactivado hasta entonces.
stale-challenge = Este veredicto es de un escenario anterior ({ $scenario }), no de los ajustes actuales. Pulsa «Ejecutar y comprobar» para actualizarlo. «Copiar enlace de entrega» copia el enlace de los ajustes que comprobó.
# La comparación de los predictores del EKF en el recorrido por el diseño.
stale-compare = Esta comparación es de un escenario anterior ({ $scenario }), no de los ajustes actuales. Pulsa «Ejecutar» y después el botón de la comparación para actualizarla.
