sweep-not-settled = nicht eingeschwungen: In den letzten { $periods } Perioden änderten sich Verstärkung und Phase von ω von der ersten zur zweiten Hälfte um { $gain } dB bzw. { $phase }° (eingeschwungen: innerhalb von ±{ $gain-bound } dB und ±{ $phase-bound }°)

## Die Achsen und Startwerte einer Modellfehlerkarte: warum sie zurückgewiesen werden, und der Name einer Achse.
map-axis-form = Achse '{ $axis }': Erwartet wird KEY=LO..HI:N, z. B. plant.rr=-10%..+10%:11 oder k1=-20%..+20%:5
map-axis-unknown = Achse '{ $axis }': { $key } ist kein Feld eines Szenarios
map-axis-not-numeric = Achse '{ $axis }': { $key } ist keine Zahl; eine Karte variiert numerische Felder
map-axis-whole = Achse '{ $axis }': { $key } nimmt nur ganze Zahlen an; wählen Sie für die Karte ein kontinuierliches Feld
map-axis-inactive = Achse '{ $axis }': { $key } hat in diesem Szenario keine Wirkung, jede Zelle würde also gleich laufen
map-axis-end = Achse { $key }: { $end } '{ $text }': Erwartet wird eine Zahl oder ein Prozentwert wie -10%
map-axis-mixed = Achse '{ $axis }': LO und HI müssen beide Werte oder beide Prozentwerte sein
map-axis-count = Achse { $key }: N '{ $text }': Erwartet wird eine ganze Zahl von 1 bis { $max }
map-axis-zero = Achse '{ $axis }': { $other } ist 0, ein relativer Fehler dazu ist also ebenfalls 0; geben Sie { $key } in Werten an
map-axis-order = Achse { $key }: LO ({ $lo }) liegt über HI ({ $hi })
map-axis-against-model = { $key } gegenüber dem Modell (%)
map-axis-against-motor = { $key } gegenüber dem Motor (%)
map-axis-against-base = { $key } gegenüber dem Basiswert (%)
map-axis-unit = { $key } ({ $unit })
map-seeds-form = Startwerte '{ $seeds }': Erwartet wird A..B, ganze Zahlen von 0 bis { $max }
map-seeds-order = Startwerte '{ $seeds }': Der erste Startwert liegt über dem letzten
map-seeds-many = Startwerte '{ $seeds }': { $count } Startwerte, mehr als die { $max }, die eine Karte rechnet
map-seeds-twice = Die Startwerte sind zweimal angegeben: Geben Sie sie nur einmal an
map-axes-count = { $count } Achsen: Eine Karte hat eine oder zwei
map-axes-repeated = Beide Achsen variieren { $key }: Variieren Sie zwei verschiedene Felder
map-axes-sides = Die Achsen variieren { $first } und { $second }, beide Seiten desselben Parameters: Variieren Sie nur eine Seite, angegeben in Werten oder als relativer Fehler gegenüber der anderen
map-no-seeds = Keine Startwerte: Eine Karte rechnet mindestens einen
map-runs-many = Die Karte braucht { $runs } Läufe ({ $cells } Zellen × { $seeds } Startwerte), mehr als die zulässigen { $max }; verwenden Sie weniger Punkte oder Startwerte
map-cell-refused = { $key }={ $value }: { $reason }
map-work = Die Karte braucht { $work } Schritte der Strecke ({ $cells } Zellen × { $seeds } Startwerte × die Schritte eines Laufs), mehr als die zulässigen { $max }; verwenden Sie weniger Punkte oder Startwerte oder eine kürzere 'duration'
map-law-work = Die eigenen Regelgesetze der Karte brauchen { $work } Operationen ({ $cells } Zellen × { $seeds } Startwerte × bis zu { $per-run } je Lauf), mehr als die zulässigen { $max }; verwenden Sie höchstens { $runs } Läufe (Zellen × Startwerte), eine kürzere 'duration' oder Regelgesetze mit weniger Operationen

## Der abgeleitete Entwurf (design=derived): die Regel hinter jedem Wert, mit ihrer Begründung.
# $voltage: verkettete Nennspannung (V effektiv); $frequency: Nennfrequenz (Hz).
design-rule-vdc = √2 × { $voltage } V, die gleichgerichtete Netzspannung; vlimit=circle, die Spannungsgrenze ist also die Amplitude vdc/√3 der Nennphasenspannung
design-rule-flux = der Rotorfluss bei { $voltage } V, { $frequency } Hz und Leerlauf, M·V/|Rs + jωLs|: die eigene Magnetisierung des Motors
design-rule-flux-capped = begrenzt auf M·i_rated/√2 (der Leerlauffluss bei { $voltage } V, { $frequency } Hz verlangt mehr): Der Magnetisierungsstrom lässt die Hälfte von i_rated² für das Drehmoment
design-rule-psi = das Quadrat des Flusses, das Ziel für φa² + φb²
design-rule-id = Magnetisierungsstrom, flux/M
# $i_rated: die Amplitude des Nennstroms (A).
design-rule-iq = momentbildender Strom, √({ $i_rated }² − i_d²): der Rest des Nennstroms
design-rule-torque = Drehmoment bei Nennstrom und Nennfluss, (3/2)·np·(M/Lr)·flux·i_q
design-rule-accel = Nennbeschleunigung, torque/J: die Steigung der Reversierung, die der Motor mit Nennstrom schafft
# $share: Prozent der Spannungsgrenze.
design-rule-base = Eckdrehzahl: Nennfluss und momentbildender Nennstrom brauchen dort stationär { $share } % der Spannungsgrenze; darüber senkt fw=1 den Fluss wie base/ω und hält so die induzierte Gegenspannung, und der Rest der Spannung ist die Reserve der Stromregelkreise
# $kts: k·Ts; $share: Prozent der Spannungsgrenze; $sigma: Streuinduktivität σ (H).
design-rule-gain-ts = k2 = k3 = k4 = { $kts }/Ts: Jeder Fehler darf je Abtastschritt um das { $kts }-Fache seiner selbst sinken, wie die 1200/s des Artikels bei 20 kHz; die Spannungsschranke, { $share } % der Grenze durch σ·i_rated (σ = { $sigma } H), liegt höher
design-rule-gain-voltage = k2 = k3 = k4 = { $share } % der Spannungsgrenze durch σ·i_rated (σ = { $sigma } H): Einen Fehler in Höhe des Nennstroms mit dieser Rate abzubauen, verlangt ein Viertel der Spannung; die Abtastschranke { $kts }/Ts liegt höher
# $ratio: k1 durch k2.
design-rule-k1 = k1 = { $ratio } × k2: Der Drehzahlregelkreis ist langsamer als der Strom, den er vorgibt
design-rule-q = Prozessrauschen: Das Modell ist der Motor und wird wie die Strecke integriert, also ist Q nur eine Untergrenze, die die Verstärkung des Filters am Leben hält; mit den 1e-3 des Artikels läge der NIS dieser Motoren unter seinem Band
design-rule-r = das Rauschen des Stromsensors: R entspricht ihm
design-rule-r-none = kein Sensorrauschen: r_std = i_rated/1000, damit die Verstärkung des Filters endlich bleibt
# $time: Sekunden.
design-rule-q-load = torque²/{ $time } s: Die Last darf sich in { $time } s um ihr Nennmoment ändern
design-rule-load-std = torque/4: Die Last ist anfangs bis auf ein Viertel des Nennmoments unbekannt
# Unter der Beschreibung der Vorlage, wenn das Szenario design=derived hat.
design-derived-heading = Der aus dem Motor abgeleitete Entwurf und die Regel hinter jedem Wert
# $reason: warum der Kern ihn nicht ableiten konnte.
design-failed = Der abgeleitete Entwurf konnte nicht angezeigt werden: { $reason }

## Ein Motor aus Typenschild und Laborversuchen (`imlab motor`, die Registerkarte „Analyse“)

# $key ist das Feld (rs, no-load, locked, nema, rated, j, np), $value die Eingabe.
identify-bad-field = '{ $key }' = '{ $value }': Erwartet wird { $expected }
identify-expect-positive = eine positive Zahl
identify-expect-whole = eine ganze Zahl von mindestens 1
identify-expect-nema = A, B, C oder D
identify-expect-rated = V,F,I: die verkettete Nennspannung (V effektiv), die Nennfrequenz (Hz) und der Nennstrom (A effektiv), positiv und durch Kommas getrennt
identify-expect-reading = V,I,P,F: verkettete Spannung (V effektiv), Leiterstrom (A effektiv), aufgenommene Leistung (W) und Frequenz (Hz), durch Kommas getrennt; die Leistung darf 0 sein, die übrigen Werte sind positiv
# $what ist die Größe einer Messung, wie der Code sie nennt (voltage, current, frequency, power, rs).
identify-not-positive = { $what } muss eine positive Zahl sein
# $test ist das Feld des Versuchs: no-load oder locked.
identify-power-too-high = '{ $test }': Die Leistung des Versuchs ist größer, als √3·V·I zulässt, sein Widerstand wäre also größer als seine Impedanz
identify-no-rotor-resistance = 'locked': Der Widerstand je Strang im Kurzschlussversuch, { $locked } Ω, ist nicht größer als der Statorwiderstand von { $rs } Ω, für den Rotorwiderstand bleibt also nichts übrig
identify-no-magnetising = 'no-load': Die Leerlaufreaktanz ist nicht größer als die Streureaktanz des Stators, für die Magnetisierungsreaktanz bleibt also nichts übrig
# $stator und $rotor sind die Anteile der Streuung (0.5 und 0.5), $letter der NEMA-Designbuchstabe.
identify-heading = das Ersatzschaltbild aus Leerlauf- und Kurzschlussversuch (IEEE Std 112), die Streuung aus dem Kurzschlussversuch im Verhältnis { $stator }/{ $rotor } auf Stator und Rotor aufgeteilt (NEMA-Design { $letter })
identify-how-rs = Gleichstrommessung
identify-how-rr = Schätzwert: Widerstand im Kurzschlussversuch abzüglich rs, über den Magnetisierungszweig auf den Rotorwiderstand umgerechnet
identify-how-m = Schätzwert: Leerlaufreaktanz abzüglich der Streureaktanz des Stators
identify-how-ls = Schätzwert: m plus der Statoranteil der Streuung aus dem Kurzschlussversuch
identify-how-lr = Schätzwert: m plus der Rotoranteil der Streuung aus dem Kurzschlussversuch
identify-how-given = vorgegeben
identify-link-heading = der Motor in der Vorlage step, als Strecke und Modell zugleich, mit seinen Nenndaten (Nennspannung, Nennfrequenz, Nennstrom) und dem abgeleiteten Entwurf:
