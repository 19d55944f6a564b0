# Die Beschriftungen, Schaltflächen, Hinweise und Meldungen der Seite, nach dem Teil der Seite, der sie zeigt.
# Zahlen kommen in Variablen, bereits in der Schreibweise der Sprache. Eine Variable namens $reason,
# $warning, $description oder $label enthält die eigenen Worte des Simulationskerns, vorerst auf Englisch;
# ein Szenario ($scenario), der Schlüssel eines Felds ($key), der Name einer Vorlage ($preset) oder ein
# Befehl wird so geschrieben, wie er ist, und nie übersetzt.

## Der Kopfbereich

# The browser tab's title.
page-title = IM Lab: drehgeberlose Regelung von Asynchronmaschinen
# The name of the app, in the page's heading.
page-name = IM Lab
page-skip-link = Zu den Diagrammen springen
page-intro = Drehgeberlose Regelung von Asynchronmaschinen: EKF-Beobachter und vierstufiger Backstepping-Regler (Zhang, Wang, Bortoff et al., 2015), simuliert mit 20 kHz in Ihrem Browser.
help-links =
    .aria-label = Info / Hilfe
# Stands before the links to the guides.
help-links-intro = Info / Hilfe:
help-student-guide = Leitfaden für Studierende
help-lecturer-guide = Leitfaden für Lehrende
help-all-guides = Alle Leitfäden
language-menu = Sprache

## Das Laden der Lektionen

# $reason is the browser's reason, in its words.
lessons-not-loaded = Die Texte der Lektionen konnten nicht geladen werden: { $reason }. Öffnen Sie die Registerkarte „Lektionen“ erneut, um es noch einmal zu versuchen.

## Schaltflächen, die an mehreren Stellen vorkommen

shared-cancel = Abbrechen
# Downloads a table as a CSV file.
shared-csv = CSV

## Die Startleiste: die Vorlage, „Starten“, die Statuszeile und die Links

run-preset = Vorlage
run-button = Starten
run-settings = Einstellungen
run-unrun = Einstellungen geändert, noch nicht gestartet: Drücken Sie „Starten“ oder die Eingabetaste. Die Adresse und „Link kopieren“ beziehen sich auf den angezeigten Lauf.
share-copy-link = Link kopieren
# Downloads an image of the plots.
export-png = PNG
share-copy-embed = Embed-Code kopieren
    .title = Kopiert ein iframe-Snippet, das die sichtbaren Diagramme der Registerkarte „Verläufe“ für dieses Szenario zeigt

## Die Ergebnisse: die Registerkarten, die Ansichtsleiste und die Kennwerte

results =
    .aria-label = Ergebnisse
tabs =
    .aria-label = Ansichten
tab-plots = Verläufe
tab-walkthrough = Entwurfsdurchgang
tab-lessons = Lektionen
tab-analysis = Analyse
tab-challenge = Aufgabe
present-button = Präsentation
    .title = Größere Schrift und Diagramme für den Projektor; die Einstellungen wandern in ein ausklappbares Seitenfeld
view-full-run = Ganzer Lauf
    .title = Zeigt in jedem Diagramm den ganzen Lauf (auch per Doppelklick auf ein Diagramm oder mit Esc)
view-fit = y-Achsen nach dem Anlaufvorgang anpassen
# $ms is the time the start-up transient ends, in milliseconds (8.5).
view-fit-from = y-Achsen nach dem Anlaufvorgang anpassen (t ≥ { $ms } ms)
view-fit-why = Warum dieser Zeitpunkt?
# $reason is the core's explanation of where the start-up transient ends.
view-transient-reason = Anlaufvorgang: { $reason }.
figures-all = Alle Kennwerte
figures-fewer = Weniger Kennwerte
figures-strip =
    .aria-label = Kennwerte des Laufs
plots-hint = Ziehen Sie über ein Diagramm, um alle zu vergrößern; Doppelklick, Esc oder „Ganzer Lauf“ zeigt wieder den ganzen Lauf. Die Legende nennt die aufgezeichneten Werte am Abtastwert unter dem Mauszeiger; klicken Sie auf ein Diagramm, um jeden Term zu diesem Zeitpunkt zu untersuchen.

## Die angehefteten Läufe und ihre Überlagerung (Registerkarte „Verläufe“)

pins-pin = Diesen Lauf anheften
# Labels the menu of the column the overlay compares.
pins-overlay = Überlagerung
pins-column-omega = Drehzahl ω
pins-column-omega-hat = Geschätzte Drehzahl ω̂
pins-column-flux = Fluss |φ|
pins-column-voltage = Spannung u_sa
pins-unpin = Lösen
# A pinned run in the list: $n is its number (1), $legend how its settings differ from the current run's (k1=600).
pins-item = Pin { $n }: { $legend }
# A pinned run's name in the overlay's legend; $n is its number (1).
pins-name = Pin { $n }
# The current run, in the overlay's legend.
pins-current = aktuell
# The difference between the current run and pinned run $n, in the overlay's legend.
pins-difference = aktuell − Pin { $n }
# The overlay's title; $column is the column compared, as the overlay's menu names it (speed ω).
pins-overlay-title = { $column }: aktueller Lauf und angeheftete Läufe
pins-difference-title = { $column }: aktuell − Pin
# $n is the pin being run (2), $count how many are run (3), $percent how much of it is done (45).
pins-status-running = Pin { $n } von { $count } wird gerechnet: { $percent } %
pins-status-done = Angeheftet
pins-status-cancelled = Anheften abgebrochen
# $length is the length of the address's pins part in characters, $max the most it may have.
pins-link-too-long = Die Pins in der Adresse wurden nicht gerechnet: { $length } Zeichen, mehr als die { $max }, die ein Pin-Fragment enthalten darf.
# $pins lists the pins that could not be read, each quoted; $count is how many there are.
pins-link-malformed = In der Adresse ignoriert, da fehlerhaft: { $pins }.
# $sent is how many pins were run (5), $dropped how many more the address held.
pins-link-dropped = Nur die ersten { $sent } Pins der Adresse wurden gerechnet; { $dropped } weitere wurden ausgelassen.
# A run that could not be pinned: the first of a list (the others follow with pins-rejected-next,
# separated by semicolons). $scenario is its scenario, $reason why.
pins-rejected-first = { $scenario } konnte nicht angeheftet werden: { $reason }
pins-rejected-next = { $scenario } konnte nicht angeheftet werden: { $reason }
# The sentence of the runs that could not be pinned; $list holds them (pins-rejected-first, pins-rejected-next).
pins-rejected = { $list }.
# Why a run was not pinned: pinning was cancelled before it started, or while it ran.
pins-reason-unrun = nicht gerechnet: Das Anheften wurde abgebrochen
pins-reason-cancelled = abgebrochen

## Listen in Meldungen

# A list cut after its first few items; $list holds those, $count is how many more there are.
list-more = { $list } … und { $count } weitere

## Die Statuszeile und die Meldungen des Laufs

# $samples is the number of samples the run computes.
run-status-starting = { $samples } Abtastwerte werden gerechnet…
run-status-progress = Läuft: { $done } von { $total } Abtastwerten
# $ms is how long the run took, in milliseconds.
run-status-done = { $rows } Abtastwerte in { $ms } ms
run-status-ran-away = Divergiert: { $rows } Abtastwerte in { $ms } ms
run-status-stopped = Angehalten nach { $rows } Abtastwerten
# $percent is how much of the run was done (45).
run-status-cancelled = Abgebrochen bei { $percent } %
run-status-worker-failed = Angehalten: Der Simulations-Worker ist ausgefallen
# $reason is the core's explanation of why the run stopped; $rows the samples computed before.
run-stopped-early = Der Lauf endete vorzeitig: { $reason }. Die Diagramme zeigen die { $rows } Abtastwerte davor.
# $warning is the core's sentence saying that the run ran away.
run-ran-away = { $warning } Die Diagramme zeigen, was der Motor getan hat.
run-worker-not-started = Der Simulations-Worker konnte nicht starten ({ $reason }). Laden Sie die Seite neu, um es erneut zu versuchen.
run-worker-failed = Der Simulations-Worker ist ausgefallen ({ $reason }). Er wurde neu gestartet; drücken Sie „Starten“, um es erneut zu versuchen.
# $pins lists the scenarios of the pinned runs, separated by semicolons.
run-worker-failed-pins = Der Simulations-Worker ist ausgefallen ({ $reason }). Er wurde neu gestartet; drücken Sie „Starten“, um es erneut zu versuchen. Die angehefteten Läufe wurden verworfen: { $pins }.
# $language is the code of the language asked for (de).
page-language-failed = Die Seite konnte ihre Texte für { $language } nicht laden ({ $reason }): Sie wird auf Englisch angezeigt.
page-messages-failed = Die übrigen Texte der Seite konnten nicht geladen werden ({ $reason }). Werkzeuge, Lektionen und Entwurfsdurchgang brauchen sie: Beim nächsten Aufruf wird es erneut versucht.
page-challenge-tools-failed = Aufgabeneditor und Bewertung der Registerkarte „Aufgabe“ konnten nicht geladen werden: { $reason }. Öffnen Sie die Registerkarte erneut, um es noch einmal zu versuchen.
page-lesson-map-failed = Die Karte der Lektion wurde nicht gelesen: { $reason }.
# $lesson is the name the address asked for; $lessons lists the lessons' names.
page-no-lesson = Keine Lektion namens „{ $lesson }“. Lektionen: { $lessons }.
# Why a lesson's link could not be compared with the lesson's run: these complete the lesson
# panel's sentence "This link holds settings of its own, … : …" (lesson-own-settings).
lesson-differences-refused = Der Kern hat einige davon zurückgewiesen ({ $reason })
lesson-differences-uncompared = Sie ließen sich nicht mit ihm vergleichen

## Warum der Simulations-Worker ausgefallen ist (der $reason der Meldungen oben)

worker-unknown-error = unbekannter Fehler
worker-unreadable = eine Nachricht von ihm war nicht lesbar
# $error is the browser's error; $panic the core's own message.
worker-crash-panic = { $error }; Rust-Panic: { $panic }
worker-crash-memory = { $error }; höchstwahrscheinlich ist dem Kern der Speicher ausgegangen
# A worker of the analyses' pool failed; $reason says why.
pool-worker-failed = ein Worker ist ausgefallen ({ $reason })
pool-worker-failed-restart = ein Worker ist ausgefallen ({ $reason }); der nächste Lauf startet einen neuen
# $reason is the browser's error.
worker-tools-not-loaded = Die Werkzeuge konnten nicht geladen werden ({ $reason }): Prüfen Sie die Verbindung und versuchen Sie es erneut.
# $reason is the core's error.
compare-failed = Vergleich fehlgeschlagen: { $reason }
compare-running = Beide Prädiktoren werden gerechnet…

## Exporte

export-csv-starting = CSV wird exportiert…
export-csv-progress = CSV wird exportiert: { $rows } von { $total } Zeilen
export-csv-done = CSV exportiert: { $total } Zeilen
export-csv-cancelled = CSV-Export abgebrochen
export-csv-cancelled-by-run = Der CSV-Export wurde abgebrochen: Ein neuer Lauf hat begonnen.
export-csv-stopped = CSV-Export angehalten
export-csv-failed-status = CSV-Export fehlgeschlagen
# $reason is the core's error, or export-csv-gone.
export-csv-failed = Der CSV-Export ist fehlgeschlagen: { $reason }.
export-csv-gone = Der Worker hält diesen Lauf nicht mehr; starten Sie ihn erneut
# $megabytes is how much of the CSV the browser held; $error the browser's error's name;
# $command the command line that exports the run (not translated).
export-csv-refused = Der Browser hat es abgelehnt, mehr als { $megabytes } MB CSV zu halten ({ $error }). Exportieren Sie diesen Lauf stattdessen über die Kommandozeile: { $command }
export-png-not-ready = Diese Diagramme werden noch gezeichnet; exportieren Sie sie gleich noch einmal.

## Teilen

share-link-copied = Link kopiert: Er reproduziert diesen Lauf bitgenau.
# $link is the page's address.
share-copy-this-link = Kopieren Sie diesen Link: { $link }
# The title of an embedded frame, read by screen readers: $preset is the preset's name, $plots the plots' ids (speed, flux).
share-embed-title = IM Lab: { $preset }, { $plots }
# $plots lists the plots' ids (speed, flux); $count is how many.
share-embed-copied =
    Embed-Code kopiert: { $count ->
        [one] das Diagramm
       *[other] die Diagramme
    } { $plots } dieses Laufs (die sichtbaren Diagramme der Registerkarte „Verläufe“). Fügen Sie ihn in eine Folie oder eine Kursseite ein.
# $code is the HTML code to copy.
share-embed-copy-this =
    Kopieren Sie diesen Embed-Code für { $count ->
        [one] das Diagramm
       *[other] die Diagramme
    } { $plots } dieses Laufs (die sichtbaren Diagramme der Registerkarte „Verläufe“): { $code }
# $names lists the unknown plot ids the address asked for, each quoted, $count how many;
# $shown the plots shown instead; $plots every plot's id.
embed-unknown-plots = Kein Diagramm namens { $names }; gezeigt wird stattdessen { $shown }. Diagramme: { $plots }.

## Ein Ergebnis eines früheren Szenarios als das der Einstellungen ($scenario ist dieses Szenario)


## Das eigene Regelgesetz eines Schritts (das Einstellungsformular und der Entwurfsdurchgang)

# $step is the step's number (1 to 4); v{ $step } names its control law (v1).
law-paper-default = Noch kein eigenes Regelgesetz: Dieser Schritt verwendet v{ $step } des Artikels.

## Das Einstellungsformular

settings-group-reference = Sollwert
settings-group-controller = Regler: Backstepping oder klassische IFOC
settings-group-gains = Backstepping-Verstärkungen
settings-group-observer = Beobachter (EKF)
settings-group-noise = Rauschen und Startwert
settings-group-plant = Strecke: der simulierte Motor
settings-group-model = Modell: was EKF und Regler annehmen
settings-group-load = Unbekannte Last: ein Sprung oder eine Tabelle von Punkten
settings-group-limits = Spannungsgrenze (Rechteck), Nennstrom, Dauer und Zeitschritte
settings-group-drive = Antrieb: Rechentotzeit, Wechselrichtergrenze und PWM
settings-group-law = Eigene Regelgesetze für die Backstepping-Schritte (leer: die des Artikels)
# The values a field allows, under it and in its tooltip (settings-allowed).
settings-allowed-formula = eine Formel in den Namen, die „Diesen Schritt selbst schreiben“ im Entwurfsdurchgang auflistet; leer: das Regelgesetz des Artikels
# $min and $max are the least and the largest value ($max with the field's unit: 20 s), $op is < or ≤,
# $key the field's key (duration).
settings-allowed-range = { $min } { $op } { $key } ≤ { $max }
# A table of points: $points points at most; $min and $max bound the values ($max with their unit).
settings-allowed-table = bis zu { $points } Punkte t:value, etwa 0:0,0.1:100, Zeiten ab 0 steigend; Werte von { $min } bis { $max }
settings-allowed-whole = { $min } { $op } { $key } ≤ { $max }, ganze Zahl
# $values is what the field allows (settings-allowed-range, or its options: euler | rk4).
settings-allowed = zulässig: { $values }
# $list holds the core's reasons, separated by semicolons.
settings-link-rejected = Einige Einstellungen in der Adresse wurden zurückgewiesen und auf den Werten der Vorlage belassen: { $list }.
# $preset is the preset shown instead.
settings-link-refused = Das Szenario in der Adresse wurde zurückgewiesen: { $reason }. Stattdessen wird { $preset } gezeigt.
# $description is the core's description of the preset; $fields lists the keys of the settings changed (k1, duration).
settings-preset-changed = Vorlage { $preset }: { $description }. Dieser Lauf ändert { $fields }; was die Beschreibung der Vorlage über ihren Lauf sagt, muss für diesen also nicht gelten.
settings-idle = { $changed } Ignoriert: { $idle }.
settings-idle-separator = {"; "}

## Die Kennwertleiste und die wichtigsten Kennwerte

# A current as a multiple of the motor's rated current: $value is the current (20.33 A),
# $ratio the multiple (5.08), $rated the rated current (4).
figures-to-rated = { $value } (das { $ratio }-Fache des Nennstroms von { $rated } A)
# The mean NIS ($value) and its 95 % band, from $low to $high.
figures-nis-inside = { $value } (95-%-Band { $low }–{ $high }: innerhalb)
figures-nis-outside = { $value } (95-%-Band { $low }–{ $high }: außerhalb)
# The tooltip of a figure: $value is its exact value with its unit, $window the core's words for the part of the run it covers.
figures-exact = exakt: { $value }; { $window }
# The tooltip of a figure the run had not reached: $reason is the core's words for it.
figures-no-value = kein Wert: { $reason }; { $window }
# Whether a final value had settled by the end of the run. $rate, $scatter, $tolerance and $to-go
# are values with their unit (0.5 rad/s).
figures-trend-settled = bis zum Ende des Laufs eingeschwungen
figures-trend-ran-away = der Lauf ist divergiert: kein Endwert
figures-trend-drifting = driftet mit dem Random-Walk-Schätzwert des EKF für die Last oder R_r: Ein längerer Lauf endet anderswo
figures-trend-fluctuating = schwankt um ±{ $scatter }: Der letzte Abtastwert ist kein Endwert
figures-trend-changing = ändert sich noch: { $rate } pro s am Ende; Lauf verlängern
figures-trend-changing-to-go = ändert sich noch: { $rate } pro s am Ende; Lauf verlängern (es fehlen noch etwa { $to-go })
# The tooltip of a final value's trend: $ms is the length of the end of the run the line is fitted to.
figures-trend-fit = Gerade durch die letzten { $ms } ms: { $rate } pro s, mit einer Streuung der Abtastwerte von { $scatter } um sie; eingeschwungen heißt: Die Gerade bewegt sich um höchstens { $tolerance }, und das Vierfache der Streuung passt in diese Toleranz
figures-trend-fit-approach = Gerade durch die letzten { $ms } ms: { $rate } pro s, mit einer Streuung der Abtastwerte von { $scatter } um sie; die Mittelwerte der letzten drei Zehntel nähern sich einem Wert, der { $to-go } entfernt liegt; eingeschwungen heißt: Die Gerade bewegt sich um höchstens { $tolerance }, und das Vierfache der Streuung passt in diese Toleranz
# The key figures row: $value is a value with its unit; $ratio a multiple of the rated current.
figures-key-peak = Spitzenwert |i_s| { $value } ({ $ratio }× Nennstrom)
figures-key-final =
    ω − ω_d am Ende { $value } ({ $trend ->
        [settled] eingeschwungen
        [changing] ändert sich noch
        [drifting] driftet
        [fluctuating] schwankt
       *[ran-away] divergiert
    })
figures-key-nis-inside = mittlerer NIS { $value } (innerhalb seines 95-%-Bands)
figures-key-nis-outside = mittlerer NIS { $value } (außerhalb seines 95-%-Bands)
# The plots' text alternative carries the figures: $figures lists them, separated by semicolons.
figures-caption = Kennwerte dieses Laufs: { $figures }.

## Die Diagramme

plot-speed = Rotordrehzahl
plot-speed-reference = ω_d Sollwert
plot-speed-estimated = ω̂ geschätzt
plot-speed-true = ω wahr
plot-speed-error = Drehzahl-Folgefehler ω − ω_d
plot-flux = Betrag des Rotorflusses
plot-flux-target = √ψ_d Ziel
plot-flux-estimated = |φ̂| geschätzt
plot-flux-true = |φ| wahr
plot-current = Statorströme
plot-current-a-estimated = î_sa geschätzt
plot-current-b-estimated = î_sb geschätzt
plot-current-a-true = i_sa wahr
plot-current-b-true = i_sb wahr
plot-voltage = Angelegte Statorspannungen (nach der Begrenzung)
# The voltage limit's lines on the voltage plot.
plot-voltage-limit-high = +Grenze
plot-voltage-limit-low = −Grenze
plot-z13 = Folgefehler
# "right": the series is read on the plot's right-hand axis.
plot-z13-flux = z3 = |φ̂|² − ψ_d (Wb², rechts)
plot-z24 = Fehler der virtuellen Stellgrößen
plot-z24-torque = z2 Drehmomentfehler (rad/s²)
plot-z24-flux = z4 Fehler der Flussänderungsrate (Wb²/s, rechts)
plot-est = Schätzfehler
plot-est-flux = |φ| − |φ̂| (Wb, rechts)
# A backstepping plot's title ($title) when the classical IFOC drives the motor.
plot-not-driving = { $title } (zum Vergleich berechnet; treibt den Motor nicht)
# A plot's text alternative: $title is its title, $unit its axis's unit, $signals its series' names.
plot-caption = { $title }, in { $unit } über der Zeit t in s. Signale: { $signals }.
plot-caption-two-axes = { $title }, in { $unit } (links) und { $unit2 } (rechts) über der Zeit t in s. Signale: { $signals }.
plot-caption-keys = Fokussieren Sie das Diagramm und untersuchen Sie den Lauf mit den Pfeiltasten Abtastwert für Abtastwert (Umschalttaste: 1 % des Fensters).

## Die Registerkarte „Analyse“


## Die Registerkarte „Lektionen“


## Die Registerkarte „Aufgabe“


## The challenge panel's controls, built with the page

challenge-progress =
    .aria-label = Erledigte Läufe der Aufgabe
challenge-cancel = Prüfung abbrechen
challenge-copy = Abgabelink kopieren
challenge-open-failed = Die Aufgabe konnte nicht geöffnet werden: { $reason }. Die Seite zeigt stattdessen das Standardszenario.
law-checking = Ihr Regelgesetz wird an der Entwurfsdynamik geprüft…
law-verdict-failed = Der Befund zu Ihrem Regelgesetz konnte nicht berechnet werden: { $reason }
walkthrough-load-failed = Der Entwurfsdurchgang konnte nicht geladen werden: Prüfen Sie die Verbindung und laden Sie die Seite neu.
lesson-panel =
    .aria-label = Lektion
challenge-panel =
    .aria-label = Aufgabe
stale-back = Zurück zu diesem Szenario
