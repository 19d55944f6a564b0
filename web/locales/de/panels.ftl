# The Analysis, Lessons and Challenge tabs' own words, and the marks of a result of an earlier
# scenario: they come with the rest of the page's messages, after the first plot (web/l10n/l10n.js).

map-heading = Modellfehlerkarte
# The map's introduction is cut around three pieces of code: plant.*, model.* and an example
# axis, plant.rr=-10%..+10%:11. map-intro-start stands before "plant.*", map-intro-model between
# "plant.*" and "model.*", map-intro-axes between "model.*" and the example, map-intro-example after it.
map-intro-start = Wie weit trägt ein Ergebnis, wenn der Motor nicht dem entspricht, was EKF und Regler annehmen? Rechnet das aktuelle Szenario über einen oder zwei Parameter des Motors (
map-intro-model = ) oder des Modells (
map-intro-axes = ), jeden Wert mit jedem Startwert, und zeigt für jeden Kennwert Median und Spannweite über die Startwerte. Schreiben Sie eine Achse als KEY=LO..HI:N, in Werten oder als relative Fehler gegenüber der anderen Seite:{ " " }
map-intro-example = { " " }ist der Rotorwiderstand des Motors von 10 % unter bis 10 % über dem des Modells. Jedes andere Zahlenfeld, etwa eine Verstärkung (k1=-20%..+20%:5), die Einstellung des EKF oder das Flussziel, wird gegen den eigenen Wert des Szenarios gelesen.
map-axis = Achse
map-second-axis = zweite Achse (optional)
map-seeds = Startwerte
map-run-button = Karte berechnen
sweep-heading = Frequenzgang des geschlossenen Regelkreises
sweep-intro = Rechnet sinusförmige Drehzahlsollwerte ω_d = Offset + A·sin(2πft) über das aktuelle Szenario, passt nach der ersten Hälfte jedes Laufs die Grundschwingung von ω (und des Drehzahlschätzwerts des Reglers) an und liest die −3-dB-Bandbreite und die Phase bei 200 Hz ab. Halten Sie A so klein, dass die Spannungen von der Grenze fernbleiben; die Tabelle gibt die Sättigung an. Die klassische IFOC braucht eine Arbeitsdrehzahl (ihr MRAS ist nahe der Drehzahl null blind) und längere Läufe (ihr Drehzahlregelkreis liegt bei 10 Hz).
# The sweep's fields: from … Hz, to … Hz, points, offset … rad/s, run length … s, workers.
sweep-from = von
sweep-to = bis
sweep-points = Punkte
sweep-offset = Offset
sweep-run-length = Laufdauer
sweep-workers = Worker
sweep-variants = Varianten
sweep-variant-euler = Euler-EKF (Artikel)
sweep-variant-rk4 = RK4-EKF
sweep-variant-perfect = idealer Beobachter
sweep-variant-delay = Euler-EKF, ein Abtastschritt Totzeit
sweep-variant-ifoc = klassische IFOC, Drehmomentvorsteuerung
sweep-variant-ifocpi = klassische IFOC, nur PI
sweep-run-button = Frequenzgang berechnen
seeds-heading = Startwert-Durchlauf
seeds-intro = Rechnet das aktuelle Szenario parallel mit N Rausch-Startwerten und zeigt für jeden Abtastwert den Mittelwert und das Band von Min. bis Max. des Drehzahlfehlers und des Schätzfehlers.
# Labels the number of seeds.
seeds-count = Startwerte
seeds-run-button = Startwerte durchrechnen
motor-heading = Ein eigener Motor, aus Typenschild und Laborversuchen
lessons-heading = Lektionen
lessons-intro = Jede Lektion lädt eine Vorlage, startet sie und öffnet neben den Diagrammen ein Lektionsfeld: worauf zu achten ist, die Frage, ein Hinweis und die Antwort. Die Kennwerte über den Diagrammen beantworten die meisten Fragen.
challenges-heading = Entwurfsaufgaben
challenges-intro = Eine Aufgabe ist eine Entwurfsaufgabe in einem Link: Die Studierenden dürfen nur einige Einstellungen ändern und bestehen, wenn jedes Kriterium erfüllt ist, im Nominallauf und in seinen Varianten. Die Links unten öffnen die eingebauten Aufgaben; auf der Registerkarte „Aufgabe“ lassen sich neue erstellen.
compose-heading = Aufgabe erstellen
grade-heading = Kurs bewerten
# The grading's introduction is cut around the command "imlab grade": grade-intro-start stands before it, grade-intro-end after it.
grade-intro-start = Bewertet jeden Abgabelink einer Kursdatei anhand einer Aufgabe, in diesem Browser: Nichts verlässt ihn. Die Kursdatei enthält einen Link pro Zeile oder ist der CSV-Export einer Kursplattform mit einer Spalte von Links (ihre übrigen Spalten, etwa die Namen der Studierenden, werden ins Ergebnis übernommen). Die CSV-Datei ist dieselbe, die{ " " }
grade-intro-end = { " " }für dieselben Dateien schreibt, Byte für Byte. Eine abgebrochene oder unterbrochene Bewertung bleibt bis zur nächsten Bewertung in diesem Browser gespeichert, und „Bewerten“ macht dort weiter, wo sie aufgehört hat.
grade-challenge-input =
    .placeholder = Name einer eingebauten Aufgabe oder Aufgabenlink
grade-class-file = Kursdatei
# Labels the menu of the figure the map shows.
map-figure = Kennwert
map-progress =
    .aria-label = Erledigte Läufe der Karte
sweep-csv = CSV (erste Variante)
seeds-progress =
    .aria-label = Erledigte Startwert-Läufe
compose-fill = Aus aktuellem Szenario übernehmen
grade-challenge = Aufgabe
grade-paste = oder die Links einfügen, einen pro Zeile
grade-run = Bewerten
grade-csv = CSV herunterladen
grade-progress =
    .aria-label = Bewertete Abgaben
grade-table =
    .aria-label = Bewertungen des Kurses
stale-map = Diese Karte gehört zu einem früheren Szenario ({ $scenario }), nicht zu den aktuellen Einstellungen. Drücken Sie „Karte berechnen“, um sie zu aktualisieren. Ihr CSV-Export nennt das Szenario, für das sie berechnet wurde.
stale-sweep = Diese Bode-Diagramme und diese Tabelle gehören zu einem früheren Szenario ({ $scenario }), nicht zu den aktuellen Einstellungen. Drücken Sie „Frequenzgang berechnen“, um sie zu aktualisieren. Ihr CSV-Export, der sein Szenario nicht nennt, ist bis dahin gesperrt.
stale-seeds = Diese Startwert-Bänder gehören zu einem früheren Szenario ({ $scenario }), nicht zu den aktuellen Einstellungen. Drücken Sie „Startwerte durchrechnen“, um sie zu aktualisieren. Ihr CSV-Export, der sein Szenario nicht nennt, ist bis dahin gesperrt.
stale-challenge = Dieser Befund gehört zu einem früheren Szenario ({ $scenario }), nicht zu den aktuellen Einstellungen. Drücken Sie „Starten und prüfen“, um ihn zu aktualisieren. „Abgabelink kopieren“ kopiert den Link der Einstellungen, die er geprüft hat.
# The walkthrough's comparison of the EKF's predictors.
stale-compare = Dieser Vergleich gehört zu einem früheren Szenario ({ $scenario }), nicht zu den aktuellen Einstellungen. Drücken Sie „Starten“ und dann die Schaltfläche des Vergleichs, um ihn zu aktualisieren.
