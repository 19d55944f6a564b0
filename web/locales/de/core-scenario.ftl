# Die Meldungen des Kerns zu einem Szenario: warum ein Link, eine Einstellung oder ein Lauf
# zurückgewiesen wurde. Die Kommandozeile gibt sie aus der englischen Datei aus, die Seite in der
# Sprache der Lesenden. Feldnamen, Schlüssel, Werte, Vorlagen und Einstellungen (v=1, preset=NAME,
# 'duration', 'ts', law.v2, pwm=1) sind die eigenen Worte des Links: unverändert lassen. Zitierte
# Eingaben behalten ihre Anführungszeichen.

## Ein zurückgewiesenes Szenario

scenario-missing = Feld '{ $key }' fehlt (ein Szenario beginnt mit v={ $version }&preset=NAME)
scenario-unsupported-version = Feld 'v' = '{ $value }': nicht unterstützte Codec-Version, zulässig: { $version }
# $presets lists the presets' names.
scenario-unknown-preset = Feld 'preset' = '{ $name }': unbekannte Vorlage, zulässig: { $presets }
scenario-unknown-key = Feld '{ $key }' ist kein Feld eines Szenarios (das Einstellungsformular und `imlab describe` führen sie auf)
scenario-duplicate-key = Feld '{ $key }' ist mehrfach angegeben
scenario-malformed = '{ $piece }' hat nicht die Form Schlüssel=Wert
# $expected is one of the scenario-expected-* messages.
scenario-bad-value = Feld '{ $key }' = '{ $value }': ungültig, erwartet wird { $expected }
# $allowed is one of the scenario-allowed-* messages.
scenario-out-of-range = Feld '{ $key }' = { $value }: außerhalb des Bereichs, zulässig: { $allowed }
# $reference is the kind of reference the scenario has (step, sine, ramp…).
scenario-not-applicable = Feld '{ $key }' gilt nicht für die Sollwertform '{ $reference }' (zuerst ref= setzen)
# $which is "plant" or "model", the prefix of the fields; $error is a param-* message.
scenario-physics = { $which ->
        [plant] Parameter der Strecke ({ $which })
       *[model] Parameter des Modells ({ $which })
    }: { $error }
# $error says where and why the formula was refused.
scenario-bad-formula = Feld '{ $key }': { $error }
scenario-refused = Feld '{ $key }': { $why }
scenario-law-fw = Ein eigenes Regelgesetz für Schritt 3 oder 4 ist für ein konstantes Flussziel geschrieben, und fw=1 verschiebt es; schalten Sie fw aus oder lassen Sie das Regelgesetz leer
scenario-design = Feld 'design' = 'derived': { $why }
design-no-voltage = Die Nennspannung lässt { $available } V für den stationären Betrieb, Nennfluss mit Nennstrom braucht aber schon im Stillstand { $needed } V
scenario-too-long = Das Szenario ist { $bytes } Bytes lang, mehr als die zulässigen { $max } Bytes ({ $kib } KiB)

## Was ein Feld annimmt

scenario-expected-formula = eine Formel, prozentkodiert als UTF-8
scenario-expected-one-of = eines von { $options }
scenario-expected-number = eine Dezimalzahl
# A table of points: a reference or a load torque given as t:value pairs.
scenario-expected-table = eine durch Kommas getrennte Liste von Punkten t:value wie 0:0,0.1:100, jede Zahl eine Dezimalzahl
scenario-expected-table-length = höchstens { $max } Punkte; diese Tabelle hat { $count }
scenario-expected-table-rising = von Punkt zu Punkt steigende Zeiten; { $after } s liegt nicht nach { $before } s
scenario-expected-table-time = Zeiten von 0 bis { $max } s; { $t } s liegt außerhalb
# $unit is the values' unit (rad/s); $before and $after are the times of the two points.
scenario-expected-table-slope = eine Änderung um höchstens { $max } { $unit } pro Sekunde zwischen den Punkten; von { $before } s bis { $after } s ist sie schneller
scenario-allowed-choice = { $options }
scenario-allowed-formula = eine Formel in den Namen, die Schritt { $step } verwenden darf (`imlab describe` führt sie auf), oder leer
# $values is the values' range (scenario-allowed-unit).
scenario-allowed-table = bis zu { $max } Punkte t:value, Zeiten von 0 bis { $duration } s steigend, Werte { $values }; zwischen den Punkten geradlinig, vor dem ersten und nach dem letzten Punkt gehalten
# A field's range: "0 < k1 ≤ 1000000"; $below is < or ≤.
scenario-allowed-range = { $min } { $below } { $key } ≤ { $max }
# $range is the range above, with its unit after it: "0 < k1 ≤ 1000000 (1/s)".
scenario-allowed-unit = { $range } ({ $unit })
scenario-allowed-whole = { $range }, ganze Zahl
scenario-allowed-pwm = pwm=1 mit vlimit=circle oder hex: Ein Zweipunkt-Wechselrichter kann die Ecken des Rechtecks nicht erzeugen

## Ein zu großer Lauf

scenario-too-many-samples = 'duration'/'ts' = { $duration } s / { $ts } s = { $samples } Abtastwerte sind mehr als die zulässigen { $max }; verkürzen Sie 'duration' oder erhöhen Sie 'ts'
scenario-shorter-than-sample = 'duration' = { $duration } s ist kürzer als ein Abtastschritt, 'ts' = { $ts } s
# $how is one of the scenario-work-* messages; $pwm is yes when the run has PWM.
scenario-too-much-work = Der Rechenaufwand des Laufs, { $samples } Abtastwerte ('duration'/'ts' = { $duration } s / { $ts } s) × { $per_sample } RK4-Schritte der Strecke je Abtastwert ({ $how }) = { $work } Schritte, ist größer als die zulässigen { $max }; verringern Sie 'substeps' oder 'duration' oder erhöhen Sie 'ts'{ $pwm ->
        [yes] , oder schalten Sie 'pwm' aus
       *[no] {""}
    }
scenario-work-substeps = 'substeps' = { $substeps }
scenario-work-substeps-pwm = 'substeps' = { $substeps } in jedem der 7 PWM-Intervalle
scenario-work-prediction = { $plant } und { $substeps } für die Prädiktion des idealen Beobachters ('delay.comp')
# $parts lists scenario-law-work-step and scenario-law-work-rates messages.
scenario-law-work = Der Rechenaufwand der Regelgesetze, { $samples } Abtastwerte ('duration'/'ts' = { $duration } s / { $ts } s) × { $per_sample } Operationen je Abtastwert ({ $parts }) = { $work }, ist größer als die zulässigen { $max } (ein Sinus oder Kosinus zählt 64 Operationen, eine Potenz 32, exp, ln, tanh und atan2 je 12); schreiben Sie Regelgesetze mit höchstens { $fits } Operationen je Abtastwert, verkürzen Sie 'duration' auf { $duration_fit } s oder erhöhen Sie 'ts' auf { $ts_fit } s
scenario-law-work-step = law.v{ $step } { $work }
scenario-law-work-rates = die Änderungsraten der eigenen v1 und v3 { $work }
# $fewer is yes when the caller can keep every n-th sample.
scenario-trace-too-large = Die Aufzeichnung von { $rows } Abtastwerten × { $columns } Spalten braucht { $mib } MiB, mehr als die zulässigen { $max } MiB; verkürzen Sie 'duration' oder erhöhen Sie 'ts'{ $fewer ->
        [yes] , oder behalten Sie weniger Abtastwerte (ein größeres 'every')
       *[no] {""}
    }
sweep-run-too-large = Jeder Lauf des Frequenzgangs behält seine { $samples } Abtastwerte, { $mib } MiB, mehr als die zulässigen { $max } MiB; verkürzen Sie die Laufdauer des Frequenzgangs oder erhöhen Sie 'ts'

## Motorparameter, die physikalisch nicht möglich sind

param-not-positive = { $name } = { $value } muss eine endliche Zahl > 0 sein
param-negative = { $name } = { $value } muss eine endliche Zahl ≥ 0 sein
param-sigma = Streuinduktivität σ = Ls − M²/Lr = { $sigma } H muss > 0 sein (M = { $m }, Ls = { $ls }, Lr = { $lr }): M² muss kleiner als Ls·Lr sein
scenario-allowed-every = 1 ≤ every

## Ein zurückgewiesener Lauf des Frequenzgangs

sweep-allowed-amp = 0 < sine.amp für einen Frequenzgang
sweep-allowed-nyquist = unterhalb der Nyquist-Frequenz 1/(2·Ts) = { $nyquist } Hz
sweep-allowed-period = mindestens eine Periode im Anpassungsfenster: freq ≥ { $least } Hz bei einem Lauf von { $duration } s
# $reason is sweep-unresolved or sweep-too-small.
sweep-allowed-measurable = eine Amplitude, die der Frequenzgang messen kann: { $reason }; erhöhen Sie die Amplitude
sweep-unresolved = Die Anpassung von ω_d selbst über das Anpassungsfenster ergibt { $found } rad/s, mehr als { $tolerance } % daneben (das Quadrat der Amplitude erzeugt einen Unterlauf, oder Offset + Amplitude wird auf den Offset { $offset } rad/s gerundet)
# $name is a figure's column name, $value its value (NaN or inf).
sweep-too-small = Bei { $freq } Hz ergibt die Systemantwort { $name } = { $value }, zu klein für die Anpassung

## Listen

# What separates the items of a list the core gives ("law.v1 12, law.v2 40").
core-list-separator = {", "}
field-idle = { $key } hat bei { $because } keine Wirkung
