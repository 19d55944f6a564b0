# Der Entwurfsdurchgang (web/teaching/walkthrough*.js). Eine Zahl zu einem Lauf ist eine Variable,
# benannt nach ihrer Zeile der Messtabelle (web/teaching/measurements/walkthrough.csv).
# Eine geschweifte Klammer des Texts (wie in u_{"{"}k−1{"}"}) wird {"{"} und {"}"} geschrieben.

## Section model (walkthrough-text.js): 1. The motor model (2)

walkthrough-model-title = 1. Das Motormodell (2)
walkthrough-model-prose-1 = Der Zustand besteht aus der Rotordrehzahl ω = x1, den Statorströmen i_sa, i_sb = x2, x3 und den Komponenten des Rotorflusses φ_ra, φ_rb = x4, x5 im ständerfesten a–b-Koordinatensystem. Nur die Ströme werden gemessen; die Spannungen u1, u2 sind die Eingangsgrößen.
walkthrough-model-prose-2 = Das Drehmoment, bezogen auf das Trägheitsmoment, ist a1(x3·x4 − x2·x5) in rad/s²: Strom kreuz Fluss (a1 = 3n_pM/(2JL_r) enthält bereits 1/J; mit J multipliziert ergibt sich N m). Die Last a2 + a3·x1 ist das konstante T0 und die Reibung Cf·ω, jeweils geteilt durch J. Die folgenden zusammengefassten Parameter berechnet der Kern aus den verwendeten Motorparametern; Strecke (der simulierte Motor) und Modell (was EKF und Regler annehmen) können sich unterscheiden.
walkthrough-model-note = σ ist hier in Henry angegeben: Das σ = L_s − M²/L_r des Artikels ist die vom Stator aus gesehene Gesamtstreuinduktivität (die transiente Induktivität), nicht die Eigenstreuinduktivität L_s − M des Stators; viele Lehrbücher schreiben stattdessen die dimensionslose Streuziffer σ = 1 − M²/(L_sL_r).
walkthrough-model-plot-title = Drehzahl und Fluss

## Section ekf (walkthrough-text.js): 2. The extended Kalman filter (10)–(20)

walkthrough-ekf-title = 2. Das erweiterte Kalman-Filter (10)–(20)
walkthrough-ekf-prose-1 = Das EKF schätzt alle fünf Zustände aus den gemessenen Strömen und den angelegten Spannungen. Es prädiziert mit dem nach dem expliziten Euler-Verfahren diskretisierten Modell (10), linearisiert mit der Jacobi-Matrix (11) und korrigiert mit der Innovation: den gemessenen abzüglich der prädizierten Ströme.
walkthrough-ekf-prose-2 = Q (Prozessrauschen: q·Ts auf jedem Zustand, dazu q_speed·Ts allein auf der Drehzahl) gibt an, wie sehr dem Modell vertraut wird, R (Messrauschen, r_std²·I), wie sehr den Sensoren. Ein einziges q für Zustände unterschiedlicher Einheiten ist die Wahl des Artikels; q_speed lässt den Drehzahlschätzwert wandern, ohne den Rest zu lockern. Die Verstärkung K_k geht als Beobachterverstärkung L = K_k/Ts der allgemeinen Form (4) in den Regler ein: Die Schätzfehler x̃ sind das, was der Regler verkraften muss.
walkthrough-ekf-prose-3 = Ein konsistentes Filter hat seine Innovationen etwa 95 % der Zeit innerhalb ihres ±2σ-Bands und ein normiertes Innovationsquadrat (NIS) mit dem Mittelwert 2. Bereiche und Schranken in diesem Entwurfsdurchgang gelten über { $wt-ekf-euler-nis--draws } Rauschrealisierungen (Startwerte 1 bis { $wt-ekf-euler-nis--draws }). Der Euler-Prädiktor kann 200-Hz-Strömen nicht folgen: Bei sine200 beträgt sein mittlerer NIS bei jeder Realisierung mindestens { $wt-ekf-euler-nis }, der des RK4-Prädiktors höchstens { $wt-ekf-rk4-nis }; vergleichen Sie beide unten.
walkthrough-ekf-prose-4 = Abschnitt 3.1 des Artikels nennt eine Abhilfe, die er nicht ausführt: langsam veränderliche Größen als zusätzliche Zustände behandeln. Die Einstellung ekf.load fügt a2 = T_L0/J als Random Walk hinzu (der Regler verwendet dann â2 und dessen Änderungsrate, die Injektion l_a·(x̃2, x̃3)); ekf.rr fügt den Rotorwiderstand hinzu (a5, a7, a8, a10 des Reglers folgen R̂_r). Die letzten beiden Diagramme zeigen beide Schätzwerte mit ihren ±2σ-Bändern aus P gegenüber den wahren Werten. Ein zusätzlicher Zustand nimmt alles auf, was dem Modell fehlt, ob zu Recht oder zu Unrecht: Ein Zustand für den Rotorwiderstand hält unter einer unbekannten Last die Last für einen Widerstand (siehe die Lektionen).
walkthrough-ekf-note = Das gedruckte (13) prädiziert mit u_{"{"}k|k−1{"}"}; die Spannung, die über den letzten Abtastschritt gewirkt hat, ist u_{"{"}k−1{"}"}, die (10) verwendet und ebenso das Filter hier. Die Joseph-Form schreibt die Kovarianzaktualisierung (19) als Summe zweier symmetrischer Terme, die für jede Verstärkung K positiv semidefinit sind: Rundungsfehler können P viel schwerer eine der beiden Eigenschaften verlieren lassen als in der Kurzform (I − K_kC)P_{"{"}k|k−1{"}"}, auch wenn nichts das garantiert.
walkthrough-ekf-plot-title = Innovation ỹ_a mit ihrem ±2σ-Band aus S_k
walkthrough-ekf-plot4-title = Normiertes Innovationsquadrat mit seinem 95-%-Band (χ², 2 Freiheitsgrade)
walkthrough-ekf-plot2-title = Drehzahlschätzwert und seine Varianz
walkthrough-ekf-plot3-title = Flussbetrag: wahr und geschätzt
walkthrough-ekf-plot5-title = Lastmoment: Schätzwert â2·J mit seinem ±2σ-Band und wahrer Wert
walkthrough-ekf-plot6-title = Rotorwiderstand: Schätzwert mit seinem ±2σ-Band und der Wert des Motors

## Section bridge (walkthrough-text.js): 3. From the observer to the controller: (4) and (5)

walkthrough-bridge-title = 3. Vom Beobachter zum Regler: (4) und (5)
walkthrough-bridge-prose-1 = Der Regler sieht nie den Zustand des Motors, nur den Schätzwert x̂ des Beobachters und die gemessenen Ströme x2, x3. Der Schätzfehler sei x̃ = x − x̂. Zwei seiner Komponenten werden gemessen: die Stromresiduen x̃2 = x2 − x̂2 und x̃3 = x3 − x̂3. Drei nicht: der Drehzahlfehler x̃1 und die Flussfehler x̃4, x̃5.
walkthrough-bridge-prose-2 = Der Artikel entwirft den Regler für einen Beobachter der allgemeinen Form (4): das Modell (2), mit den Schätzwerten nachgebildet, plus eine Injektion si_i = l_i1·x̃2 + l_i2·x̃3 (5), eine Korrektur, die jeden Schätzwert über die gemessenen Residuen nachführt. Als Schritt des expliziten Euler-Verfahrens gelesen, hat die Aktualisierung des EKF diese Form mit L = K_k/Ts und dem A-priori-Residuum y_k − Cx̂_{"{"}k|k−1{"}"} (15), in den Zeilen 2 bis 5. Zeile 1 nur näherungsweise: Der Drehmomentterm des EKF verwendet die geschätzten Ströme x̂2, x̂3, wo (4) die gemessenen x2, x3 verwendet. Der Regler hier verwendet das A-posteriori-Residuum y_k − Cx̂_{"{"}k|k{"}"} = (I − CK_k)(y_k − Cx̂_{"{"}k|k−1{"}"}), das zu x̃ = x − x̂ für das A-posteriori-x̂_{"{"}k|k{"}"} passt, das er verwendet; beide stimmen nur überein, solange CK_k klein ist.
walkthrough-bridge-prose-3 = Subtrahiert man (4) von (2), ergibt sich die unten stehende Fehlerdynamik. Der Regler differenziert die gemessenen Residuen (sie stecken in v1 und in ψ3), und ihre Ableitungen enthalten die nicht gemessenen x̃1, x̃4, x̃5. Jede solche Ableitung wird zweigeteilt: in die nominelle Residuendynamik, also das, was ẋ̃2 und ẋ̃3 mit x̃1 = x̃4 = x̃5 = 0 wären und was der Regler berechnet, und in den Rest, den er nicht berechnen kann. Der Entwurf nimmt außerdem L als konstant an: L̇ wird im Folgenden überall vernachlässigt.
walkthrough-bridge-prose-4 = Das ist der integrierte Entwurf, nach dem der Artikel benannt ist: Die Fehlerdynamik des Beobachters ist Teil des Reglerentwurfs, und die unbekannten Terme treten nur dort auf, wo ein gemessener Strom oder ein Residuum differenziert wird, in Schritt 2 (ż2 enthält ẋ2, ẋ3 und v̇1) und in Schritt 4 (ż4 enthält die Änderungsraten der Injektionen si4, si5). Die Schritte 1 und 3 haben keine. In den beiden anderen werden sie als d̃2 und d̃4 zusammengefasst und als beschränkte Störungen behandelt. Bei exaktem Modell sind das alle; ein Modell, das vom Motor abweicht, fügt ż2 und ż4 eigene Terme hinzu, die d̃2 und d̃4 des Artikels nicht enthalten.
walkthrough-bridge-prose-5 = Die Integration ersetzt die Trennung der Zeitskalen, die die Zusammenfassung des Artikels nennt: einen Beobachter, der so viel schneller als der Regler ausgelegt ist, dass der Regler seinen Schätzwert wie den Zustand behandeln darf. Die folgenden Regelgesetze setzen x̂ weiterhin dort ein, wo eine Zustandsrückführung x einsetzen würde, nach dem Prinzip der Gewissheitsäquivalenz (Certainty Equivalence); was der Entwurf hinzufügt, ist, dass die Schätzfehler in sein Lyapunov-Argument eingehen, als d̃2 und d̃4, die unter Annahme 4.2 beschränkt sind, statt dass man sie einfach als null annimmt.
walkthrough-bridge-figure = Regler und Beobachter wie in Abb. 1 des Artikels: Der Regler sieht den Motor nur über Schätzwert, Verstärkung und Residuen des EKF sowie die gemessenen Ströme.
    .alt = Blockschaltbild: Der Sollwert sowie Schätzwert, Verstärkung und Residuen des EKF gehen in den Backstepping-Regler; seine Spannung durchläuft die Spannungsgrenze und speist den Motor; die gemessenen Ströme und die angelegte Spannung gehen zurück in das EKF.
walkthrough-bridge-note = Der Artikel schreibt si_i(x̃2, x̃3) für die Injektion; hier ist si_i ihr Wert l_i1·x̃2 + l_i2·x̃3. Der Buchstabe ψ bezeichnet sowohl das Flussziel ψ_d als auch die bekannten Terme ψ2, ψ3, ψ4 der folgenden Schritte: Beides hat nichts miteinander zu tun.

## Section step1 (walkthrough-text.js, walkthrough-laws.js): 4. Step 1: the speed loop

walkthrough-step1-title = 4. Schritt 1: der Drehzahlregelkreis
walkthrough-step1-prose-1 = Schritt 1 regelt die geschätzte Drehzahl: z1 = x̂1 − ω_d. Ihre Ableitung nach der ersten Zeile von (4) ist der offene Kreis (23). Man zerlegt den Reibungsterm um den Sollwert, −a3·x̂1 = −a3·z1 − a3·ω_d: Die Eigendämpfung −a3·z1 des Motors bleibt, und −a3·ω_d ist ein bekannter Term.
walkthrough-step1-prose-2 = Eine virtuelle Stellgröße ist ein Signal, das ein Schritt als seine Eingangsgröße behandelt, obwohl der Motor keinen solchen Eingang hat. Die von Schritt 1 ist der Drehmomentterm a1(x3·x̂4 − x2·x̂5), gebildet aus gemessenen Strömen und geschätzten Flüssen: Man fordert, dass er gleich v1 ist (ein Drehmoment bezogen auf das Trägheitsmoment, in rad/s²), und nennt die Abweichung z2 (24). Dann gilt (25).
walkthrough-step1-prose-3 = Man wählt v1 = v1a + v1s (26). Die Vorsteuerung v1a (27) kompensiert jeden bekannten Term; si1 ist bekannt, da es nur die gemessenen Residuen verwendet. Die Rückführung v1s = −k1s1·z1 (28) ergibt (29), ż1 = −k1·z1 + z2 mit k1 = a3 + k1s1: k1s1 ist der Teil der Rate k1, den der Regler zur Eigendämpfung a3 des Motors hinzufügt; daher enthält v1a den Term a3·ω_d und nicht a3·x̂1. Die Schritte 1 und 2 behalten die Eigendämpfung des Motors; die Schritte 3 und 4 kompensieren alles, was sie kennen.
walkthrough-step1-prose-4 = Die Lyapunov-Funktion von Schritt 1 ist V1 = ½z1². Entlang (29) gilt V̇1 = z1ż1 = −k1z1² + z1z2: negativ bis auf den Kreuzterm z1z2, den Schritt 2 kompensiert.
walkthrough-step1-prose-5 = Schritt 2 benötigt v̇1. Man differenziert (30) bei konstantem L (L̇ vernachlässigt): Die Änderungsrate der Injektion ist l11·ẋ̃2 + l12·ẋ̃3, und ẋ̃2, ẋ̃3 enthalten die nicht gemessenen x̃1, x̃4, x̃5 (Abschnitt 3). Der bekannte Teil von v̇1 setzt an ihre Stelle die nominelle Residuendynamik; der Rest, das „…“ unten, geht in d̃2 ein.
walkthrough-step1-note = Das gedruckte (31) hat a3·ω_d und â2, wo a3·ω̇_d und dâ2/dt hingehören (oben korrigiert). Das „…“ steht für die Terme in x̃1, x̃4, x̃5: −(l11·a5 − l12·a6·x̂1)·x̃4 − (l12·a5 + l11·a6·x̂1)·x̃5 − (l11·a6·x5 − l12·a6·x4)·x̃1.
walkthrough-step1-plot-title = Schritt 1: z1, v1 = v1a + v1s und der Drehmomentterm
walkthrough-step1-plot3-title = Schritt 1: ż1, wie es sich im Lauf ergab (seine Änderung über jeden Abtastschritt, geteilt durch Ts), gegenüber dem entworfenen −k1·z1 + z2
walkthrough-law-1-intro = Leiten Sie v1 selbst her und schreiben Sie es unten als Formel in den Namen dieses Abschnitts (x1h für x̂1, wd und dwd für ω_d und ω̇_d, si1, a2, a3, k1s1, z1; die vollständige Liste steht unten), mit + − * / ^, Klammern und Funktionen. Es läuft mit 20 kHz anstelle von (26) des Artikels, sobald Sie die Eingabetaste drücken oder mit dem Tippen innehalten; ein leeres Feld stellt das Regelgesetz des Artikels wieder her. Nach dem Lauf prüft der Befund Ihr Regelgesetz an zufällig gezogenen Zuständen und Parameterwerten gegen die Entwurfsdynamik ż1 = −k1·z1 + z2, und das Diagramm unten zeigt sein Residuum über den Lauf: null für ein Regelgesetz, das sie ergibt.
walkthrough-law-1-plot-title = Schritt 1: Residuum Ihres Regelgesetzes, ż1 gegenüber dem entworfenen ż1 = −k1·z1 + z2 (Ihr v1 abzüglich dessen des Artikels)

## Section step2 (walkthrough-text.js, walkthrough-laws.js): 5. Step 2: the torque loop

walkthrough-step2-title = 5. Schritt 2: der Drehmomentregelkreis
walkthrough-step2-prose-1 = Schritt 2 lässt den Drehmomentterm v1 folgen, indem er z2 gegen null treibt, und hier treten die Spannungen zum ersten Mal auf. Man differenziert (24): ẋ2 und ẋ3 bringen bu1 und bu2 ein, daher ist v2 = b·a1(x̂4·u2 − x̂5·u1) die Eingangsgröße; x̂̇4, x̂̇5 sind die aus (4); und −v̇1 ist (31). Was der Regler kennt, fasst man in ψ2 zusammen, und schreibt man den Drehmomentterm als z2 + v1, so folgt (32).
walkthrough-step2-prose-2 = ψ2 sammelt alles Bekannte: die Fluss- und die Stromdynamik, die Injektionen si4, si5 und den bekannten Teil von v̇1. Die nicht gemessenen Fehler x̃1, x̃4, x̃5 gehen nur über d̃2 (33) ein (bei exaktem Modell; ein Modell, das vom Motor abweicht, fügt ż2 eigene Terme hinzu): linear, mit Koeffizienten aus x̂, x und L, also beschränkt, solange x̂, x, L und x̃ es sind. Der Artikel hält x̂ mit einer Projektion (7)–(9) beschränkt; das beschränkt x̂, nicht x̃, und solange die Projektion eingreift, ist x̂̇ nicht mehr (4), und ψ2–ψ4 sind nicht mehr exakt. Das EKF hier hat keine Projektion: Nichts als der Lauf selbst beschränkt x̂.
walkthrough-step2-prose-3 = Man wählt v2 = v2a + v2s (34): v2a = −ψ2 − z1 kompensiert die bekannten Terme und den Kreuzterm z1z2 von V̇1; v2s = −k2s1·z2 + v2s2 (36) fügt die Rückführung hinzu, mit k2 = a7 + a8 + k2s1, da der Motor die Dämpfung a7 + a8 selbst liefert. Für den Motor des Artikels ist a7 + a8 = 232,7 /s, also k2s1 = 967,3 /s bei k2 = 1200 /s.
walkthrough-step2-prose-4 = Der robuste Term v2s2 = −h2²z2/(4ε2) (38) dominiert d̃2, wenn h2 eine Schranke für |d̃2| ist. Mit V_s2 = ½(z1² + z2²) (39) gilt V̇_s2 = −k1z1² − k2z2² + z2(v2s2 + d̃2) ≤ −k1z1² − k2z2² + ε2 (40). Kein endliches h2 leistet das für ein d̃2, das unbeschränkt wächst: Sobald |d̃2| größer als h2 wird, kann z2(v2s2 + d̃2) größer als ε2 werden.
walkthrough-step2-prose-5 = Welche Terme in d̃2 gehen, ist eine Wahl: (33) schreibt die wahre Drehzahl als x1 = x̂1 + x̃1 und behält den Anteil x̂1 in ψ2; eine andere Aufteilung würde Terme zwischen ψ2 und d̃2 verschieben und ż2 unverändert lassen. Hier stützt sich der Artikel auf Annahme 4.2 (22): Sie nimmt an, dass x̃ in einem bekannten Quader [x̃_min, x̃_max] liegt, stellt fest, dass d̃2 dann beschränkt ist, und setzt h2 auf diese Schranke (38), wie Schritt 4 h4 setzt (53). Werte für den Quader oder die Schranken gibt sie nicht an. Hier sind h2 und h4 Einstellungen; das d̃2-Diagramm unten und das d̃4-Diagramm von Schritt 4 messen die Terme im gezeigten Lauf, eine Möglichkeit, sie für diesen Lauf zu bemessen. ε2 wägt dann den Endwert ε/λ von (59) gegen die Rate h2²/(4ε2) ab, die v2s2 zu der von z2 hinzufügt, und ein mit Ts abgetasteter Regelkreis verkraftet eine Rate nur deutlich unter etwa 2/Ts; die Lektion „Die robusten Terme und die Schranke (59)“ rechnet eine Wahl durch.
walkthrough-step2-prose-6 = Das Differenzieren von z2 liefert außerdem −(a7 + a8)·z2, die Eigendämpfung des Motors; das gedruckte (32) lässt sie weg, und das k2 = a7 + a8 + k2s1 von (36) berücksichtigt sie.
walkthrough-step2-note = Das gedruckte (35) lautet v2a = −ψ2 − d̃2 − z1: d̃2 ist unbekannt, also kann kein Regler es subtrahieren; der Regler hier verwendet −ψ2 − z1 und überlässt d̃2 dem robusten Term.
walkthrough-step2-shows-1 = Das Diagramm unten wertet d̃2 aus der simulierten Wahrheit aus: das tatsächliche ż2 des Motors abzüglich der Terme, die der Regler kennt, mit den wahren Strömen anstelle der gemessenen. Es wird für das EKF mit fünf Zuständen ohne Totzeitkompensation ausgewertet; für einen Beobachter mit zusätzlichen Zuständen (ekf.load, ekf.rr) oder mit delay.comp bleibt das Diagramm leer. h2 muss mindestens der Spitzenwert von |d̃2| sein, damit (38) es dominiert: Lesen Sie ihn bei step mit exaktem Modell ab, dann mit einem Modellfehler (plant.j, plant.rr). Liegt R_r des Motors 10 % über dem des Modells (plant.rr = 5.445), so divergiert der Regelkreis oder versagt bei { $wt-rrhigh-runaway } von { $wt-rrhigh-runaway--draws } Realisierungen: Der Fluss läuft bei { $wt-rrhigh-off } davon, und der Regler versagt bei { $wt-rrhigh-fail } vor dem Ende. Der Fluss beträgt am Ende der 0,1 s der Vorlage { $wt-rrhigh-flux-min } bis { $wt-rrhigh-flux-max } Wb und nach 1 s { $wt-rrhigh1s-flux-min } bis { $wt-rrhigh1s-flux-max } Wb, und die Koeffizienten von d̃2 in (33) wachsen mit x.
walkthrough-step2-plot-title = Schritt 2: z2 und v2 = v2a + v2s
walkthrough-step2-plot2-title = Schritt 2: d̃2, aus der simulierten Wahrheit ausgewertet, gegenüber ±h2
walkthrough-step2-plot3-title = Schritt 2: ż2, wie es sich im Lauf ergab (seine Änderung über jeden Abtastschritt, geteilt durch Ts), gegenüber dem entworfenen −k2·z2 − z1 (mit seinem robusten Term bei robust=1)
walkthrough-law-2-intro = Leiten Sie v2 selbst her und schreiben Sie es unten als Formel in den Namen dieses Abschnitts (v1 und z2 (aus Schritt 1), x2 und x3, x4h und x5h, si4 und si5, dxt2 und dxt3, l11 und l12, ddwd, a1 bis a10, k1, k1s1, k2s1; die vollständige Liste steht unten), mit + − * / ^, Klammern und Funktionen. Es läuft mit 20 kHz anstelle von (34) des Artikels, sobald Sie die Eingabetaste drücken oder mit dem Tippen innehalten; ein leeres Feld stellt das Regelgesetz des Artikels wieder her. Mit Ihrem eigenen v1 unter Schritt 1 wird Ihr v2 daran gemessen: Es muss Ihr v1 differenzieren, mit dem ż1, das Ihr v1 ergibt. Nach dem Lauf prüft der Befund Ihr Regelgesetz an zufällig gezogenen Zuständen und Parameterwerten gegen die Entwurfsdynamik ż2 = −k2·z2 − z1, und das Diagramm unten zeigt sein Residuum über den Lauf: null für ein Regelgesetz, das sie ergibt.
walkthrough-law-2-plot-title = Schritt 2: Residuum Ihres Regelgesetzes, ż2 gegenüber dem entworfenen ż2 = −k2·z2 − z1 (Ihr v2 abzüglich des v2, das es ergibt: dessen des Artikels oder, nach Ihrem eigenen v1, desjenigen, das Ihres differenziert)

## Section step3 (walkthrough-text.js, walkthrough-laws.js): 6. Step 3: the flux outer loop

walkthrough-step3-title = 6. Schritt 3: der äußere Flussregelkreis
walkthrough-step3-prose-1 = Schritt 3 regelt das Quadrat des geschätzten Flussbetrags: z3 = x̂4² + x̂5² − ψ_d (42). Seine Ableitung benötigt nur (4): ż3 = 2x̂4·x̂̇4 + 2x̂5·x̂̇5 − ψ̇_d, worin sich die a9-Terme aufheben, unten allein in den Schätzwerten geschrieben. Schreibt man x̂2 = x2 − x̃2 und x̂3 = x3 − x̃3, so trennt sich die virtuelle Stellgröße 2a10(x2·x̂4 + x3·x̂5), der Teil von ż3, den die Statorströme treiben, von ψ3 (43).
walkthrough-step3-prose-2 = ψ3 hängt nur von Schätzwerten und gemessenen Residuen ab, daher hat Schritt 3 überhaupt keinen unbekannten Term: Mit v3 = −ψ3 − k3·z3 (45) gilt ż3 = −k3·z3 + z4 (46) zeitkontinuierlich exakt, für den eigenen Flussschätzwert des Beobachters. Seine Lyapunov-Funktion ist V3 = ½z3² mit V̇3 = −k3z3² + z3z4; Schritt 4 kompensiert den Kreuzterm.
walkthrough-step3-prose-3 = Da v3 = −ψ3 − k3·z3 ist, lautet der nächste Fehler z4 (44) z4 = ż3 + k3·z3: das, was z3 daran fehlt, mit der Rate k3 abzuklingen.
walkthrough-step3-prose-4 = Der Artikel schreibt die Rückführung als v3s = −k3s1·z3 und setzt k3 = k3s1 (46): v3a kompensiert ψ3 vollständig, einschließlich des Eigenabklingens −2a8·(x̂4² + x̂5²) des Flusses, sodass die ganze Rate k3 vom Regler stammt, während in Schritt 1 die Dämpfung a3 des Motors Teil von k1 ist.
walkthrough-step3-note = Die Problemstellung verlangt, dass x4² + x5² dem Wert ψ_d² folgt, doch (42) subtrahiert ψ_d: ψ_d ist hier das Ziel für das Quadrat des Betrags, in Wb². Das psi_d des Szenarios ist dieses Ziel: psi_d = 0.5 Wb² fordert einen Flussbetrag |φ| = 0,707 Wb. Die Simulationen des Artikels geben „ϕ_d = 0,5“ als gewünschten Flussbetrag an, was wörtlich genommen 0,5 Wb (0,25 Wb²) bedeutet; die Vorlagen fassen es wie (42) als Quadrat des Betrags auf, als Quadrat des Anfangsflusses [0,5; 0,5] des Artikels.
walkthrough-step3-shows-1 = Das z3-Diagramm zeigt den Fehler des eigenen Flussschätzwerts des Beobachters gegenüber dem Ziel, nicht den des Motors. Bei step mit exaktem Modell beträgt sein RMS-Wert ab 15 ms { $wt-z3-min } bis { $wt-z3-max } mWb² mit dem EKF und { $wt-z3-quiet } mWb² ohne Messrauschen (noise=0): Das Rauschen gelangt über die Innovationen in z3. Mit dem idealen Beobachter (perfect=1), dessen Schätzwert der Fluss des Motors ist, bleibt er unter { $wt-z3-perfect-max } mWb².
walkthrough-step3-plot-title = Schritt 3: z3 und v3 = v3a + v3s
walkthrough-step3-plot3-title = Schritt 3: ż3, wie es sich im Lauf ergab (seine Änderung über jeden Abtastschritt, geteilt durch Ts), gegenüber dem entworfenen −k3·z3 + z4
walkthrough-law-3-intro = Leiten Sie v3 selbst her und schreiben Sie es unten als Formel in den Namen dieses Abschnitts (x4h und x5h, xt2 und xt3, si4 und si5, a8, a10, k3, z3; die vollständige Liste steht unten), mit + − * / ^, Klammern und Funktionen. Es läuft mit 20 kHz anstelle von (45) des Artikels, sobald Sie die Eingabetaste drücken oder mit dem Tippen innehalten; ein leeres Feld stellt das Regelgesetz des Artikels wieder her. Nach dem Lauf prüft der Befund Ihr Regelgesetz an zufällig gezogenen Zuständen und Parameterwerten gegen die Entwurfsdynamik ż3 = −k3·z3 + z4, und das Diagramm unten zeigt sein Residuum über den Lauf: null für ein Regelgesetz, das sie ergibt.
walkthrough-law-3-plot-title = Schritt 3: Residuum Ihres Regelgesetzes, ż3 gegenüber dem entworfenen ż3 = −k3·z3 + z4 (Ihr v3 abzüglich dessen des Artikels)

## Section step4 (walkthrough-text.js, walkthrough-laws.js): 7. Step 4: the flux inner loop and the voltages

walkthrough-step4-title = 7. Schritt 4: der innere Flussregelkreis und die Spannungen
walkthrough-step4-prose-1 = Schritt 4 treibt z4 gegen null; seine Eingangsgröße v4 = 2a10·b(x̂4·u1 + x̂5·u2) ist die zweite Kombination der Spannungen. Da z4 = ż3 + k3·z3 ist, gilt ż4 = z̈3 + k3·ż3 = z̈3 + k3(−k3z3 + z4). Man differenziert ż3 noch einmal, und zwar in seiner Form allein in den Schätzwerten (der ersten Zeile von Schritt 3), nicht in der Form (43), deren gemessene Ströme unbekannte Terme einbrächten, die sich aufheben: Die Terme in x̂̇4, x̂̇5 sammeln sich wie unten, x̂̇2 und x̂̇3 bringen die Spannungen (v4) und die Stromdynamik ein, und die Änderungsraten der Injektionen l41·ẋ̃2 + l42·ẋ̃3 und l51·ẋ̃2 + l52·ẋ̃3 bringen die Ableitungen der Residuen ein.
walkthrough-step4-prose-2 = In der Ableitung von 2a10·(x2·x̂4 + x3·x̂5) heben sich die a6-Terme von ẋ2 und ẋ3 (2) in ihrem bekannten Teil auf, a6·x̂1·(x̂4·x̂5 − x̂5·x̂4) = 0, weshalb ψ4 kein a6 enthält; der Rest, der x̃1, x̃4, x̃5 enthält, geht in d̃4. Mit V_s4 = ½z3² + ½z4² (56) gilt V̇_s4 = −k3z3² − k4z4² + z4(v4s2 + d̃4) ≤ −λ4·V_s4 + ε4 mit λ4 = 2·min(k3, k4), was sich zu (57) integrieren lässt, wie es Abschnitt 8 für V tut.
walkthrough-step4-prose-3 = ψ4 verwendet für ẋ̃2 und ẋ̃3 die nominelle Residuendynamik (Abschnitt 3), mit vernachlässigtem L̇: Das gedruckte (47) gilt mit L̇ = 0. Was die nominelle Dynamik auslässt, die Terme in x̃1, x̃4, x̃5 von ẋ̃2 und ẋ̃3, gewichtet mit 2(l41·x̂4 + l51·x̂5) und 2(l42·x̂4 + l52·x̂5), ist d̃4.
walkthrough-step4-prose-4 = Man wählt v4 = −ψ4 − z3 − k4·z4 + v4s2 (49)–(51): Das −z3 kompensiert den Kreuzterm z3z4 von V̇3, und es folgt (52). v2 und v4 legen zusammen beide Spannungen über die Entkopplungsmatrix (54) fest, die invertierbar ist, solange der geschätzte Fluss nicht null ist (55). Dann greift die Spannungsgrenze: Der Artikel gibt nur eine Grenze von 400 V an; das Rechteck (vlimit=box) begrenzt jede Komponente auf ±400 V, während der Kreis und das Sechseck des Wechselrichters (vlimit) den ganzen Vektor herunterskalieren und seine Richtung beibehalten. Solange sie greift, gilt die entworfene Fehlerdynamik nicht mehr.
walkthrough-step4-note = Das gedruckte (48) hat a21, a22, wo a41, a42 hingehören (oben korrigiert). ψ4 oben ist das umgruppierte gedruckte (47): Der Artikel schreibt 2a10(l21·x̃2·x̂4 + …) für 2a10(x̂4·si2 + x̂5·si3) und zerlegt jedes Produkt mit x̂̇4, x̂̇5 in zwei. Sein d̃4 ist dasselbe wie das gedruckte, Term für Term.
walkthrough-step4-shows-1 = |d̃4|, wie d̃2 aus der simulierten Wahrheit ausgewertet, ist unten gegenüber ±h4 aufgetragen; h4 muss mindestens sein Spitzenwert sein, damit (53) es dominiert.
walkthrough-step4-shows-2 = In seinen ersten 5 ms fordert der Anlaufvorgang Spannungen weit jenseits der Grenze: Das vorgegebene u_sa erreicht Spitzen von { $wt-cmd-step-min } bis { $wt-cmd-step-max } V bei step und { $wt-cmd-rr-min } bis { $wt-cmd-rr-max } V bei rr-mismatch, und bei rr-mismatch begrenzt die Grenze die Vorgabe bis zu einem Zeitpunkt zwischen { $wt-clip-rr-min } und { $wt-clip-rr-max } ms. Die Diagramme passen ihre y-Achsen an den Lauf nach diesem Vorgang an; entfernen Sie das Häkchen bei „y-Achsen nach dem Anlaufvorgang anpassen“ über den Diagrammen, um ihn zu sehen.
walkthrough-step4-plot-title = Schritt 4: z4, v4 und die Spannung vor und nach der Begrenzung
walkthrough-step4-plot2-title = Schritt 4: d̃4, aus der simulierten Wahrheit ausgewertet, gegenüber ±h4
walkthrough-step4-plot3-title = Schritt 4: ż4, wie es sich im Lauf ergab (seine Änderung über jeden Abtastschritt, geteilt durch Ts), gegenüber dem entworfenen −k4·z4 − z3 (mit seinem robusten Term bei robust=1)
walkthrough-law-4-intro = Leiten Sie v4 selbst her und schreiben Sie es unten als Formel in den Namen dieses Abschnitts (v3 und z4 (aus Schritt 3), dx4h und dx5h, dxt2 und dxt3, si2 bis si5, l41 bis l52, a5, a7, a8, a10, k3, k4, z3; die vollständige Liste steht unten), mit + − * / ^, Klammern und Funktionen. Es läuft mit 20 kHz anstelle von (49) des Artikels, sobald Sie die Eingabetaste drücken oder mit dem Tippen innehalten; ein leeres Feld stellt das Regelgesetz des Artikels wieder her. Mit Ihrem eigenen v3 unter Schritt 3 wird Ihr v4 daran gemessen: Es muss Ihr v3 differenzieren, mit dem ż3, das Ihr v3 ergibt. Nach dem Lauf prüft der Befund Ihr Regelgesetz an zufällig gezogenen Zuständen und Parameterwerten gegen die Entwurfsdynamik ż4 = −k4·z4 − z3, und das Diagramm unten zeigt sein Residuum über den Lauf: null für ein Regelgesetz, das sie ergibt.
walkthrough-law-4-plot-title = Schritt 4: Residuum Ihres Regelgesetzes, ż4 gegenüber dem entworfenen ż4 = −k4·z4 − z3 (Ihr v4 abzüglich des v4, das es ergibt: dessen des Artikels oder, nach Ihrem eigenen v3, desjenigen, das Ihres differenziert)

## Section stability (walkthrough-text.js): 8. Stability: Theorem 4.6

walkthrough-stability-title = 8. Stabilität: Satz 4.6
walkthrough-stability-prose-1 = Mit V = ½(z1² + z2² + z3² + z4²) (58) ergeben die vier entworfenen Fehlerdynamiken V̇ = −k1z1² − k2z2² − k3z3² − k4z4² + z2(v2s2 + d̃2) + z4(v4s2 + d̃4) (60). Die Kreuzterme ±z1z2 und ±z3z4 heben sich auf: Dafür sind das −z1 in v2a und das −z3 in v4a da.
walkthrough-stability-prose-2 = Drei Zeilen schließen den Beweis ab. Erstens: Ist |d̃2| ≤ h2 (h2 = δ_d2 aus (38), eine Schranke für d̃2, deren Existenz der Artikel unter den Schranken von Annahme 4.2 für x̃ (22) behauptet, aber nicht herleitet: d̃2 ist linear in x̃1, x̃4, x̃5 mit Koeffizienten, die die wahren x1, x4, x5, die Schätzwerte und die Verstärkungen l11, l12 enthalten, sodass Schranken für x̃ es nur beschränken, solange diese beschränkt bleiben), so beschränkt die Youngsche Ungleichung das robuste Paar: z2(v2s2 + d̃2) ≤ h2|z2| − h2²z2²/(4ε2) ≤ ε2, da die Differenz ein vollständiges Quadrat ist. Dasselbe gilt für z4 mit h4 und ε4. Zweitens: Σk_i·z_i² ≥ min(k_i)·Σz_i² = 2·min(k_i)·V = λV. Also gilt V̇ ≤ −λV + ε mit ε = ε2 + ε4. Drittens der Vergleichsschritt: e^(λt)·V hat die Änderungsrate e^(λt)·(V̇ + λV) ≤ ε·e^(λt); Integration von 0 bis t ergibt (59).
walkthrough-stability-prose-3 = V addiert Quadrate unterschiedlicher Einheiten (z1 in rad/s, z2 in rad/s², z3 in Wb², z4 in Wb²/s), und auch ε2 (rad²/s⁵) und ε4 (Wb⁴/s³) unterscheiden sich: (59) gilt für die SI-Zahlenwerte. Auf jede beliebige Gewichtung überträgt es sich nicht ohne Weiteres: Mit V = ½Σw_i·z_i² werden die Kreuzterme von V̇ zu (w1 − w2)·z1z2 und (w3 − w4)·z3z4, die sich nur für w1 = w2 und w3 = w4 aufheben (ungleiche Gewichte hinterlassen einen Kreuzterm, der λ senkt), es sei denn, die Kopplungen −z1 aus (35) und −z3 aus (50) werden zu −(w1/w2)·z1 und −(w3/w4)·z3 umskaliert. Diese Kopplungen tragen eine Einheit (1/s² in SI), die die bloße Summe verbirgt. Die Schranke gilt für die Summe, für jedes einzelne ½z_i² nur über die Summe. Das Diagramm vergleicht das aufgezeichnete V mit dieser Schranke für diesen Lauf.
walkthrough-stability-prose-4 = Der Satz beschränkt die Fehler z_i der Schätzwerte, nicht den Motor: Der wahre Drehzahlfehler ist |x1 − ω_d| ≤ |z1| + |x̃1|. Er setzt |d̃2| ≤ h2 und |d̃4| ≤ h4 über den ganzen Lauf voraus; diese Schranken selbst setzen beschränkte x, x̂ und L voraus, was gerade die Folgerung des Satzes ist, und die vernachlässigten L̇-Terme stehen weder in ψ noch in d̃. Über den wahren Motor sagt er nichts, wenn die Annahme verletzt ist.
walkthrough-stability-shows-1 = Mit dem Anfangsfehler von 10 % im EKF und exaktem Modell hält die Spannungsgrenze den Anlauf im Zaum: sine200 divergiert mit ihr bei { $wt-limit-runaway } von { $wt-limit-runaway--draws } Realisierungen (liegt R_r des Motors 10 % über dem des Modells, selbst mit ihr bei { $wt-limit-rrhigh-runaway }), ohne sie (vmax=100000) dagegen bei { $wt-nolimit-runaway }, wobei die Drehzahl um bis zu { $wt-nolimit-off-max } rad/s abweicht und der Fluss bis zu { $wt-nolimit-flux-max } Wb erreicht. Aus einem korrekten Anfangsschätzwert (init_err=0) folgt derselbe Lauf ohne Grenze bei exaktem Modell bei jeder Realisierung mit { $wt-exact-rms-min } bis { $wt-exact-rms-max } rad/s RMS; liegt R_r des Motors 10 % über dem des Modells, versagt er selbst dann: Sein RMS-Fehler beträgt mindestens { $wt-exact-rrhigh-rms } rad/s, und er divergiert bei { $wt-exact-rrhigh-runaway } von { $wt-exact-rrhigh-runaway--draws } Realisierungen.
walkthrough-stability-plot-title = Lyapunov-Funktion V(t) = ½Σz_i² gegenüber der Schranke (59), logarithmische Skala

## The plots' signals, in their legends (walkthrough-text.js, walkthrough-laws.js)

walkthrough-series-estimated = { $signal } geschätzt
walkthrough-series-true = { $signal } wahr
walkthrough-series-right = { $signal } (rechts)
walkthrough-series-right-unit = { $signal } ({ $unit }, rechts)
walkthrough-series-feedforward = Vorsteuerung { $term }
walkthrough-series-feedback = Rückführung { $term }
walkthrough-series-run = { $signal } aus dem Lauf
walkthrough-series-designed = { $expression } (Entwurf)
walkthrough-series-load-true = T_L wahr (T0 + Sprung)
walkthrough-series-rr-motor = R_r des Motors
walkthrough-series-u-commanded = u_sa vorgegeben (V)
walkthrough-series-u-applied = u_sa angelegt (V)
walkthrough-series-lyapunov = V(t) Lyapunov-Funktion
walkthrough-series-bound = Schranke (59)
walkthrough-series-law-paper = Ihr { $output } − { $output } des Artikels
walkthrough-series-law-gives = Ihr { $output } − das { $output }, das { $rate } ergibt
walkthrough-nis-low = 2,5-%-Quantil
walkthrough-nis-high = 97,5-%-Quantil
walkthrough-stability-plot-unit = V (gemischte Einheiten: ½Σz_i²)

## A section's frame (walkthrough-sections.js, walkthrough.js)

walkthrough-diagram-label = Schaubild zu Abschnitt { $section }
walkthrough-equation-label = Gleichung { $number } in Abschnitt { $section }
walkthrough-run-shows = Was der Lauf zeigt
walkthrough-lumped-label = Zusammengefasste Parameter von Strecke und Modell
walkthrough-lumped-plant = Strecke
walkthrough-lumped-model = Modell
walkthrough-stability-waiting = Starten Sie ein Szenario, um V mit der Schranke zu vergleichen.
walkthrough-compare-button = Euler- und RK4-Prädiktor an diesem Szenario vergleichen
walkthrough-compare-label = Euler- und RK4-Prädiktor im Vergleich
walkthrough-knobs = Entwurfsparameter
walkthrough-ifoc-note = Dieses Szenario verwendet das klassische IFOC-Vergleichsverfahren. Die Backstepping-Terme unten werden zum Vergleich aus dem Schätzwert des EKF berechnet; sie treiben den Motor nicht.
walkthrough-equations-failed = Die Gleichungen konnten nicht geladen werden: Prüfen Sie die Verbindung und öffnen Sie den Entwurfsdurchgang erneut.

## The stability report (walkthrough-reports.js): the bound (59) against V over the run, then
## what it adds when V leaves the bound, by the likely cause. Its sentences are shown one after
## the other, parted by a space.

walkthrough-stability-nothing = Es wurde nichts aufgezeichnet.
walkthrough-stability-bound-robust = λ = 2·min(k) = { $lambda } 1/s, ε = { $eps } (robuste Terme eingeschaltet).
walkthrough-stability-bound-off = λ = 2·min(k) = { $lambda } 1/s, ε = { $eps } (robuste Terme ausgeschaltet, die Schranke ist also V(0)·e^(−λt)).
walkthrough-stability-under =
    V bleibt { $samples ->
        [one] bei seinem einzigen Abtastwert
       *[other] bei allen { $samples } Abtastwerten
    } unter der Schranke.
walkthrough-stability-above =
    V liegt bei { $outside } von { $samples ->
        [one] { $samples } Abtastwert
       *[other] { $samples } Abtastwerten
    } über der Schranke, erstmals bei t = { $first } s; bei { $outsideSaturated } davon ist die Spannung gesättigt ({ $saturated ->
        [one] insgesamt ist { $saturated } Abtastwert gesättigt
       *[other] insgesamt sind { $saturated } Abtastwerte gesättigt
    }).
walkthrough-stability-cause-saturation = Bei den meisten dieser Abtastwerte liegt die vorgegebene Spannung jenseits der Grenze: Die Sättigung setzt die entworfene Fehlerdynamik außer Kraft, auf der die Schranke beruht.
walkthrough-stability-cause-sampling = Mit dem idealen Beobachter und exaktem Modell ist d̃2 = d̃4 = 0, und zeitkontinuierlich bliebe V unter der Schranke (bei gleichen Verstärkungen auf ihr). Der abgetastete Regelkreis hinterlässt einen eigenen Fehler in den z_i, von der Größenordnung Ts: Bei decay bleibt V auf einem Sockel stehen, während die Schranke weiter fällt, sodass V weit über ihr endet, und eine Halbierung von Ts skaliert den Sockel mit dem Faktor { $wt-decay-halfts }. Ein Fehler im Rotorwiderstand bringt eine eigene Störung ein, weit über diesem Sockel: Liegt R_r des Motors 10 % über bzw. unter dem des Modells, endet V bei decay beim { $wt-decay-rrhigh }- bzw. { $wt-decay-rrlow }-Fachen davon. Ein Fehler im Trägheitsmoment tut das bei decay nicht: Liegt das Trägheitsmoment des Modells 20 % über bzw. unter dem des Motors (model.j = 0.024 und model.j = 0.016), endet V beim { $wt-decay-jhigh }- bzw. { $wt-decay-jlow }-Fachen des Sockels.
walkthrough-stability-cause-estimation-errors = Die Schätzfehler gehen als d̃2 und d̃4 ein; bei ausgeschalteten robusten Termen beschränkt nichts z2·d̃2 + z4·d̃4, sodass die Schranke (die dann d̃ = 0 annimmt) nicht gelten muss.
walkthrough-stability-cause-eps-or-sampling = ε ist zu klein für die tatsächlichen d̃2, d̃4, oder die Abtastung mit 20 kHz bringt einen Fehler ein, den der zeitkontinuierliche Beweis nicht kennt.

## The EKF's predictors compared (walkthrough-reports.js)

walkthrough-compare-note = Gleiches Szenario und gleicher Startwert, nur der Prädiktor des EKF unterscheidet sich; Kennwerte ab t = { $from } s, dem Ende des Anlaufvorgangs, wie in der Kennwertleiste.
walkthrough-compare-predictor = Prädiktor
walkthrough-compare-tracking = RMS-Folgefehler (rad/s)
walkthrough-compare-speed = RMS-Fehler des Drehzahlschätzwerts (rad/s)
walkthrough-compare-flux = RMS-Fehler des Flussschätzwerts (Wb)
walkthrough-compare-nis = mittlerer NIS
walkthrough-compare-saturated = Abtastwerte an der Spannungsgrenze
