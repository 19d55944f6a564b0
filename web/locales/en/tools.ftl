# The analysis and challenge tools' words: the Analysis tab (sweeps, seed bands, the model-error
# map), the challenge panel a student sees, and the Challenge tab a lecturer uses (the composer,
# its check, the grading of a class). Numbers come in variables, already written in the language's
# way. Names the core gives (a variant's or a figure's label, a field's name, a scenario, the core's
# messages) also come in variables, in English for now.

## Frequency-response sweep: the Bode plots and the table (web/analysis/analysis.js)

sweep-plot-magnitude = Magnitude of ω/ω_d
sweep-plot-phase = Phase of ω against ω_d
# The phase plot's y-axis label.
sweep-axis-degrees = degrees
# The legend's label of a variant's points that had not settled; $variant is the variant's label,
# e.g. "Backstepping + Euler EKF (paper)".
sweep-series-unsettled = { $variant }, not settled
sweep-unsettled =
    { $count ->
        [one] { $count } point had not settled (hollow markers): the bandwidth and the phase at 200 Hz are never read off them. Longer runs may settle them.
       *[other] { $count } points had not settled (hollow markers): the bandwidth and the phase at 200 Hz are never read off them. Longer runs may settle them.
    }
# A point that had not settled: $variant is the variant's label, $frequency its frequency (a
# sweep-hz), $reason the core's words on why.
sweep-unsettled-point = { $variant }, { $frequency }: { $reason }
# A frequency, e.g. "12.50 Hz".
sweep-hz = { $value } Hz
# A phase, e.g. "-45.30 °".
sweep-degrees = { $value } °
sweep-head-variant = variant
sweep-head-bandwidth = −3 dB bandwidth
sweep-head-phase = phase at 200 Hz
sweep-head-saturation = worst saturation
sweep-head-failed = failed points
sweep-head-unsettled = unsettled points
sweep-head-peak = peak |i_s| (A)
sweep-bandwidth-unsettled = not given: it would rest on a point that had not settled
sweep-bandwidth-below = below the lowest frequency
sweep-not-reached = not reached in the grid
sweep-phase-not-reached-settled = not reached by the settled points
# The unsettled points' cell: how many, and their frequencies (each a sweep-hz, joined by commas).
sweep-unsettled-cell = { $count }: { $frequencies }
sweep-peak-none = none measured
# The largest stator current a variant needs, and the motor's rated current, both in A.
sweep-peak = { $peak } (rated { $rated })
# As sweep-peak, with how many points need more than the rated current, and their frequencies
# (each a sweep-hz, joined by commas).
sweep-peak-over = { $peak } (rated { $rated }); above the rating at { $count }: { $frequencies }

## Seed bands: the plots (web/analysis/analysis.js)

seeds-plot-error = Speed error ω − ω_d over seeds (mean, min, max)
seeds-plot-estimate = Estimation error ω − ω̂ over seeds (mean, min, max)
seeds-series-mean = mean
seeds-series-min = min
seeds-series-max = max

## Frequency-response sweep: the form's run, status line and link (web/analysis/sweeps.js)

# The mark on a sweep shown for an earlier scenario. web/ui/stale.js writes its sentence from these
# parts: “{ sweep-stale } of an earlier scenario (SCENARIO), not of the settings now. Press
# { sweep-stale.press } to bring it up to date. { sweep-stale.export }”. The value is the
# sentence's subject and verb; .press names the Run sweep button as the page labels it.
sweep-stale = These Bode plots and this table are
    .press = “Run sweep”
    .export = Their CSV, which does not name its scenario, is off until then.
# $value is what the workers field holds, as typed.
sweep-workers-invalid = workers = { $value }: expected a whole number from 1 to 8.
sweep-status-checking = Checking the sweep…
# The core's message on why the sweep's form is not acceptable, in English for now.
sweep-refused = { $reason }.
sweep-not-run = The sweep was not run: the settings are not valid or not allowed here; the message at the top says why.
sweep-status-running = Sweeping…
# $variants: the variants swept; $points: the frequencies of each; $ms: the time it took.
sweep-status-done =
    { $workers ->
        [one] { $variants } × { $points } runs in { $ms } ms on { $workers } worker.
       *[other] { $variants } × { $points } runs in { $ms } ms on { $workers } workers.
    }
sweep-status-cancelled = Sweep cancelled.
# $reason: the error's message, in English for now.
sweep-status-failed = Sweep failed: { $reason }
# A sweep in the address of a shared link that could not be run. $link is that part of the
# address ("#sweep=" and the sweep's text), $reason the core's message on why.
sweep-link-refused = The sweep in the address ({ $link }) was not run: { $reason }.

## Seed runs: the form's run and status line (web/analysis/seeds.js)

# The mark on seed bands shown for an earlier scenario (see sweep-stale).
seeds-stale = These seed bands are
    .press = “Run seeds”
    .export = Their CSV, which does not name its scenario, is off until then.
# $value is what the seeds field holds, as typed.
seeds-count-invalid = seeds = { $value }: expected a whole number from 1 to 1000.
seeds-not-run = The seeds were not run: the settings are not valid or not allowed here; the message at the top says why.
seeds-status-starting = Running seeds…
# $percent: the share of the runs done, in per cent.
seeds-status-running = Running seeds: { $percent } %
# $runs: the runs that completed; $seeds: the seeds asked for; $first and $last: the first and
# the last seed.
seeds-status-done = { $runs } of { $seeds } seeds ({ $first } to { $last }) completed.
seeds-status-cancelled = Seed runs cancelled.
# $reason: the error's message, in English for now.
seeds-status-failed = Seed sweep failed: { $reason }

## Model-error map: its run and status line (web/analysis/robust.js)

# The mark on a map shown for an earlier scenario (see sweep-stale).
map-stale = This map is
    .press = “Run map”
    .export = Its CSV names the scenario it was run for.
map-status-starting = Running { $cells } cells × { $seeds } seeds…
map-status-running = Running the map: { $done } of { $total } runs.
# $reason: the core's message on why it refuses the map, in English for now.
map-refused = The map was not run: { $reason }.
map-not-run = The map was not run: the settings are not valid or not allowed here; the message at the top says why.
# $reason: the error's message, in English for now.
map-failed = The map failed: { $reason }
# $finished: the cells whose every seed ran; $cells: the cells of the map.
map-status-cancelled = Map cancelled: { $finished } of { $cells } cells finished and are shown; the others were not run.
# $first and $last: the first and the last seed; $seconds: the time the map took.
map-status-done = { $cells } cells × { $seeds } seeds ({ $first }–{ $last }) in { $seconds } s.
# A map in the address of a shared link that could not be run. $link is that part of the
# address ("#robust=" and the map's text), $reason the core's message on why.
map-link-refused = The map in the address ({ $link }) was not run: { $reason }.

## Model-error map: the plot over one axis (web/analysis/map-plot.js)

# $figure: the figure's label, from the core, e.g. "RMS of ω − ω_d".
map-plot-title = { $figure } over the seeds: median, and min–max band
map-series-min = min
map-series-median = median
map-series-max = max
# A value of the map's axis left out of the plot: the value, how many seeds ran away there and
# of how many.
map-gap = { $value } ({ $ranAway } of { $runs } seeds)
# As map-gap, for an axis in per cent of the parameter's value.
map-gap-percent = { $value } % ({ $ranAway } of { $runs } seeds)
# $cells: the values left out, each a map-gap, joined by commas.
map-gaps = Not drawn, because some seeds ran away there: { $cells }.

## Model-error map: the table and its key (web/analysis/map-table.js, map-colours.js)

# A figure with its unit, e.g. "RMS of ω − ω_d (rad/s)": in the figure menu and the key.
map-figure-unit = { $figure } ({ $unit })
map-cell-not-run = not run
# The tooltip of a cell. $scenario: the cell's scenario; then counts of its seeds; $figure: the
# figure's label; $min and $max: its range over the seeds.
map-cell-title = { $scenario }: { $ranAway } of { $runs } seeds ran away, { $inconsistent } inconsistent, { $overRating } past the rated current, { $unsettled } with the speed error not settled at the end; { $figure } { $min } to { $max }
# The top left corner of a two-axis table: the first axis's name runs down, the second's across.
map-grid-corner = { $rows } ↓ / { $columns } →
map-head-median = median
map-head-range = min – max
# A cell's range over the seeds.
map-range = { $min } – { $max }
# The key above the table. $figure: the figure (with its unit); $seeds: how many seeds; $colours:
# the colour scale (map-scale-…); $seed: the seed a clicked cell runs. ✕, ⚠, I↑ and ~ are the
# marks the cells show.
map-key = { $figure }, median over the seeds that did not run away ({ $seeds } seeds); colour: { $colours }. ✕ k/N: the run ran away on k of the N seeds (the run's own page says so, or it diverged), never coloured as a value; ⚠ the EKF was inconsistent; I↑ k/H: of the H seeds that held, k drew more than the motor's rated current after the start-up; ~ k/H: k ended with the speed error not settled (both outlined, and coloured by their median). Click a cell to run it (seed { $seed }).
# The colour scale of values of both signs; $max: the largest magnitude.
map-scale-diverging = blue −{ $max } through white 0 to red { $max }
# The colour scale of values of one sign spanning more than a decade, from $min to $max.
map-scale-log = log scale from light { $min } to dark { $max }
map-scale-linear = linear scale from light { $min } to dark { $max }
# No cell has a value to colour.
map-scale-none = none
