# Die Liste der Lektionen und das Lektionsfeld neben den Diagrammen.

## Die Liste auf der Registerkarte „Lektionen“

lesson-numbered-title = { $number }. { $title }
lesson-list-question = Frage: { $question }
lesson-start = Lektion { $number } starten

## Das Lektionsfeld

lesson-count = Lektion { $number } von { $count }
lesson-run = {" "}· Lauf { $run }
lesson-look-head = Worauf zu achten ist
lesson-question-head = Frage
lesson-hint = Hinweis
lesson-show-answer = Antwort zeigen (für Lehrende)
lesson-previous = ← Vorherige
lesson-next = Nächste →
lesson-close = Lektion schließen
lesson-copy-link-short = Link kopieren
lesson-copy-link-rest = {" "}(zu dieser Lektion)
lesson-link-copied = Link kopiert: Er öffnet diese Lektion und ihren Lauf.
lesson-copy-this-link = Kopieren Sie diesen Link: { $link }
lesson-load-run = Lauf der Lektion laden
lesson-own-settings = Dieser Link enthält eigene Einstellungen, und sie werden so gezeigt, wie er sie enthält, nicht der Lauf der Lektion: { $differences }. Was die Lektion über ihren Lauf sagt, muss für sie nicht gelten.
