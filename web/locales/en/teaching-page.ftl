# The teaching tools' words: the inspect panel, the editor of a step's own law (in the walkthrough
# and in the settings), and the walkthrough's own notes. The core's words (its units, its terms'
# meanings, its verdicts and errors) come in variables, said in the page's language.

## The inspect panel (inspect-panel.js): every term of the design at one sample

# The panel's heading: $k is the sample's index (1024), $time its time in seconds (0.0512).
inspect-title = Inspect sample k = { $k }, t = { $time } s
inspect-copy = Copy exact values
# Said on the copy button once the values are on the clipboard.
inspect-copied = Copied
inspect-copy-failed = Copy failed: select the table instead
inspect-close = Close (Esc)
# A value's tooltip: $value is the exact value, as the CSV export writes it (0.000123456789).
inspect-exact = exact: { $value }
# The tables' captions: the terms of step $step (1 to 4), of the voltage and of the estimate.
inspect-group-step = Step { $step }
inspect-group-voltage = Voltage (54) and limit
inspect-group-estimate = Estimate x̂ (k|k)
inspect-group-measured = Measured and true
# The terms' tables: their column headers.
inspect-term = term
inspect-value = value
inspect-unit = unit
inspect-meaning = meaning
inspect-gain-caption = Kalman gain K_k (A⁻¹ × state unit) and L = K_k/Ts (per second)
# The gain table's first column header: its rows are the states.
inspect-gain-row = row

## A step's own law (law-editor.js)

law-write = Write this step
law-names = The names and functions you can use
# The table of the names a law may use: its column headers.
law-names-name = name
law-names-symbol = symbol
law-names-unit = unit
law-names-meaning = meaning
# $functions lists the functions a law may call, each with its meaning as the core writes it,
# parted by semicolons (“sin(x): sine; cos(x): cosine”).
law-names-functions = With + − * / ^ (or · and −), parentheses, numbers and the functions { $functions }.
# An error in a law as typed: $at is the place of the character it concerns, counted from 1;
# $reason is the core's (“unknown name 'foo' (see the list of names)”).
law-error-at = At character { $at }: { $reason }
# A verdict on a law other than the one typed now: $output is the law's output (v2), $law the
# formula that ran (“-si1 + dwd - k1s1*z1”), $verdict the core's verdict on it.
law-stale = Not the law typed: the run shown, and this verdict and the residual plot, are of { $output } = { $law }. { $verdict }
# The same for a law judged on the previous step's own law: $previous is that law's output (v1)
# and $previousLaw its formula.
law-stale-after = Not the law typed: the run shown, and this verdict and the residual plot, are of { $output } = { $law } after { $previous } = { $previousLaw }. { $verdict }

## The walkthrough (walkthrough.js)

