# La lista de lecciones y el panel de la lección junto a las gráficas.

## The list in the Lessons tab

lesson-numbered-title = { $number }. { $title }
lesson-list-question = Pregunta: { $question }
lesson-start = Empezar la lección { $number }

## The lesson panel

lesson-count = Lección { $number } de { $count }
lesson-run = {" "}· ejecución { $run }
lesson-look-head = Qué observar
lesson-question-head = Pregunta
lesson-hint = Pista
lesson-show-answer = Mostrar la respuesta (para el profesor)
lesson-previous = ← Anterior
lesson-next = Siguiente →
lesson-close = Cerrar la lección
lesson-copy-link-short = Copiar enlace
lesson-copy-link-rest = {" "}a esta lección
lesson-link-copied = Enlace copiado: abre esta lección y su ejecución.
lesson-copy-this-link = Copia este enlace: { $link }
lesson-load-run = Cargar la ejecución de la lección
lesson-own-settings = Este enlace contiene ajustes propios, y se muestran tal como él los tiene, no como en la ejecución de la lección: { $differences }. Lo que la lección dice de su ejecución no tiene por qué cumplirse con ellos.
