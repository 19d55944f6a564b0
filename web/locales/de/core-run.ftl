# Die Worte des Kerns zu einem Lauf: was jede Einstellung bedeutet, was jede Vorlage zeigt, die
# Kennwerte eines Laufs und der Teil des Laufs, den jeder abdeckt, die Warnungen, ohne die sie nicht
# zu lesen sind, wo der Anlaufvorgang endet und warum ein Lauf anhielt. Schlüssel und Feldnamen
# (k1, law.v1, ekf.q), die Werte eines Felds (euler, rk4, box), Symbole (ω_d, φa², Rs, |i_s|),
# Einheiten, Formeln und die Gleichungs- und Abbildungsnummern des Artikels ((38), Fig 2) bleiben
# unverändert.

## Eine Zeit

# A time in milliseconds or in seconds, with up to 4 significant digits.
time-ms = { $ms } ms
time-s = { $s } s

## Was jede Einstellung bedeutet (Schlüssel, Einheit und Bereich gibt der Codec vor)

# (0/1) marks a switch: 0 off, 1 on.

field-design = Entwurf: paper (Artikel, eingestellte Werte) oder derived (aus den Motordaten)
field-ref = Art des Drehzahlsollwerts
field-ref-value = konstante Drehzahl
field-sine-amp = Amplitude des Sinus
field-sine-freq = Frequenz des Sinus
field-sine-offset = zum Sinus addierte Konstante
field-step-size = Sprunghöhe
field-step-time = Zeitpunkt des Sprungs
field-step-wn = Eigenfrequenz ωn des Sprungfilters
field-ramp-start = Startzeitpunkt der Rampe
field-ramp-level = Plateauwert der Rampe
field-ramp-slope = Betrag der Rampensteigung
field-ramp-hold = Dauer des Plateaus
field-rev-start = Hochlaufbeginn der Reversierung
field-rev-level = umgekehrte Drehzahl, +level auf −level
field-rev-slope = Betrag der Reversiersteigung
field-rev-hold = Dauer bei +level vor der Umkehr
field-ref-table = Sollwert als Tabelle von Punkten t:ω_d, zwischen ihnen geradlinig
field-psi_d = Flussziel für φa² + φb²
field-fw = Feldschwächung oberhalb der Eckdrehzahl (0/1)
field-fw-base = Eckdrehzahl der Feldschwächung
field-k1 = Abklingrate des Drehzahlfehlers k1
field-k2 = Abklingrate des Drehmomentfehlers k2 = a7 + a8 + k2s1
field-k3 = Abklingrate des Flussfehlers k3
field-k4 = Abklingrate des Fehlers der Flussänderungsrate k4
field-robust = robuste Terme (38) und (53) anwenden (0/1)
field-eps2 = ε2 aus (38): die Schranke für z2·(v2s2 + d̃2)
field-h2 = h2 aus (38): Schranke für |d̃2|
field-eps4 = ε4 aus (53): die Schranke für z4·(v4s2 + d̃4)
field-h4 = h4 aus (53): Schranke für |d̃4|
field-law-v1 = Ihr Schritt 1: die virtuelle Stellgröße v1 (leer: (26) des Artikels)
field-law-v2 = Ihr Schritt 2: v2 (leer: (34) des Artikels)
field-law-v3 = Ihr Schritt 3: die virtuelle Stellgröße v3 (leer: (45) des Artikels)
field-law-v4 = Ihr Schritt 4: v4 (leer: (49) des Artikels)
# backstepping and ifoc are the field's values: keep them as they are.
field-controller = backstepping (Artikel) oder ifoc (klassische drehgeberlose FOC zum Vergleich)
field-ifoc-bw_i = Bandbreite der IFOC-Stromregelkreise
field-ifoc-bw_w = Bandbreite des IFOC-Drehzahlregelkreises
field-ifoc-bw_mras = Bandbreite des MRAS-Drehzahlschätzers der IFOC
field-ifoc-i_max = Begrenzung des q-Stroms der IFOC
field-ifoc-ff = Drehmomentvorsteuerung der IFOC J·ω̇_d + T0 + Cf·ω_d (0/1)
# euler and rk4 are the field's values: keep them as they are.
field-ekf = EKF-Prädiktor: euler (Artikel) oder rk4
field-ekf-q = Prozessrauschen Q = q·Ts·I, ein Wert für alle Zustände: A²/s für die Ströme, (rad/s)²/s für ω, Wb²/s für die Flüsse
field-ekf-q_speed = zusätzliches Prozessrauschen nur auf dem Drehzahlzustand, Q_ωω = (q + q_speed)·Ts
field-ekf-r_std = angenommenes Stromrauschen, R = r_std²·I
field-ekf-load = Last a2 = T_L0/J als EKF-Zustand schätzen (0/1)
field-ekf-q_load = Random-Walk-Intensität des Lastmoments
field-ekf-load_std = Anfangsstandardabweichung des Lastschätzwerts
field-ekf-rr = Rotorwiderstand R_r als EKF-Zustand schätzen (0/1)
field-ekf-q_rr = Random-Walk-Intensität des Rotorwiderstands
field-ekf-rr_std = Anfangsstandardabweichung des R_r-Schätzwerts
field-init_err = relativer Anfangsfehler der Schätzwerte
field-start = Anfangszustand: paper (Artikel: 2 A, 2 A, 0,5 Wb, 0,5 Wb) oder magnetized (auf das Flussziel)
field-perfect = idealer Beobachter: Der Regler erhält den wahren Zustand (0/1)
field-noise = Standardabweichung des Strommessrauschens
field-seed = Rausch-Startwert
# The simulated motor's parameters, the plant's; the model's, what the controller and the observer
# assume, read the same.
field-motor = Motor von Strecke und Modell zugleich, samt Nennstrom
field-plant-rs = Statorwiderstand Rs
field-plant-rr = Rotorwiderstand Rr
field-plant-m = Gegeninduktivität M
field-plant-ls = Statorinduktivität Ls
field-plant-lr = Rotorinduktivität Lr
field-plant-j = Trägheitsmoment J
field-plant-np = Polpaarzahl np
field-plant-t0 = konstantes Lastmoment T0
field-plant-cf = viskose Reibung Cf
field-model-rs = { field-plant-rs }
field-model-rr = { field-plant-rr }
field-model-m = { field-plant-m }
field-model-ls = { field-plant-ls }
field-model-lr = { field-plant-lr }
field-model-j = { field-plant-j }
field-model-np = { field-plant-np }
field-model-t0 = { field-plant-t0 }
field-model-cf = { field-plant-cf }
field-load-time = Zeitpunkt des unbekannten Lastsprungs
field-load-torque = Höhe des unbekannten Lastsprungs
field-load-table = unbekanntes Lastmoment als Tabelle von Punkten t:torque, zwischen ihnen geradlinig (statt des Sprungs)
field-vmax = Spannungsgrenze je Komponente
field-duration = simulierte Zeit
field-ts = Abtastzeit Ts
field-substeps = RK4-Teilschritte der Strecke je Abtastwert
field-i_rated = Nennstrom: Amplitude |i_s| des Nennphasenstroms
field-rated-v = Nennspannung, verkettet, effektiv
field-rated-f = Nennfrequenz
field-delay = Rechentotzeit: u_k wird einen Abtastschritt später angelegt (0/1)
field-delay-comp = Totzeitkompensation: Regelung aus der Einschrittprädiktion x̂(k+1|k) (0/1)
# box, circle and hex are the field's values: keep them as they are.
field-vlimit = Spannungsgrenze: box (±vmax je Komponente, der Artikel), circle (|u| ≤ vdc/√3) oder hex (Zweipunkt-Wechselrichter)
field-vdc = Zwischenkreisspannung der Grenzen circle und hex und der PWM
field-pwm = Zweipunkt-Wechselrichter, symmetrische PWM mit der Abtastfrequenz (0/1; vlimit circle oder hex)

## Was jede Vorlage zeigt (preset-NAME: die Vorlage NAME)

# A preset's name in a description (sine200, load-step, rr-mismatch) is the link's: keep it as it is.

preset-sine200 = Abb. 2 des Artikels: Folgen von 0,5 sin(2π·200 t) rad/s mit dem EKF; der Strom erreicht Spitzen über dem Nennstrom des Motors
preset-step = Abb. 3 des Artikels: Sprung 0 → 0,5 rad/s bei 50 ms über ein kritisch gedämpftes Filter mit 200 Hz
preset-ramp = Abb. 4 des Artikels: Trapez auf 100 rad/s mit ±400 rad/s², Halten und zurück
preset-sine200-1rad = 1 rad/s bei 200 Hz: treibt die Spannung in die Sättigung an der 400-V-Grenze, und der Folgefehler ist mehr als dreimal so groß wie bei sine200
preset-sine200-rk4 = Abb. 2 mit einem RK4-Prädiktor im EKF statt des Euler-Prädiktors des Artikels
preset-rr-mismatch = 50 rad/s halten, mit einem Rotorwiderstand des Motors 10 % über dem des Modells: Die wahre Drehzahl erholt sich über Sekunden vom Anlauf und schwingt über dem Sollwert ein (6 s lang laufen lassen, um das Ende zu sehen)
preset-load-step = 50 rad/s halten; ein unbekannter Lastsprung von 2 N m bei 0,15 s, den das EKF mit 5 Zuständen nicht sehen kann
preset-decay = Idealer Beobachter, kein Rauschen, ω_d ≡ 0: Die Fehler klingen mit den entworfenen 1200/s ab und bleiben dann auf einem Restniveau stehen, das mit der Abtastzeit kleiner wird
preset-ifoc-step = Klassischer Vergleich: drehgeberlose IFOC mit MRAS, Sprung auf 40 rad/s (das MRAS ist nahe der Drehzahl null blind)
preset-load-step-est = load-step mit der Last a2 als EKF-Zustand (RK4-Prädiktor): Bei exaktem Modell hält sich die Drehzahl über den unbekannten Sprung hinweg, nicht aber, wenn R_r des Motors 3 % unter dem des Modells liegt
preset-rr-mismatch-est = rr-mismatch mit R_r als EKF-Zustand (RK4-Prädiktor): kein langsamer Übergangsvorgang, und R̂_r bleibt nahe am Wert des Motors
preset-sine200-drive = Übersteht 200 Hz einen realen Antrieb? sine200 mit einem Abtastschritt Rechentotzeit, dem Sechseck eines Wechselrichters mit 540 V und PWM
preset-high-gain = Verstärkungen 3000/s (2,5× so hoch wie im Artikel): Die Prädiktionsfehler des Euler-EKF treiben die Spannung über die Verstärkungen in die Sättigung an der 400-V-Grenze

## Die Kennwerte eines Laufs (`imlab metrics` nennt sie mit dem Teil nach figure-)

figure-transient_end = Ende des Anlaufvorgangs
figure-tracking_rms = RMS-Wert von ω − ω_d
figure-tracking_peak = Spitzenwert |ω − ω_d|
figure-settling_time = 2-%-Ausregelzeit von ω nach dem Sprung
figure-saturated_share = Anteil der Abtastwerte an der Spannungsgrenze
figure-mean_nis = mittlerer NIS
figure-mean_nis_low = mittlerer NIS, untere Grenze des 95-%-Bands eines konsistenten Filters
figure-mean_nis_high = mittlerer NIS, obere Grenze des 95-%-Bands eines konsistenten Filters
figure-current_peak = Spitzenwert des Statorstroms |i_s|
figure-current_rms = RMS-Wert des Statorstroms |i_s|
figure-current_rated = Nennstrom |i_s| (i_rated)
figure-ripple_peak = Spitzenwert der PWM-Stromwelligkeit
figure-ripple_rms = RMS-Wert der Spitzenwerte der PWM-Stromwelligkeit über die Perioden
figure-flux_error_final = Flussfehler am Ende |φ_r| − √ψ_d
figure-speed_error_final = Drehzahlfehler am Ende ω − ω_d
figure-speed_estimate_error_final = Schätzfehler der Drehzahl am Ende ω − ω̂
figure-law_residual = größtes Residuum der Entwurfsdynamik Ihrer Regelgesetze, über den Lauf und an den gezogenen Zuständen des Befunds, relativ zum Regelgesetz des Artikels
# Not among the run's figures: a challenge may name it.
figure-load_recovery_time = Erholzeit nach dem Lastsprung

## Der Teil des Laufs, den ein Kennwert abdeckt

# $time is a time (time-ms or time-s): where the start-up transient ends.
window-after-transient = t ≥ { $time }
window-start-up = Anlauf, t < { $time }
# $time is the time of the reference's step.
window-from-step = ab dem Sprung bei { $time }
window-rating = Nennstrom des Motors
# $time is the time of the run's last sample.
window-last-sample = letzter Abtastwert, t = { $time }
window-law-residual = der ganze Lauf und die gezogenen Zustände des Befunds

## Ein Kennwert, den der Lauf bis zu seinem Ende nicht erreicht hat, statt seines Werts

# $time is the time of the run's last sample.
unreached-not-settled = bis zum Ende des Laufs nicht eingeschwungen (t = { $time })

## Was man zu den Kennwerten eines Laufs wissen muss

# $speed is ω − ω_d at the run's end, $estimate ω̂ − ω, $flux the flux modulus and $target its
# target √ψ_d.
warning-runaway = Der Lauf ist divergiert: An seinem Ende liegt die wahre Drehzahl { $speed } rad/s vom Sollwert entfernt, der Drehzahlschätzwert { $estimate } rad/s von der wahren Drehzahl, und der Fluss beträgt { $flux } Wb bei einem Ziel von { $target } Wb. Der Regler regelt die Schätzwerte des EKF; Satz 4.6 beschränkt den geschlossenen Regelkreis nur, solange die Schätzfehler beschränkt bleiben, und wenn sie das nicht tun (ein Anlauffehler, den nur die Spannungsgrenze hält, ein falsches Modell bei kleiner Drehzahl), beschränkt nichts den Motor.
# $low and $high are the ends of the band.
warning-inconsistent-above = Das EKF ist in diesem Lauf inkonsistent: Sein mittlerer NIS beträgt { $nis }, weit über dem 95-%-Band { $low }–{ $high } eines Filters, dessen Modell passt. Seine Schätzwerte und die Drehzahl, mit der der Regler arbeitet, können weit von der Wahrheit entfernt sein, so schmal ihre Bänder auch aussehen.
warning-inconsistent-below = Das EKF ist in diesem Lauf inkonsistent: Sein mittlerer NIS beträgt { $nis }, weit unter dem 95-%-Band { $low }–{ $high } eines Filters, dessen Modell passt. Es nimmt mehr Rauschen an, als vorhanden ist, und folgt den Messungen daher langsamer, als es könnte.
# $figure is the figure's name (law_residual); $cause says why it is not a number.
warning-not-following = Die Drehzahl folgt ihrem Sollwert nicht: von t = { $since } bis zum Ende des Laufs bleibt ω − ω_d außerhalb von ±({ $share } % von |ω_d| + { $margin } rad/s) und endet bei { $error } rad/s mit ω_d = { $reference } rad/s.
warning-not-following-window = Die Drehzahl folgt ihrem Sollwert nicht: über das ganze Fenster der Kennwerte, von t = { $since } bis zum Ende des Laufs, bleibt ω − ω_d außerhalb von ±({ $share } % von |ω_d| + { $margin } rad/s) und endet bei { $error } rad/s mit ω_d = { $reference } rad/s.
warning-not-finite = { $figure } ist keine endliche Zahl: { $cause }.

## Wo der Anlaufvorgang endet, und warum dort

transient-nothing-recorded = noch nichts aufgezeichnet
# In place of a time: the criterion was never met in the first half of the run.
transient-never = nie in der ersten Hälfte (nicht verwendet)
# $k is the smallest of the gains k1..k4 (1/s); $time the controller's start-up.
transient-backstepping = 5 Zeitkonstanten der langsamsten entworfenen Fehlerrate (1/{ $k } s) = { $time }
# $bw is the IFOC current-loop bandwidth ifoc.bw_i (Hz); $time the controller's start-up.
transient-ifoc = 5 Zeitkonstanten der IFOC-Stromregelkreise (1/(2π·{ $bw } Hz)) = { $time }
# $controller is transient-backstepping or transient-ifoc; $observer, $estimates, $flux and $speed
# are times, or transient-never; $end is event when the transient was cut at the scenario's first
# event (the step or the load step), half when it was clamped to half the run, else none; $at is
# the time of that event or of half the run.
transient-reason = { $controller }, gezählt ab dem Anlauf des Beobachters. Innovationskovarianz des EKF eingeschwungen (2σ-Band innerhalb von 10 % seines Endwerts): { $observer }; Schätzwerte des EKF konvergiert (mittlerer NIS über 2 ms innerhalb des Doppelten seines Niveaus in der zweiten Hälfte, für 5 ms): { $estimates }; Flussschätzwert innerhalb des 1,5-Fachen seines späteren RMS-Fehlers (für 5 ms): { $flux }; Drehzahlschätzwert innerhalb des Doppelten seines späteren RMS-Fehlers (5-ms-Fenster, für 5 ms): { $speed }{ $end ->
        [event] ; abgeschnitten beim ersten Ereignis des Szenarios, bei { $at }
        [half] ; auf die Hälfte des aufgezeichneten Laufs begrenzt ({ $at })
       *[none] {""}
    }

## Warum ein Lauf anhielt

# $t is the sample's time (s); $signal the state that left its bounds (omega, i_sa, phi_a…);
# $value its value, in scientific notation (1.2e5, NaN).
sim-diverged = divergiert bei t = { $t } s: { $signal } = { $value } hat seine Grenzen verlassen
# $column is a column of the run's CSV; $value is inf, -inf or NaN.
sim-not-finite = angehalten bei t = { $t } s: Spalte '{ $column }' würde { $value } aufzeichnen, keine endliche Zahl
# $error is a control-* message.
sim-control = Regler versagte bei t = { $t } s: { $error }
# $formula is the student's law as typed; $value is inf, -inf or NaN; $reading is
# sim-law-reads-nothing or sim-law-reads.
sim-law = Ihr law.v{ $step } = { $formula } ergab { $value } bei t = { $t } s, { $reading }
sim-law-reads-nothing = ohne ein Signal zu lesen
# $signals lists the names the law reads with their values there (x1h = 52.3, z1 = 0.01).
sim-law-reads = mit { $signals }
# $flux and $min in scientific notation (Wb²).
control-singular = Entkopplungsmatrix (55) ist singulär: Der geschätzte Fluss x̂4² + x̂5² = { $flux } Wb² liegt unter { $min } Wb²
control-law = Das Regelgesetz von Schritt { $step } ergab { $value }, keine endliche Zahl
pin-room-full = es können höchstens { $max } Läufe angeheftet werden; lösen Sie zuerst einen
pin-legend-same = gleiches Szenario
overlay-ts-differs = der angeheftete Lauf { $scenario } tastet mit Ts = { $pinned } s ab, der aktuelle mit { $current } s: Überlagerungen brauchen dasselbe Ts
