# The analysis and challenge tools' words: the Analysis tab (sweeps, seed bands, the model-error
# map), the challenge panel a student sees, and the Challenge tab a lecturer uses (the composer,
# its check, the grading of a class). Numbers come in variables, already written in the language's
# way. Names the core gives (a variant's or a figure's label, a field's name, a scenario, the core's
# messages) also come in variables.

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

# $value is what the workers field holds, as typed.
sweep-workers-invalid = workers = { $value }: expected a whole number from 1 to 8.
sweep-status-checking = Checking the sweep…
# The core's message on why the sweep's form is not acceptable.
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
# $reason: the error's message.
sweep-status-failed = Sweep failed: { $reason }
# A sweep in the address of a shared link that could not be run. $link is that part of the
# address ("#sweep=" and the sweep's text), $reason the core's message on why.
sweep-link-refused = The sweep in the address ({ $link }) was not run: { $reason }.

## Seed runs: the form's run and status line (web/analysis/seeds.js)

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
# $reason: the error's message.
seeds-status-failed = Seed sweep failed: { $reason }

## Model-error map: its run and status line (web/analysis/robust.js)

map-status-starting = Running { $cells } cells × { $seeds } seeds…
map-status-running = Running the map: { $done } of { $total } runs.
# $reason: the core's message on why it refuses the map.
map-refused = The map was not run: { $reason }.
map-not-run = The map was not run: the settings are not valid or not allowed here; the message at the top says why.
# $reason: the error's message.
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

## Challenge panel: what a student sees of a challenge link (web/challenge/challenge.js)

# The panel's heading while the challenge loads.
challenge-heading = Challenge
challenge-link-rejected = This challenge link was rejected: { $reason }. The page shows the default scenario instead.
challenge-submission-another = This submission link belongs to another challenge (its challenge part was edited): it was not graded.
challenge-submission-refused = This submission link was refused: { $reason }. It was not graded; the task starts from its base settings.
challenge-submission-rejected = This submission link was rejected: { $reason }. It was not graded; the task starts from its base settings.
challenge-run = Run and check
challenge-settings = Your settings
# $fields: the settings the student may change, by their names in the settings, e.g. "k1, k2".
challenge-settings-hint = Only { $fields } can be changed; the other settings are locked by the challenge.
challenge-checklist = Checklist
challenge-task = The task in full
challenge-verdict-pending = Not checked yet: the first run is being computed.
# A criterion before the first check: $label is its figure's label, $figure the figure's name,
# e.g. "peak stator current |i_s| (current_peak): not checked yet".
challenge-need-pending = { $label } ({ $figure }): not checked yet
challenge-verdict-link-refused = ✗ Not graded: the settings in the link were refused (see above). Change the allowed settings and run.
challenge-verdict-cancelled = ✗ Check cancelled: not graded. Run again to check.
challenge-verdict-failed = ✗ The check failed: { $reason }. Not graded.
# Follows the verdict: $name is the built-in challenge the link's title claims.
challenge-verdict-edited = This is not the built-in { $name }: its terms were edited.
# Follows the verdict when the nominal run was run again for the check.
challenge-verdict-rerun = The run on screen is not the graded one (a locked setting differs): the nominal run was run again with the challenge’s settings and your allowed ones.
# The check's progress: $done of $runs runs, which are the nominal run and $variants variants.
challenge-checking =
    Checking: { $done } of { $runs ->
        [one] { $runs } run
       *[other] { $runs } runs
    } done (the nominal run and { $variants ->
        [one] { $variants } variant
       *[other] { $variants } variants
    })…
# The student's settings are no answer to the challenge, so they were not run (in the panel's
# alert, and as the verdict).
challenge-refusal-not-run = Your settings are not a valid answer: { $reason }. Not run.
challenge-verdict-not-run = ✗ Not run. Your settings are not a valid answer: { $reason }.
# The settings of the run just ended are no answer, so it was not graded.
challenge-refusal-not-graded = Your settings are not a valid answer: { $reason }. Not graded.
challenge-verdict-not-graded = ✗ Not graded. Your settings are not a valid answer: { $reason }.
challenge-copied = Submission link copied: it replays these runs bit for bit.
# The browser refused to copy: $url is the link, to copy by hand.
challenge-copy-by-hand = Copy this submission link: { $url }

## Challenge panel: the checklist and its controls (web/challenge/checklist.js)

checklist-not-measured = not measured
# A settling time never reached.
checklist-never = never (∞)
# A measured value with its unit, e.g. "0.0123 rad/s".
checklist-value-unit = { $value } { $unit }
checklist-passed =
    { $criteria ->
        [one] ✓ Passed: the criterion is met.
       *[other] ✓ Passed: all { $criteria } criteria are met.
    }
# As checklist-passed, for a challenge with robustness variants: $variants is how many.
checklist-passed-variants =
    { $criteria ->
        [one] ✓ Passed: the criterion is met (the nominal run and { $variants ->
            [one] { $variants } variant
           *[other] { $variants } variants
        }).
       *[other] ✓ Passed: all { $criteria } criteria are met (the nominal run and { $variants ->
            [one] { $variants } variant
           *[other] { $variants } variants
        }).
    }
# $met of the $criteria criteria hold.
checklist-failed = ✗ Not passed: { $met } of { $criteria } criteria met.
checklist-failed-variants =
    ✗ Not passed: { $met } of { $criteria } criteria met (the nominal run and { $variants ->
        [one] { $variants } variant
       *[other] { $variants } variants
    }).
# The mark before a criterion.
checklist-pass = ✓ pass
checklist-fail = ✗ fail
# A criterion judged: $label is its figure's label, $value the value measured (checklist-value-unit,
# or checklist-not-measured), $bound the bound in the core's words, e.g. "≤ 0.004 s".
checklist-criterion = { $label }: { $value }, needs { $bound }
# As checklist-criterion, judged on a variant's run: $run is that run's settings, e.g. "seed=3".
checklist-criterion-worst = { $label }: { $value }, needs { $bound } (worst run: { $run })
# Why a criterion fails, after it: $reason is the core's, e.g. "above the bound".
checklist-reason = — { $reason }

## Challenge panel: the knobs of the allowed settings (web/challenge/knobs.js)

# A setting's description (the core's) and its unit, e.g.
# "speed-error rate k1 (1/s)".
challenge-knob-doc = { $doc } ({ $unit })
# What a setting may be: $options are its choices, joined by commas, e.g. "euler, rk4".
challenge-allowed-choice = allowed: one of { $options }
# $unit: the unit of the formula's value, e.g. "V".
challenge-allowed-formula = allowed: a formula of your own ({ $unit }; the walkthrough’s “Write this step” lists the names)
# $lo and $hi: the range's ends, as the settings write numbers (with a point), e.g. "300" and "1200".
challenge-allowed-range = allowed: { $lo } to { $hi }
challenge-allowed-range-unit = allowed: { $lo } to { $hi } { $unit }

## Challenge panel: the header, where the challenge comes from (web/challenge/origin.js)

# Above the challenge's title.
challenge-kind = Challenge
challenge-origin-builtin = Built-in challenge
challenge-origin-mine = Set by you in this browser: it composed exactly this challenge (bounds and title unchanged)
challenge-origin-other = Not a challenge you set in this browser
challenge-origin-unknown = This browser keeps no record of the challenges it composed
# Before the challenge's fingerprint, a short code of its terms.
challenge-fingerprint = Fingerprint
# $name: the built-in challenge whose title the link carries, e.g. "step-tune".
challenge-edited = Edited: this link carries the built-in challenge { $name }’s title, but not its terms. It is graded as the challenge it is, not as { $name }.

## The built-in challenges, in the Lessons tab (web/challenge/builtins.js)

# $name: the challenge's name, e.g. "step-tune".
builtins-open = Open the { $name } challenge
builtins-failed = The built-in challenges could not be listed.

## Challenge tab: composing a challenge (web/challenge/challenge-compose.js)

compose-intro = The challenge starts from the scenario in the settings (its base); the student may change only the fields listed here, within their ranges, and passes when every criterion holds. Set the scenario up and run it first: the criteria are prefilled from its figures, 20 % tighter than this run.
# Before the base scenario's text.
compose-base = Base:
# The label of the challenge's title field.
compose-title = Title
# The title the field starts with; $preset is the scenario's preset, e.g. "step".
compose-title-default = Challenge: { $preset }
compose-make = Make the challenge link
# “Fill from the current scenario” is the button's label.
compose-no-run = No finished run of this scenario to take the figures from: run it, then press “Fill from the current scenario” again.
# $reason: the core's message naming the part at fault.
compose-invalid = The challenge is not valid: { $reason }
compose-link = Challenge link
# “Set by you in this browser” is what challenge-origin-mine says.
compose-kept = This browser keeps a record that it composed this challenge: the link, opened here, says “Set by you in this browser”; a copy with another bound or title does not.
compose-not-kept = This browser keeps no record of the challenges it composed (its storage or Web Crypto is unavailable here): the link, opened here, cannot say that you set it.
compose-copy-link = Copy challenge link
compose-link-copied = The challenge link copied.
compose-link-not-copied = Select the challenge link above and copy it.
compose-open = Open as a student
compose-brief = The task in words (for a slide or the course page)
compose-copy-brief = Copy the task
compose-brief-copied = The task copied.
compose-brief-not-copied = Select the task above and copy it.

## Challenge tab: the composer's rows (web/challenge/compose-rows.js)

compose-allow-legend = Fields the student may change
compose-field = Field
# An entry of the field menu: the field's name and the core's description of it, e.g.
# "k1 — speed-error rate k1".
compose-field-option = { $field } — { $doc }
compose-add = Add
compose-remove = Remove
    .aria-label = Remove { $field }
# A field the student writes a formula for; $unit is the formula's unit.
compose-allow-formula = a formula of the student’s own ({ $unit })
# The label of a field's choices, written a|b; $field is its name.
compose-allow-choices = { $field }: choices (a|b)
# Before and between the ends of a field's range.
compose-allow-from = from
compose-allow-to = to
# After a field's range: its unit, and its value in the base scenario, e.g. "rad/s (now 600)".
compose-allow-now-unit = { $unit } (now { $value })
compose-allow-now = (now { $value })
compose-need-legend = Criteria: the figures of this run
# “All runs” is the label of each criterion's compose-need-all-runs box.
compose-need-hint = “All runs” makes the criterion hold on every variant too (the worst run counts).
# A criterion's box: $label is the figure's label, $figure its name, e.g.
# "peak stator current (current_peak)".
compose-need = { $label } ({ $figure })
# As compose-need, with the figure's $value in the last run and its $unit.
compose-need-now = { $label } ({ $figure }) — now { $value }
compose-need-now-unit = { $label } ({ $figure }) — now { $value } { $unit }
# For screen readers: the criterion's bound menu and its bound field.
compose-need-op = { $figure }: how it is bounded
compose-need-bound = { $figure }: bound
compose-need-bound-unit = { $figure }: bound { $unit }
# The bound menu's entries.
compose-op-max = at most
compose-op-min = at least
compose-op-abs = |value| at most
compose-op-band = inside its 95 % band
# In the bound field of a criterion that takes none.
compose-bound-none = none
compose-need-all-runs = all runs
compose-vary-legend = Robustness variants (optional)
# seeds:A..B and the settings are written as the page reads them: keep them as they are.
compose-vary = Variants: seeds:A..B, or settings applied on top of the student’s, separated by |
    .placeholder = seeds:2..10  or  model.j=0.016|model.j=0.024
compose-vary-seeds = Seeds 2 to 10

## Challenge tab: the check that a design passes (web/challenge/compose-check.js)

compose-check-progress =
    .aria-label = Challenge check: runs done
compose-check-cancel = Cancel check
compose-check-starting = Checking whether a design within the allowed ranges passes…
# $done of $runs runs, of $designs designs.
compose-check-running =
    Checking whether a design within the allowed ranges passes: { $done } of { $runs ->
        [one] { $runs } run
       *[other] { $runs } runs
    } ({ $designs ->
        [one] { $designs } design
       *[other] { $designs } designs
    })…
compose-check-cancelled = Check cancelled: whether a design within the allowed ranges passes is not known. Make the link again to check.
# $reason: the error's message.
compose-check-failed = The check failed: { $reason }.
# The design that changes no field.
compose-check-base-design = the base, with no field changed
# A criterion a design fails: $figure is its name, $value the value measured, $bound the bound
# in the core's words, e.g. "current_peak: 3.21 A vs ≤ 0.1 A".
compose-check-failure = { $figure }: { $value } vs { $bound }
# As compose-check-failure, for a value still changing at the end of the run.
compose-check-failure-changing = { $figure }: { $value } vs { $bound }, still changing
# A criterion with no value: $reason is the core's, e.g. "ran away".
compose-check-unmeasured = { $figure }: { $reason }
compose-check-base-passes = The base passes as it is: a student who changes nothing passes.
# $failures: the criteria it fails, each a compose-check-failure, joined by semicolons.
compose-check-base-fails = The base (no field changed) fails: { $failures }.
# $budget: the most runs a check takes.
compose-check-tried =
    The check tried { $designs ->
        [one] { $designs } design
       *[other] { $designs } designs
    } in { $runs ->
        [one] { $runs } run
       *[other] { $runs } runs
    } (at most { $budget } runs): the base first, then those that change the fewest fields, from the ends of the ranges inward (every combination, when they fit).
# $design: the settings of a design that passes, e.g. "k1=600, k2=1200" (or
# compose-check-base-design); $passing of the $tried designs pass.
compose-check-solvable = ✓ A design within the allowed ranges passes: { $design } ({ $passing } of { $tried } designs tried pass).
# $design: the design that came closest; $failures: what it fails (see compose-check-base-fails).
compose-check-unsolved = ✗ No design of the { $tried } tried passes: the bounds may be out of reach; the closest was { $design } ({ $failures }).

## Challenge tab: grading a class (web/challenge/grade.js)

# Why a class was not graded; the reasons below (grade-no-…) or the core's.
grade-refused = Not graded: { $reason }.
grade-no-challenge = name a challenge: a built-in’s name or a challenge link
grade-no-file = choose a class file, or paste the links, one a line
grade-no-submission = the file holds no submission
# $encoding: the encoding the class file was read as, e.g. "windows-1252".
grade-read-as = The class file was read as { $encoding } (it is not UTF-8).
grade-status-reading = Reading the class file…
grade-status-grading = Grading { $total } submissions…
# $kept: the submissions graded before, whose results the browser kept.
grade-status-grading-kept = Grading { $total } submissions, { $kept } kept from the last grading…
# Beside the progress bar.
grade-count = Graded { $done } of { $total }
grade-status-done = Graded { $total } of { $total }: { $passed } passed.
grade-not-stored = The browser’s storage did not take this grading: download it now.
# “Grade” is the button that grades. $graded of $total submissions were graded.
grade-status-cancelled-kept = Cancelled: { $graded } of { $total } graded, kept in this browser; Grade goes on from there.
grade-status-cancelled-lost = Cancelled: { $graded } of { $total } graded, not kept (the browser’s storage refused them).
# $reason: the error's message.
grade-status-stopped-kept = The grading stopped: { $reason }. { $graded } of { $total } graded, kept in this browser; Grade goes on from there.
grade-status-stopped-lost = The grading stopped: { $reason }. { $graded } of { $total } graded, not kept (the browser’s storage refused them).
grade-status-cancelled-reading = Cancelled while the class file was read: nothing was graded.
# A download of a grading not finished: its first $rows of $total rows. $command is the command
# line that finishes the file: keep it as it is.
grade-downloaded-partial = Downloaded the first { $rows } of { $total } rows, in order: Grade goes on from where it stopped, and { $command } can finish the file.

## Challenge tab: the class's table (web/challenge/grade-table.js)

grade-pending = not graded yet
grade-pass = ✓ pass
grade-fail = ✗ fail
grade-head-line = line
grade-head-verdict = verdict
grade-head-link = link
# A failed criterion's value with the reason it fails, e.g. "0.0234 s: above the bound".
grade-value-reason = { $value }: { $reason }
# A criterion judged on a variant's run: $text is what is said of it, $run that run's settings,
# e.g. "seed=3".
grade-worst-run = { $text } (worst run: { $run })

## The Analysis tab: a motor of your own

motor-intro = Estimates a motor's equivalent circuit from the stator's DC resistance, the no-load test at rated voltage and the locked-rotor test (IEEE Std 112), as imlab motor does, and says which values are estimates. The motor then runs as plant and model alike, with the design derived from it. Each test is one reading: line voltage, line current, input power and frequency, separated by commas.
motor-rs = stator resistance per phase, DC test
motor-no-load = no-load test
motor-locked = locked-rotor test
# The NEMA design letter splits the locked-rotor leakage between stator and rotor.
motor-nema = NEMA design letter
motor-rated = nameplate: voltage, frequency, current
motor-j = rotor inertia
motor-np = pole pairs
motor-run-button = Estimate the circuit
motor-example-button = Fill in an example
motor-example-filled = The form holds a 2.2 kW, 400 V machine as a lab would write it down: its nameplate and the readings its circuit gives (a simulated lab, not a catalogue's motor).
motor-open = Run this motor with its derived design
