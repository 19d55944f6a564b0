# Die Texte der Lehrwerkzeuge, die vor den Lektionen und dem Entwurfsdurchgang geladen werden.

## Das Untersuchungsfeld (inspect-panel.js): jeder Term des Entwurfs an einem Abtastwert

inspect-title = Untersuchung des Abtastwerts k = { $k }, t = { $time } s
inspect-copy = Exakte Werte kopieren
inspect-copied = Kopiert
inspect-copy-failed = Kopieren fehlgeschlagen: Markieren Sie stattdessen die Tabelle
inspect-close = Schließen (Esc)
inspect-exact = exakt: { $value }
inspect-group-step = Schritt { $step }
inspect-group-voltage = Spannung (54) und Begrenzung
inspect-group-estimate = Schätzwert x̂ (k|k)
inspect-group-measured = Messwerte und wahre Werte
inspect-term = Term
inspect-value = Wert
inspect-unit = Einheit
inspect-meaning = Bedeutung
inspect-gain-caption = Kalman-Verstärkung K_k (A⁻¹ × Einheit des Zustands) und L = K_k/Ts (pro Sekunde)
inspect-gain-row = Zeile

## Das eigene Regelgesetz eines Schritts (law-editor.js)

law-write = Diesen Schritt selbst schreiben
law-names = Verwendbare Namen und Funktionen
law-names-name = Name
law-names-symbol = Symbol
law-names-unit = Einheit
law-names-meaning = Bedeutung
law-names-functions = Mit + − * / ^ (oder · und −), Klammern, Zahlen und den Funktionen { $functions }.
law-error-at = Bei Zeichen { $at }: { $reason }
law-stale = Nicht das eingegebene Regelgesetz: Der gezeigte Lauf, dieser Befund und das Residuendiagramm gehören zu { $output } = { $law }. { $verdict }
law-stale-after = Nicht das eingegebene Regelgesetz: Der gezeigte Lauf, dieser Befund und das Residuendiagramm gehören zu { $output } = { $law } nach { $previous } = { $previousLaw }. { $verdict }

## Der Entwurfsdurchgang (walkthrough.js)

