# Die Texte der Analyse- und Aufgabenwerkzeuge: die Registerkarte „Analyse“, das Aufgabenfeld der
# Studierenden und die Registerkarte „Aufgabe“ der Lehrenden.

## Frequency-response sweep: the Bode plots and the table (web/analysis/analysis.js)

sweep-plot-magnitude = Betrag von ω/ω_d
sweep-plot-phase = Phase von ω gegenüber ω_d
sweep-axis-degrees = Grad
sweep-series-unsettled = { $variant }, nicht eingeschwungen
sweep-unsettled =
    { $count ->
        [one] { $count } Punkt war nicht eingeschwungen (nicht ausgefüllte Marker): Bandbreite und Phase bei 200 Hz werden nie an ihm abgelesen. In einem längeren Lauf schwingt er womöglich ein.
       *[other] { $count } Punkte waren nicht eingeschwungen (nicht ausgefüllte Marker): Bandbreite und Phase bei 200 Hz werden nie an ihnen abgelesen. In längeren Läufen schwingen sie womöglich ein.
    }
sweep-unsettled-point = { $variant }, { $frequency }: { $reason }
sweep-hz = { $value } Hz
sweep-degrees = { $value } °
sweep-head-variant = Variante
sweep-head-bandwidth = −3-dB-Bandbreite
sweep-head-phase = Phase bei 200 Hz
sweep-head-saturation = Stärkste Sättigung
sweep-head-failed = Fehlgeschlagene Punkte
sweep-head-unsettled = Nicht eingeschwungene Punkte
sweep-head-peak = Spitzenwert |i_s| (A)
sweep-bandwidth-unsettled = nicht angegeben, da sie auf einem nicht eingeschwungenen Punkt beruhen würde
sweep-bandwidth-below = unterhalb der niedrigsten Frequenz
sweep-not-reached = im Raster nicht erreicht
sweep-phase-not-reached-settled = von den eingeschwungenen Punkten nicht erreicht
sweep-unsettled-cell = { $count }: { $frequencies }
sweep-peak-none = keiner gemessen
sweep-peak = { $peak } (Nennstrom { $rated })
sweep-peak-over = { $peak } (Nennstrom { $rated }); über dem Nennstrom bei { $count }: { $frequencies }

## Seed bands: the plots (web/analysis/analysis.js)

seeds-plot-error = Drehzahlfehler ω − ω_d über die Startwerte (Mittelwert, Min., Max.)
seeds-plot-estimate = Schätzfehler ω − ω̂ über die Startwerte (Mittelwert, Min., Max.)
seeds-series-mean = Mittelwert
seeds-series-min = Min.
seeds-series-max = Max.

## Frequency-response sweep: the form's run, status line and link (web/analysis/sweeps.js)

sweep-workers-invalid = workers = { $value }: Erwartet wird eine ganze Zahl von 1 bis 8.
sweep-status-checking = Die Einstellungen des Frequenzgangs werden geprüft…
sweep-refused = { $reason }.
sweep-not-run = Der Frequenzgang wurde nicht berechnet: Die Einstellungen sind ungültig oder hier nicht zulässig; die Meldung oben nennt den Grund.
sweep-status-running = Frequenzgang wird berechnet…
sweep-status-done =
    { $workers ->
        [one] { $variants } × { $points } Läufe in { $ms } ms mit { $workers } Worker.
       *[other] { $variants } × { $points } Läufe in { $ms } ms mit { $workers } Workern.
    }
sweep-status-cancelled = Berechnung des Frequenzgangs abgebrochen.
sweep-status-failed = Berechnung des Frequenzgangs fehlgeschlagen: { $reason }
sweep-link-refused = Der Frequenzgang in der Adresse ({ $link }) wurde nicht berechnet: { $reason }.

## Seed runs: the form's run and status line (web/analysis/seeds.js)

seeds-count-invalid = Startwerte = { $value }: Erwartet wird eine ganze Zahl von 1 bis 1000.
seeds-not-run = Die Startwerte wurden nicht durchgerechnet: Die Einstellungen sind ungültig oder hier nicht zulässig; die Meldung oben nennt den Grund.
seeds-status-starting = Startwerte werden durchgerechnet…
seeds-status-running = Startwerte werden durchgerechnet: { $percent } %
seeds-status-done = { $runs } von { $seeds } Startwerten ({ $first } bis { $last }) durchgerechnet.
seeds-status-cancelled = Durchrechnen der Startwerte abgebrochen.
seeds-status-failed = Startwert-Durchlauf fehlgeschlagen: { $reason }

## Model-error map: its run and status line (web/analysis/robust.js)

map-status-starting = { $cells } Zellen × { $seeds } Startwerte werden berechnet…
map-status-running = Karte wird berechnet: { $done } von { $total } Läufen.
map-refused = Die Karte wurde nicht berechnet: { $reason }.
map-not-run = Die Karte wurde nicht berechnet: Die Einstellungen sind ungültig oder hier nicht zulässig; die Meldung oben nennt den Grund.
map-failed = Die Berechnung der Karte ist fehlgeschlagen: { $reason }
map-status-cancelled = Karte abgebrochen: { $finished } von { $cells } Zellen sind fertig und werden gezeigt; die übrigen wurden nicht berechnet.
map-status-done = { $cells } Zellen × { $seeds } Startwerte ({ $first }–{ $last }) in { $seconds } s.
map-link-refused = Die Karte in der Adresse ({ $link }) wurde nicht berechnet: { $reason }.

## Model-error map: the plot over one axis (web/analysis/map-plot.js)

map-plot-title = { $figure } über die Startwerte: Median und Band von Min. bis Max.
map-series-min = Min.
map-series-median = Median
map-series-max = Max.
map-gap = { $value } ({ $ranAway } von { $runs } Startwerten)
map-gap-percent = { $value } % ({ $ranAway } von { $runs } Startwerten)
map-gaps = Nicht gezeichnet, weil dort einige Startwerte divergiert sind: { $cells }.

## Model-error map: the table and its key (web/analysis/map-table.js, map-colours.js)

map-figure-unit = { $figure } ({ $unit })
map-cell-not-run = nicht berechnet
map-cell-title = { $scenario }: { $ranAway } von { $runs } Startwerten divergiert, { $inconsistent } inkonsistent, { $overRating } über dem Nennstrom, { $unsettled } mit am Ende nicht eingeschwungenem Drehzahlfehler; { $figure } { $min } bis { $max }
map-grid-corner = { $rows } ↓ / { $columns } →
map-head-median = Median
map-head-range = Min. – Max.
map-range = { $min } – { $max }
map-key = { $figure }, Median über die nicht divergierten Startwerte ({ $seeds } Startwerte); Farbe: { $colours }. ✕ k/N: Der Lauf ist bei k der N Startwerte divergiert (das meldet die Seite des Laufs selbst, oder seine Werte wuchsen über alle Grenzen), nie als Wert eingefärbt; ⚠ das EKF war inkonsistent; I↑ k/H: Von den H Startwerten, die gehalten haben, überschritten k nach dem Anlauf den Nennstrom des Motors; ~ k/H: k endeten mit nicht eingeschwungenem Drehzahlfehler (beide umrandet und nach ihrem Median eingefärbt). Klicken Sie auf eine Zelle, um sie zu starten (Startwert { $seed }).
map-scale-diverging = blau −{ $max } über weiß 0 bis rot { $max }
map-scale-log = logarithmische Skala von hell { $min } bis dunkel { $max }
map-scale-linear = lineare Skala von hell { $min } bis dunkel { $max }
map-scale-none = keine

## Challenge panel: what a student sees of a challenge link (web/challenge/challenge.js)

challenge-heading = Aufgabe
challenge-link-rejected = Dieser Aufgabenlink wurde abgelehnt: { $reason }. Die Seite zeigt stattdessen das Standardszenario.
challenge-submission-another = Dieser Abgabelink gehört zu einer anderen Aufgabe (sein Aufgabenteil wurde bearbeitet): Er wurde nicht bewertet.
challenge-submission-refused = Dieser Abgabelink wurde zurückgewiesen: { $reason }. Er wurde nicht bewertet; die Aufgabe beginnt mit ihren Grundeinstellungen.
challenge-submission-rejected = Dieser Abgabelink wurde abgelehnt: { $reason }. Er wurde nicht bewertet; die Aufgabe beginnt mit ihren Grundeinstellungen.
challenge-run = Starten und prüfen
challenge-settings = Ihre Einstellungen
challenge-settings-hint = Ändern lässt sich nur { $fields }; die übrigen Einstellungen sind durch die Aufgabe gesperrt.
challenge-checklist = Prüfliste
challenge-task = Die vollständige Aufgabe
challenge-verdict-pending = Noch nicht geprüft: Der erste Lauf wird berechnet.
challenge-need-pending = { $label } ({ $figure }): noch nicht geprüft
challenge-verdict-link-refused = ✗ Nicht bewertet: Die Einstellungen im Link wurden zurückgewiesen (siehe oben). Ändern Sie die zulässigen Einstellungen und starten Sie den Lauf.
challenge-verdict-cancelled = ✗ Prüfung abgebrochen: nicht bewertet. Starten Sie erneut, um zu prüfen.
challenge-verdict-failed = ✗ Die Prüfung ist fehlgeschlagen: { $reason }. Nicht bewertet.
challenge-verdict-edited = Dies ist nicht die eingebaute Aufgabe { $name }: Ihre Bedingungen wurden bearbeitet.
challenge-verdict-rerun = Der angezeigte Lauf ist nicht der bewertete (eine gesperrte Einstellung weicht ab): Der Nominallauf wurde mit den Einstellungen der Aufgabe und Ihren zulässigen Einstellungen erneut gerechnet.
challenge-checking =
    Prüfung: { $done } von { $runs ->
        [one] { $runs } Lauf
       *[other] { $runs } Läufen
    } fertig (der Nominallauf und { $variants ->
        [one] { $variants } Variante
       *[other] { $variants } Varianten
    })…
challenge-refusal-not-run = Ihre Einstellungen sind keine gültige Antwort: { $reason }. Nicht gerechnet.
challenge-verdict-not-run = ✗ Nicht gerechnet. Ihre Einstellungen sind keine gültige Antwort: { $reason }.
challenge-refusal-not-graded = Ihre Einstellungen sind keine gültige Antwort: { $reason }. Nicht bewertet.
challenge-verdict-not-graded = ✗ Nicht bewertet. Ihre Einstellungen sind keine gültige Antwort: { $reason }.
challenge-copied = Abgabelink kopiert: Er spielt diese Läufe bitgenau erneut ab.
challenge-copy-by-hand = Kopieren Sie diesen Abgabelink: { $url }

## Challenge panel: the checklist and its controls (web/challenge/checklist.js)

checklist-not-measured = nicht gemessen
checklist-never = nie (∞)
checklist-value-unit = { $value } { $unit }
checklist-passed =
    { $criteria ->
        [one] ✓ Bestanden: Das Kriterium ist erfüllt.
       *[other] ✓ Bestanden: Alle { $criteria } Kriterien sind erfüllt.
    }
checklist-passed-variants =
    { $criteria ->
        [one] ✓ Bestanden: Das Kriterium ist erfüllt (der Nominallauf und { $variants ->
            [one] { $variants } Variante
           *[other] { $variants } Varianten
        }).
       *[other] ✓ Bestanden: Alle { $criteria } Kriterien sind erfüllt (der Nominallauf und { $variants ->
            [one] { $variants } Variante
           *[other] { $variants } Varianten
        }).
    }
checklist-failed = ✗ Nicht bestanden: { $met } von { $criteria } Kriterien erfüllt.
checklist-failed-variants =
    ✗ Nicht bestanden: { $met } von { $criteria } Kriterien erfüllt (der Nominallauf und { $variants ->
        [one] { $variants } Variante
       *[other] { $variants } Varianten
    }).
checklist-pass = ✓ bestanden
checklist-fail = ✗ nicht bestanden
checklist-criterion = { $label }: { $value }, gefordert { $bound }
checklist-criterion-worst = { $label }: { $value }, gefordert { $bound } (ungünstigster Lauf: { $run })
checklist-reason = — { $reason }

## Challenge panel: the knobs of the allowed settings (web/challenge/knobs.js)

challenge-knob-doc = { $doc } ({ $unit })
challenge-allowed-choice = zulässig: eines von { $options }
challenge-allowed-formula = zulässig: eine eigene Formel ({ $unit }; „Diesen Schritt selbst schreiben“ im Entwurfsdurchgang listet die Namen auf)
challenge-allowed-range = zulässig: { $lo } bis { $hi }
challenge-allowed-range-unit = zulässig: { $lo } bis { $hi } { $unit }

## Challenge panel: the header, where the challenge comes from (web/challenge/origin.js)

challenge-kind = Aufgabe
challenge-origin-builtin = Eingebaute Aufgabe
challenge-origin-mine = Von Ihnen in diesem Browser gestellt: Dieser Browser hat genau diese Aufgabe erstellt (Schranken und Titel unverändert)
challenge-origin-other = Keine Aufgabe, die Sie in diesem Browser gestellt haben
challenge-origin-unknown = Dieser Browser führt keine Aufzeichnungen über die von ihm erstellten Aufgaben
challenge-fingerprint = Fingerabdruck
challenge-edited = Bearbeitet: Dieser Link trägt den Titel der eingebauten Aufgabe { $name }, aber nicht ihre Bedingungen. Er wird als die Aufgabe bewertet, die er ist, nicht als { $name }.

## The built-in challenges, in the Lessons tab (web/challenge/builtins.js)

builtins-open = Aufgabe { $name } öffnen
builtins-failed = Die eingebauten Aufgaben konnten nicht aufgelistet werden.

## Challenge tab: composing a challenge (web/challenge/challenge-compose.js)

compose-intro = Die Aufgabe geht vom Szenario in den Einstellungen aus (ihrer Basis); die Studierenden dürfen nur die hier aufgeführten Felder innerhalb ihrer Bereiche ändern und bestehen, wenn jedes Kriterium erfüllt ist. Richten Sie das Szenario ein und starten Sie es zuerst: Die Kriterien werden aus seinen Kennwerten vorbelegt, 20 % strenger als dieser Lauf.
compose-base = Basis:
compose-title = Titel
compose-title-default = Aufgabe: { $preset }
compose-make = Aufgabenlink erstellen
compose-no-run = Kein abgeschlossener Lauf dieses Szenarios, dem die Kennwerte entnommen werden könnten: Starten Sie ihn und drücken Sie dann erneut „Aus aktuellem Szenario übernehmen“.
compose-invalid = Die Aufgabe ist ungültig: { $reason }
compose-link = Aufgabenlink
compose-kept = Dieser Browser vermerkt, dass er diese Aufgabe erstellt hat: Hier geöffnet, zeigt der Link „Von Ihnen in diesem Browser gestellt“; eine Kopie mit anderer Schranke oder anderem Titel nicht.
compose-not-kept = Dieser Browser führt keine Aufzeichnungen über die von ihm erstellten Aufgaben (sein Speicher oder Web Crypto ist hier nicht verfügbar): Hier geöffnet, kann der Link nicht anzeigen, dass Sie die Aufgabe gestellt haben.
compose-copy-link = Aufgabenlink kopieren
compose-link-copied = Aufgabenlink kopiert.
compose-link-not-copied = Markieren Sie den Aufgabenlink oben und kopieren Sie ihn.
compose-open = Aus Studierendensicht öffnen
compose-brief = Die Aufgabe in Worten (für eine Folie oder die Kursseite)
compose-copy-brief = Aufgabe kopieren
compose-brief-copied = Aufgabe kopiert.
compose-brief-not-copied = Markieren Sie die Aufgabe oben und kopieren Sie sie.

## Challenge tab: the composer's rows (web/challenge/compose-rows.js)

compose-allow-legend = Felder, die Studierende ändern dürfen
compose-field = Feld
compose-field-option = { $field } — { $doc }
compose-add = Hinzufügen
compose-remove = Entfernen
    .aria-label = { $field } entfernen
compose-allow-formula = eine eigene Formel der Studierenden ({ $unit })
compose-allow-choices = { $field }: Auswahl (a|b)
compose-allow-from = von
compose-allow-to = bis
compose-allow-now-unit = { $unit } (jetzt { $value })
compose-allow-now = (jetzt { $value })
compose-need-legend = Kriterien: die Kennwerte dieses Laufs
compose-need-hint = „alle Läufe“ lässt das Kriterium auch für jede Variante gelten (der ungünstigste Lauf zählt).
compose-need = { $label } ({ $figure })
compose-need-now = { $label } ({ $figure }) — jetzt { $value }
compose-need-now-unit = { $label } ({ $figure }) — jetzt { $value } { $unit }
compose-need-op = { $figure }: Art der Schranke
compose-need-bound = { $figure }: Schranke
compose-need-bound-unit = { $figure }: Schranke in { $unit }
compose-op-max = höchstens
compose-op-min = mindestens
compose-op-abs = |Wert| höchstens
compose-op-band = innerhalb seines 95-%-Bands
compose-bound-none = keine
compose-need-all-runs = alle Läufe
compose-vary-legend = Robustheitsvarianten (optional)
compose-vary = Varianten: seeds:A..B oder Einstellungen, die zusätzlich zu denen der Studierenden angewandt werden, getrennt durch |
    .placeholder = seeds:2..10  oder  model.j=0.016|model.j=0.024
compose-vary-seeds = Startwerte 2 bis 10

## Challenge tab: the check that a design passes (web/challenge/compose-check.js)

compose-check-progress =
    .aria-label = Aufgabenprüfung: erledigte Läufe
compose-check-cancel = Prüfung abbrechen
compose-check-starting = Es wird geprüft, ob ein Entwurf innerhalb der zulässigen Bereiche besteht…
compose-check-running =
    Es wird geprüft, ob ein Entwurf innerhalb der zulässigen Bereiche besteht: { $done } von { $runs ->
        [one] { $runs } Lauf
       *[other] { $runs } Läufen
    } ({ $designs ->
        [one] { $designs } Entwurf
       *[other] { $designs } Entwürfe
    })…
compose-check-cancelled = Prüfung abgebrochen: Ob ein Entwurf innerhalb der zulässigen Bereiche besteht, ist nicht bekannt. Erstellen Sie den Link erneut, um zu prüfen.
compose-check-failed = Die Prüfung ist fehlgeschlagen: { $reason }.
compose-check-base-design = die Basis, ohne geändertes Feld
compose-check-failure = { $figure }: { $value } gegenüber { $bound }
compose-check-failure-changing = { $figure }: { $value } gegenüber { $bound }, ändert sich noch
compose-check-unmeasured = { $figure }: { $reason }
compose-check-base-passes = Die Basis besteht unverändert: Wer nichts ändert, besteht.
compose-check-base-fails = Die Basis (ohne geändertes Feld) besteht nicht: { $failures }.
compose-check-tried =
    Die Prüfung hat { $designs ->
        [one] { $designs } Entwurf
       *[other] { $designs } Entwürfe
    } in { $runs ->
        [one] { $runs } Lauf
       *[other] { $runs } Läufen
    } erprobt (höchstens { $budget } Läufe): zuerst die Basis, dann die Entwürfe, die die wenigsten Felder ändern, von den Enden der Bereiche nach innen (alle Kombinationen, sofern sie in dieses Budget passen).
compose-check-solvable = ✓ Ein Entwurf innerhalb der zulässigen Bereiche besteht: { $design } ({ $passing } von { $tried } erprobten Entwürfen bestehen).
compose-check-unsolved = ✗ Keiner der { $tried } erprobten Entwürfe besteht: Die Schranken sind womöglich unerreichbar; am nächsten kam { $design } ({ $failures }).

## Challenge tab: grading a class (web/challenge/grade.js)

grade-refused = Nicht bewertet: { $reason }.
grade-no-challenge = Nennen Sie eine Aufgabe: den Namen einer eingebauten oder einen Aufgabenlink
grade-no-file = Wählen Sie eine Kursdatei oder fügen Sie die Links ein, einen pro Zeile
grade-no-submission = Die Datei enthält keine Abgabe
grade-read-as = Die Kursdatei wurde als { $encoding } gelesen (sie ist nicht in UTF-8).
grade-status-reading = Kursdatei wird gelesen…
grade-status-grading = { $total } Abgaben werden bewertet…
grade-status-grading-kept = { $total } Abgaben werden bewertet, { $kept } aus der letzten Bewertung übernommen…
grade-count = { $done } von { $total } bewertet
grade-status-done = { $total } von { $total } bewertet: { $passed } bestanden.
grade-not-stored = Der Speicher des Browsers hat diese Bewertung nicht aufgenommen: Laden Sie sie jetzt herunter.
grade-status-cancelled-kept = Abgebrochen: { $graded } von { $total } bewertet, in diesem Browser gespeichert; „Bewerten“ macht dort weiter.
grade-status-cancelled-lost = Abgebrochen: { $graded } von { $total } bewertet, nicht gespeichert (der Speicher des Browsers hat sie abgelehnt).
grade-status-stopped-kept = Die Bewertung brach ab: { $reason }. { $graded } von { $total } bewertet, in diesem Browser gespeichert; „Bewerten“ macht dort weiter.
grade-status-stopped-lost = Die Bewertung brach ab: { $reason }. { $graded } von { $total } bewertet, nicht gespeichert (der Speicher des Browsers hat sie abgelehnt).
grade-status-cancelled-reading = Abgebrochen, während die Kursdatei gelesen wurde: Nichts wurde bewertet.
grade-downloaded-partial = Die ersten { $rows } von { $total } Zeilen wurden der Reihe nach heruntergeladen: „Bewerten“ macht dort weiter, wo es aufgehört hat, und { $command } kann die Datei vervollständigen.

## Challenge tab: the class's table (web/challenge/grade-table.js)

grade-pending = noch nicht bewertet
grade-pass = ✓ bestanden
grade-fail = ✗ nicht bestanden
grade-head-line = Zeile
grade-head-verdict = Befund
grade-head-link = Link
grade-value-reason = { $value }: { $reason }
grade-worst-run = { $text } (ungünstigster Lauf: { $run })

## The Analysis tab: a motor of your own

motor-intro = Schätzt das Ersatzschaltbild eines Motors aus dem Gleichstromwiderstand des Stators, dem Leerlaufversuch bei Nennspannung und dem Kurzschlussversuch (IEEE Std 112), wie imlab motor es tut, und gibt an, welche Werte Schätzwerte sind. Der Motor läuft dann als Strecke und Modell zugleich, mit dem daraus abgeleiteten Entwurf. Jeder Versuch ist eine Messung: verkettete Spannung, Leiterstrom, aufgenommene Leistung und Frequenz, durch Kommas getrennt.
motor-rs = Statorwiderstand je Strang, Gleichstrommessung
motor-no-load = Leerlaufversuch
motor-locked = Kurzschlussversuch (Rotor blockiert)
# The NEMA design letter splits the locked-rotor leakage between stator and rotor.
motor-nema = NEMA-Designbuchstabe
motor-rated = Typenschild: Spannung, Frequenz, Strom
motor-j = Trägheitsmoment des Rotors
motor-np = Polpaarzahl
motor-run-button = Ersatzschaltbild schätzen
motor-example-button = Beispiel eintragen
motor-example-filled = Das Formular enthält eine Maschine mit 2,2 kW und 400 V, wie ein Labor sie aufschreiben würde: ihr Typenschild und die Messwerte, die ihr Ersatzschaltbild liefert (ein simuliertes Labor, kein Motor aus einem Katalog).
motor-open = Diesen Motor mit seinem abgeleiteten Entwurf rechnen
