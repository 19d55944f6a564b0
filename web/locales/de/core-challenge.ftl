# Die Meldungen des Kerns zu Entwurfsaufgaben und ihrer Bewertung: warum ein Aufgaben- oder
# Abgabelink zurückgewiesen wurde, die Aufgabe in Worten, der Befund zu jedem Kriterium und die
# Bewertung eines Kurses. Die CSV-Datei der Bewertungen enthält sie auf Englisch. Schlüssel, Felder,
# Kennwerte und Einstellungen (c=1, allow.FIELD, need.FIGURE=OP, seeds:A..B, try.FIELD, mean_nis,
# load.torque = 0) sind die eigenen Worte des Links: unverändert lassen. Zitierte Eingaben behalten
# ihre Anführungszeichen.

## Ein zurückgewiesener Aufgaben- oder Abgabelink

# $key is the link's key (title, vary, try.k1…), $value the text it holds.
challenge-not-percent-encoded = Feld '{ $key }' = '{ $value }': kein gültiges prozentkodiertes UTF-8
challenge-too-long = Die Aufgabe ist { $bytes } Bytes lang, mehr als die zulässigen { $max } Bytes ({ $kib } KiB)
# $names lists the built-in challenges' names.
challenge-unknown = '{ $name }' ist weder ein Aufgabenlink noch eine eingebaute Aufgabe ({ $names })
challenge-unsupported-version = Feld 'c' = '{ $value }': nicht unterstützte Aufgabenversion, zulässig: { $version }
# $fields lists the keys a challenge link may hold.
challenge-unknown-key = Feld '{ $key }' ist kein Feld einer Aufgabe ({ $fields })
challenge-missing = Feld '{ $key }' fehlt
# $name is the built-in challenge's name.
challenge-builtin-extra = Feld '{ $key }' darf nicht auf challenge={ $name } folgen: Der Link einer eingebauten Aufgabe enthält nur challenge=NAME und die try.FIELD-Teile der Studierenden
# $stray is the characters written before c=; $count how many there are.
challenge-stray = Der Link beginnt vor seinem c={ $version } mit { $count ->
        [one] dem überzähligen Zeichen
       *[other] den überzähligen Zeichen
    } '{ $stray }': Entfernen Sie { $count ->
        [one] es
       *[other] sie
    }
challenge-version-missing = Feld 'c' fehlt (eine Aufgabe beginnt mit c={ $version })
challenge-title-too-long = Feld 'title' ist { $chars } Zeichen lang, mehr als die zulässigen { $max }
# $error says why the base scenario was refused (a scenario-* message).
challenge-bad-base = Feld 'base': { $error }
challenge-no-criteria = keine Kriterien: Fügen Sie mindestens ein need.FIGURE=OP hinzu
challenge-too-many-criteria = { $count } Kriterien, mehr als die zulässigen { $max }
challenge-vary-unused = Feld 'vary': Kein Kriterium verwendet die Varianten (nennen Sie die Kennwerte der Kriterien in robust=)
challenge-robust-without-vary = Feld 'robust': Es gibt keine Varianten (fügen Sie vary= hinzu)
# $key is allow.FIELD; $field the scenario field it names.
challenge-allow-unknown-field = Feld '{ $key }': '{ $field }' ist kein Feld eines Szenarios
challenge-allow-formula = Feld '{ $key }' = '{ $value }': Das Regelgesetz eines Schritts wird als allow.{ $field }=formula zugelassen
challenge-allow-range = Feld '{ $key }' = '{ $value }': erwartet wird LO..HI, zwei Zahlen mit LO ≤ HI
# $error says why an end of the range is no value of the field (a scenario-* message).
challenge-allow-refused = Feld '{ $key }' = '{ $value }': { $error }
# $options lists the field's names, separated by |.
challenge-allow-choice = Feld '{ $key }' = '{ $value }': erwartet werden verschiedene Namen aus { $options }, getrennt durch |
# $key is need.FIGURE; $figures lists the figures a criterion may name.
challenge-need-unknown-figure = Feld '{ $key }': '{ $figure }' ist kein Kennwert ({ $figures })
challenge-need-band = Feld '{ $key }' = 'band': Nur mean_nis hat ein Band
challenge-need-op = Feld '{ $key }' = '{ $value }': erwartet wird max:B, min:B, abs:B oder band
challenge-need-no-load-step = Feld '{ $key }': Die Basis hat keinen Lastsprung (load.torque = 0 oder stattdessen eine Lasttabelle)
challenge-vary-seeds = Feld 'vary' = '{ $value }': erwartet wird seeds:A..B, ganze Zahlen mit A ≤ B ≤ { $max_seed } und höchstens { $max } Startwerten
challenge-vary-too-many = Feld 'vary': { $count } Varianten, mehr als die zulässigen { $max }
# $number counts the variants from 1; $error says what is wrong with it (a scenario-* message).
challenge-vary-variant-refused = Feld 'vary', Variante { $number }: { $error }
challenge-vary-variant-empty = Feld 'vary', Variante { $number } ist leer
# $overrides is the variant's settings (seed=2); $error says why they do not apply.
challenge-variant-refused = Variante '{ $overrides }': { $error }
# $value is the robust= list, $figure the name in it that is not a criterion's.
challenge-robust-unknown = Feld 'robust' = '{ $value }': '{ $figure }' ist nicht der Kennwert eines Kriteriums (oder ist doppelt genannt)
challenge-is-submission = Feld 'try.{ $key }': Dies ist eine Abgabe, keine Aufgabe (bewerten Sie sie anhand ihrer Aufgabe)
challenge-another = Die Abgabe gehört zu einer anderen Aufgabe (ihr Aufgabentext weicht ab)
challenge-try-not-allowed = Feld '{ $field }' ist nicht zulässig
challenge-try-not-number = Feld 'try.{ $field }' = '{ $value }': keine Zahl
# $setting is the student's setting (k1=6000), $range the allowed one (300..5000).
challenge-try-outside = { $setting } liegt außerhalb von { $range }
# $options lists the allowed names, separated by |.
challenge-try-not-option = { $setting } ist keines von { $options }
challenge-compose-range-and-options = Feld '{ $key }': Geben Sie LO und HI (einen Bereich) oder Optionen (eine Auswahl) an, nicht beides
challenge-judge-runs = Die Aufgabe hat { $runs } { $runs ->
        [one] Lauf
       *[other] Läufe
    } (den Nominallauf und { $variants } { $variants ->
        [one] Variante
       *[other] Varianten
    }), davon { $measured } gemessen

## Die Aufgabe in Worten

challenge-untitled = Entwurfsaufgabe
# The challenge's title, as its author wrote it.
challenge-title = { $title }
# $base is the scenario string.
challenge-brief-start = Gehen Sie vom Szenario { $base } aus
challenge-brief-nothing-allowed = Nichts darf geändert werden: Die Basis wird bewertet, wie sie ist.
challenge-brief-allowed = Sie dürfen nur ändern:
# One field the student may change: $field its name (padded to a column), $range what it may be
# (a challenge-brief-range, -one-of or -formula message), $now the base's value, $doc the field
# in words.
challenge-brief-allow = { $field } { $range } (jetzt { $now }) — { $doc }
# $hi has its unit, if any.
challenge-brief-range = { $lo } bis { $hi }
# $options lists the names.
challenge-brief-one-of = eines von { $options }
challenge-brief-formula = eine eigene Formel
challenge-brief-formula-unit = eine eigene Formel in { $unit }
challenge-brief-needs = Ihr Entwurf muss erfüllen:
# One criterion: $number counts them from 1, $label is the figure in words, $figure its name,
# $bound a challenge-brief-at-most, -at-least, -within or -band message; $settled is yes for a
# final value, which must have settled; $robust is yes when it must hold on every variant too.
challenge-brief-need = { $number }. { $label } ({ $figure }): { $bound }{ $settled ->
        [yes] {" "}und bis zum Ende des Laufs eingeschwungen
       *[no] {""}
    }{ $robust ->
        [yes] {" "}— im Nominallauf und in jeder Variante
       *[no] {""}
    }
# $bound has its unit, if any.
challenge-brief-at-most = höchstens { $bound }
challenge-brief-at-least = mindestens { $bound }
challenge-brief-within = innerhalb von ±{ $bound }
challenge-brief-band = innerhalb des 95-%-Bands eines konsistenten Filters (mean_nis_low bis mean_nis_high)
# $first and $last are the first and the last noise seed (seed=2…).
challenge-brief-variants-seeds = Varianten (zusätzlich zu Ihren Einstellungen angewandt; der ungünstigste Lauf zählt): Rausch-Startwerte { $first } bis { $last }
# $overrides lists each variant's settings, separated by semicolons.
challenge-brief-variants = Varianten (zusätzlich zu Ihren Einstellungen angewandt; der ungünstigste Lauf zählt): { $overrides }
challenge-brief-load-recovery = Erholzeit nach dem Lastsprung: die Zeit vom Lastsprung (t = { $time } s), bis |ω − ω_d| bis zum Ende des Laufs innerhalb von max(1 % von |ω_d| beim Sprung; 0,5 rad/s) bleibt (hier { $band } rad/s bei ω_d = { $speed } rad/s); nicht erholt, wenn es am Ende noch außerhalb liegt.
challenge-brief-settled = Ein Endwert zählt nur, wenn er eingeschwungen ist: Ein Wert, der sich im letzten Zehntel des Laufs noch ändert, besteht nicht.
# A number and its unit: "0.004 s".
challenge-quantity = { $value } { $unit }

## Die Schranke eines Kriteriums und warum es nicht erfüllt ist

# $bound has its unit, if any: "≤ 0.004 s".
challenge-bound-max = ≤ { $bound }
challenge-bound-min = ≥ { $bound }
challenge-bound-abs = |·| ≤ { $bound }
challenge-bound-band = innerhalb seines 95-%-Bands
# $failure says why the run failed (in English until the simulation's messages are translated).
challenge-run-unfinished = der Lauf wurde nicht zu Ende gerechnet
challenge-reason-run-failed = Lauf fehlgeschlagen: { $failure }
# $cause says why the figure is not a number (in English until the run's report is translated).
challenge-reason-not-finite = { $cause }
challenge-reason-before-load-step = nicht gemessen: Der Lauf endet vor dem Lastsprung
challenge-reason-not-measured = in diesem Lauf nicht gemessen (z. B. ein Sprung, der nie innerhalb von 2 % einschwingt)
challenge-reason-no-band = nicht gemessen: kein NIS-Band in diesem Lauf
challenge-reason-above-bound = über der Schranke
challenge-reason-below-bound = unter der Schranke
challenge-reason-beyond-bound = jenseits der Schranke
challenge-reason-below-band = unter dem Band
challenge-reason-above-band = über dem Band
challenge-reason-not-recovered = bis zum Ende des Laufs nicht erholt
challenge-reason-still-changing = ändert sich noch

## Die Bewertung eines Kurses: der Status jeder Abgabe (auch in der CSV-Datei) und die Kursdatei

grade-row-ok = ok
# $reason says why the link is not a well-formed submission.
grade-row-malformed = fehlerhaft: { $reason }
# $reason names the field the student set that is not allowed, or out of its range.
grade-row-refused = zurückgewiesen: { $reason }
grade-row-another = andere Aufgabe
# $reason says why a run failed (in English until the simulation's messages are translated).
grade-row-run-failed = Lauf fehlgeschlagen: { $reason }
grade-internal-error = interner Fehler
# $encoding is the name of the encoding the file was read in (UTF-8, windows-1252…).
grade-line-undecoded = Zeile { $line } ist kein gültiges { $encoding }
grade-line-unclosed = Zeile { $line }: Ein Feld in Anführungszeichen wird bis zum Dateiende nicht geschlossen
grade-line-fields = Zeile { $line } hat { $fields } { $fields ->
        [one] Feld
       *[other] Felder
    }, die Kopfzeile { $header }
grade-no-link = kein Link
# $error says why the challenge was refused.
grade-challenge-refused = Aufgabe: { $error }
grade-file-not-text = Die Datei ist keine Textdatei (sie enthält NUL-Bytes: eine Tabelle oder ein Dokument?); speichern Sie sie als Textdatei mit einem Link pro Zeile oder als CSV
grade-file-utf16 = Die Datei ist UTF-16 ohne Byte-Order-Mark; speichern Sie sie als UTF-8
grade-file-header-undecoded = Zeile { $line }, die CSV-Kopfzeile, ist kein gültiges { $encoding }
# $columns lists the file's column headers, each quoted.
grade-file-no-link-column = Dieser CSV-Export hat keine Spalte mit Links (seine Spalten: { $columns }); geben Sie der Spalte mit den Links die Überschrift 'link'
grade-file-links-everywhere = Die Spalten { $columns } enthalten alle Links; geben Sie der zu bewertenden die Überschrift 'link'
grade-file-link-headers = Die Spalten { $columns } tragen alle eine Link-Überschrift; behalten Sie nur eine

## Eine unterbrochene Bewertung fortsetzen (imlab grade --resume): warum ihre frühere Ausgabe zurückgewiesen wird

grade-resume-not-utf8 = Die frühere Ausgabe ist kein UTF-8-Text, also nicht die Bewertungen dieses Kurses
# $header is the CSV header line this grading writes.
grade-resume-header = Die erste Zeile der früheren Ausgabe ist nicht die Kopfzeile dieser Bewertung '{ $header }': Die Ausgabe enthält die Bewertungen einer anderen Aufgabe oder Kursdatei
grade-resume-too-many-rows = Die frühere Ausgabe enthält mehr Zeilen, als die Kursdatei Abgaben hat ({ $rows })
grade-resume-row = Zeile { $row } der früheren Ausgabe gehört nicht zu Zeile { $line } ('{ $link }') der Kursdatei: Die Ausgabe enthält die Bewertungen einer anderen Kursdatei
# $what is one of the grade-kept-* messages.
grade-kept-differs = Zeile { $row } der früheren Ausgabe (Zeile { $line } der Kursdatei) ist nicht das, was eine erneute Bewertung ergibt: { $what }; sie wurde nach ihrer Bewertung bearbeitet oder von einer anderen Version von imlab bewertet
# $column is the CSV column's name (status, settling_time_pass…).
grade-kept-cell = In der Spalte { $column } steht '{ $found }', nicht '{ $expected }'
grade-kept-extra = Nach der letzten Spalte steht '{ $extra }'
grade-kept-short = Die Spalten ab { $column } fehlen
