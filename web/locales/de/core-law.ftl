# Die Meldungen des Kerns zum eigenen Regelgesetz eines Schritts: warum eine Formel zurückgewiesen
# wurde und der Befund über ein Regelgesetz gegenüber der Fehlerdynamik, die sein Schritt ergeben
# soll. Namen (x1h, k1s1, v1, z2), Funktionen (sqrt), Formeln (ż1 = −k1·z1 + z2, a3·ω_d),
# Einstellungen (law.v1), die Gleichungsnummern des Artikels ((28)) und zitierte Eingaben bleiben
# unverändert. Zitierte Eingaben behalten ihre Anführungszeichen.

## Eine zurückgewiesene Formel


## Ein zurückgewiesenes oder fehlendes eigenes Regelgesetz


## Der Befund über das eigene Regelgesetz eines Schritts

# $designed is the step's designed error dynamics (ż1 = −k1·z1 + z2); $output the virtual control
# the law gives (v1); $own is yes when the step is judged on the student's own law of the step
# before, $before (v1 or v3); $worst how far the law is from it, relative to its size (2e-16);
# $draws how many states were drawn; $caveats is one of the law-caveat-* messages.
law-designed = Ihr Schritt { $step } ergibt die Entwurfsdynamik { $designed }{ $own ->
        [yes] {" "}mit Ihrem eigenen { $before }: Ihr { $output } entspricht dem, das sie ergibt,
       *[no] : Ihr { $output } entspricht dem des Artikels
    } bis auf { $worst } seines Betrags an { $draws } zufällig gezogenen Zuständen und Parameterwerten.{ $caveats }
# As law-designed; $unit is the unit of $output; $difference is law-difference or
# law-difference-unnamed.
law-not-designed = Ihr Schritt { $step } ergibt nicht die Entwurfsdynamik { $designed }{ $own ->
        [yes] {" "}mit Ihrem eigenen { $before }: Ihr { $output } ({ $unit }) unterscheidet sich von dem, das sie ergibt,
       *[no] : Ihr { $output } ({ $unit }) unterscheidet sich von dem des Artikels
    } um bis zu { $worst } seines Betrags an { $draws } zufällig gezogenen Zuständen. { $difference }{ $caveats }
# $cause is one of the law-never-runs … law-not-finite messages.
law-not-designed-because = Ihr Schritt { $step } ergibt nicht die Entwurfsdynamik { $designed }: { $cause }.
law-cannot-judge = Ihr Schritt { $step } lässt sich nicht prüfen: { $cause }.
# $finding is one of the law-term-*, law-mistake-*, law-scenario-values-only and law-rate-of-z
# messages.
law-difference = Der Unterschied: { $finding }.
law-difference-unnamed = Der Unterschied ist kein einzelner Term des Regelgesetzes des Artikels: Vergleichen Sie Ihr Regelgesetz Term für Term mit der Herleitung des Schritts.

## Was ein Befund nach seinem Satz anfügt (jeder Zusatz beginnt mit dem Leerzeichen nach dem Satz)

law-caveat-none = {""}
# $names lists the names the student's law of the step before reads whose rates are not known.
law-caveat-unchained = {" "}Ihr { $before } liest { $names }; dafür kennt der Regelkreis keine Änderungsrate (sie enthält die Spannung, die ein späterer Schritt wählt, oder eine Ableitung, die dem Regelkreis fehlt). Dieser Schritt wird daher mit dem { $before } des Artikels geprüft.
law-caveat-failed = {" "}Ihr { $before } ergibt an { $failed } der { $draws } gezogenen Zustände keinen endlichen Wert; an diesen wird dieser Schritt nicht geprüft.
# Both caveats: $unread is law-caveat-unchained, $failing law-caveat-failed.
law-caveat-both = { $unread }{ $failing }

## Warum der Abstand eines Regelgesetzes von seiner Entwurfsdynamik keine Zahl ist


## Was ein falsches Regelgesetz falsch macht

# $term is a term of the paper's law with its sign (+a3·ω_d).
law-term = Der Term { $term }
# $part is a part of the term $term multiplied out.
law-term-part = Der Anteil { $part } des Terms { $term }
# $label is law-term or law-term-part.
law-term-missing = { $label } des Regelgesetzes des Artikels fehlt
law-term-wrong-sign = { $label } hat das falsche Vorzeichen
law-term-twice = { $label } kommt doppelt vor
# $factor is how many times the paper's term the law has.
law-term-scaled = { $label } ist das { $factor }-Fache dessen, was er sein sollte
law-scenario-values-only = Es stimmt nur bei den Parameterwerten und Verstärkungen dieses Szenarios mit dem Regelgesetz des Artikels überein: Ein Parameter oder eine Verstärkung ist als Zahl geschrieben, wo das Regelgesetz den Namen braucht
# The law is the paper's minus (or plus) $gain times the step's error $z (z1): $now is the rate its
# error then decays at, $meant the designed one.
law-rate-of-z = Es ist das Regelgesetz des Artikels { $sign ->
        [minus] minus
       *[plus] plus
    } { $gain }·{ $z }: Mit den Parametern dieses Szenarios klingt Ihr { $z } mit { $now } /s ab, nicht mit { $meant } /s; prüfen Sie die Verstärkung und das Vorzeichen Ihrer { $z }-Terme

## Typische Fehler Studierender, benannt, wenn ein Regelgesetz einem davon entspricht

law-mistake-k1 = Es enthält k1, wo (28) k1s1 = k1 − a3 enthält
law-mistake-a3-x1h = Es enthält a3·x̂1, wo (27) a3·ω_d enthält
law-mistake-k2 = Es enthält k2, wo (36) k2s1 = k2 − a7 − a8 enthält: Das −(a7 + a8)·z2 von ż2 bleibt dann stehen
law-mistake-printed-dv1 = Es übernimmt v̇1, wie es in (31) gedruckt ist, mit beiden Druckfehlern: a3·ω_d, wo die Ableitung von a3·ω_d a3·ω̇_d ist, und â2, wo die Ableitung von â2 seine Änderungsrate ist (0 bei bekannter Last)
law-mistake-printed-dv1-wd = Es übernimmt v̇1, wie es in (31) gedruckt ist, mit a3·ω_d, wo die Ableitung von a3·ω_d a3·ω̇_d ist
law-mistake-printed-dv1-a2 = Es übernimmt v̇1, wie es in (31) gedruckt ist, mit â2, wo die Ableitung von â2 seine Änderungsrate ist (0 bei bekannter Last)
law-mistake-robust-2 = Es schreibt den robusten Term −h2²/(4·ε2)·z2 aus (38) ohne den Schalter robust, sodass er auch wirkt, wenn die robusten Terme ausgeschaltet sind
law-mistake-psi-modulus = Es behandelt ψ_d als Betrag des Flusses (ψ_d²), wo das z3 = x̂4² + x̂5² − ψ_d des Artikels es als quadrierten Betrag behandelt
law-mistake-factor-2 = Es lässt den Faktor 2 in ganz ψ3 weg: Die Änderungsrate von x̂4² + x̂5² ist 2·(x̂4·x̂̇4 + x̂5·x̂̇5)
law-mistake-residual-rates = Es lässt die Kettenregelterme der Residuen 2·(l41·x̂4 + l51·x̂5)·ẋ̃2 und 2·(l42·x̂4 + l52·x̂5)·ẋ̃3 von ψ4 weg
law-mistake-drifts = Es enthält die Driftterme f̂4, f̂5 des Modells, wo ψ4 die Änderungsraten des Beobachters x̂̇4 = f̂4 + si4 und x̂̇5 = f̂5 + si5 enthält: Die Injektionen fehlen
law-mistake-drift-4 = Es enthält den Driftterm f̂4 des Modells, wo ψ4 die Änderungsrate des Beobachters x̂̇4 = f̂4 + si4 enthält: Die Injektion si4 fehlt
law-mistake-drift-5 = Es enthält den Driftterm f̂5 des Modells, wo ψ4 die Änderungsrate des Beobachters x̂̇5 = f̂5 + si5 enthält: Die Injektion si5 fehlt
law-mistake-factor-si4 = Der Faktor von x̂̇4 lässt si4 weg: Die Änderungsrate von 2·x̂4·si4 in ψ3 ergibt 2·si4·x̂̇4
law-mistake-factor-si5 = Der Faktor von x̂̇5 lässt si5 weg: Die Änderungsrate von 2·x̂5·si5 in ψ3 ergibt 2·si5·x̂̇5
law-mistake-robust-4 = Es schreibt den robusten Term −h4²/(4·ε4)·z4 aus (53) ohne den Schalter robust, sodass er auch wirkt, wenn die robusten Terme ausgeschaltet sind

## Die Namen, die ein Regelgesetz verwenden darf, und ihre Bedeutung (Name, Symbol und Einheit stehen daneben)

formula-name-x1h = geschätzte Rotordrehzahl ω̂ (A-posteriori-x̂1)
formula-name-x2h = geschätzter Statorstrom î_sa
formula-name-x3h = geschätzter Statorstrom î_sb
formula-name-x4h = geschätzter Rotorfluss φ̂_ra
formula-name-x5h = geschätzter Rotorfluss φ̂_rb
formula-name-x2 = gemessener Statorstrom i_sa
formula-name-x3 = gemessener Statorstrom i_sb
formula-name-xt2 = Residuum x̃2 = x2 − x̂2
formula-name-xt3 = Residuum x̃3 = x3 − x̂3
formula-name-dxt2 = nominelle Änderungsrate von x̃2: −(a7 + l21)·x̃2 − l22·x̃3
formula-name-dxt3 = nominelle Änderungsrate von x̃3: −l31·x̃2 − (a7 + l32)·x̃3
formula-name-dx4h = Änderungsrate von x̂4 im Beobachter: −a8·x̂4 − a9·x̂1·x̂5 + a10·x̂2 + si4
formula-name-dx5h = Änderungsrate von x̂5 im Beobachter: −a8·x̂5 + a9·x̂1·x̂4 + a10·x̂3 + si5
formula-name-wd = Drehzahlsollwert ω_d
formula-name-dwd = seine erste Ableitung
formula-name-ddwd = seine zweite Ableitung
formula-name-psi-d = Flussziel für x̂4² + x̂5²
formula-name-si1 = Injektion des Beobachters in x̂1: l11·x̃2 + l12·x̃3
formula-name-si2 = Injektion des Beobachters in x̂2
formula-name-si3 = Injektion des Beobachters in x̂3
formula-name-si4 = Injektion des Beobachters in x̂4
formula-name-si5 = Injektion des Beobachters in x̂5
formula-name-l11 = Beobachterverstärkung L = K/Ts, Zeile 1, Spalte 1
formula-name-l12 = Beobachterverstärkung, Zeile 1, Spalte 2
formula-name-l21 = Beobachterverstärkung, Zeile 2, Spalte 1
formula-name-l22 = Beobachterverstärkung, Zeile 2, Spalte 2
formula-name-l31 = Beobachterverstärkung, Zeile 3, Spalte 1
formula-name-l32 = Beobachterverstärkung, Zeile 3, Spalte 2
formula-name-l41 = Beobachterverstärkung, Zeile 4, Spalte 1
formula-name-l42 = Beobachterverstärkung, Zeile 4, Spalte 2
formula-name-l51 = Beobachterverstärkung, Zeile 5, Spalte 1
formula-name-l52 = Beobachterverstärkung, Zeile 5, Spalte 2
formula-name-a1 = μ = 3·np·M/(2·J·Lr): a1·(x3·x̂4 − x2·x̂5) ist das Drehmoment durch J
formula-name-a2 = T0/J (der Schätzwert â2, wenn das EKF die Last schätzt)
formula-name-a3 = Cf/J
formula-name-a5 = α·β mit α = Rr/Lr und β = M/(σ·Lr)
formula-name-a6 = np·β
formula-name-a7 = γ = Rs/σ + α·β·M
formula-name-a8 = α = Rr/Lr
formula-name-a9 = np
formula-name-a10 = α·M
formula-name-b = 1/σ
formula-name-da2 = Änderungsrate von â2 (seine Injektion), wenn das EKF die Last schätzt, sonst 0
formula-name-k1 = Abklingrate des Drehzahlfehlers
formula-name-k2 = Abklingrate des Drehmomentfehlers (k2 = a7 + a8 + k2s1)
formula-name-k3 = Abklingrate des Flussfehlers
formula-name-k4 = Abklingrate des Fehlers der Flussänderungsrate
formula-name-k1s1 = k1 − a3
formula-name-k2s1 = k2 − a7 − a8
formula-name-h2 = Schranke für |d̃2| aus (38)
formula-name-eps2 = ε2 aus (38)
formula-name-h4 = Schranke für |d̃4| aus (53)
formula-name-eps4 = ε4 aus (53)
formula-name-robust = 1, wenn die robusten Terme (38) und (53) eingeschaltet sind, sonst 0
formula-name-z1 = Drehzahlfehler x̂1 − ω_d
formula-name-z3 = Flussfehler x̂4² + x̂5² − ψ_d
formula-name-v1 = virtuelle Stellgröße von Schritt 1 (Ihre, wenn Sie sie geschrieben haben)
formula-name-z2 = Drehmomentfehler a1·(x3·x̂4 − x2·x̂5) − v1
formula-name-v3 = virtuelle Stellgröße von Schritt 3 (Ihre, wenn Sie sie geschrieben haben)
formula-name-z4 = Fehler der Flussänderungsrate 2·a10·(x2·x̂4 + x3·x̂5) − v3

## Die Funktionen, die ein Regelgesetz aufrufen darf: jede mit ihren Argumenten und was sie liefert
## (Name und Argumente der Funktion gehören zur Formelsprache: unverändert lassen)

formula-function-sqrt = sqrt(x): Quadratwurzel
formula-function-exp = exp(x): Exponentialfunktion
formula-function-ln = ln(x): natürlicher Logarithmus
formula-function-sin = sin(x): Sinus, x in rad
formula-function-cos = cos(x): Kosinus, x in rad
formula-function-tanh = tanh(x): Tangens hyperbolicus
formula-function-abs = abs(x): Betrag
formula-function-sign = sign(x): −1, 0 oder 1
formula-function-atan2 = atan2(y, x): der Winkel von (x, y) (rad)
formula-function-min = min(a, b): der kleinere Wert
formula-function-max = max(a, b): der größere Wert
formula-function-sat = sat(x, m): x begrenzt auf [−m, m]
