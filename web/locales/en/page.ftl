# The page's labels, buttons, notes and messages, by the part of the page that shows them.
# Numbers come in variables, already written in the language's way. A variable named $reason,
# $warning, $description or $label holds the simulation core's own words;
# a scenario ($scenario), a field's key ($key), a preset's name ($preset) or a command is written as
# it is and never translated.

## The header

# The browser tab's title.
page-title = IM Lab: speed-sensorless induction-motor control
# The name of the app, in the page's heading.
page-name = IM Lab
page-skip-link = Skip to the plots
page-intro = Speed-sensorless induction-motor control: EKF observer and four-step backstepping controller (Zhang, Wang, Bortoff et al., 2015), simulated at 20 kHz in your browser.
help-links =
    .aria-label = About / Help
# Stands before the links to the guides.
help-links-intro = About / Help:
help-student-guide = Student guide
help-lecturer-guide = Lecturer guide
help-all-guides = All guides
language-menu = Language

## Loading the lessons

# $reason is the browser's reason, in its words.
lessons-not-loaded = The lessons’ texts could not be loaded: { $reason }. Open the Lessons tab again to retry.

## Buttons shared by several places

shared-cancel = Cancel
# Downloads a table as a CSV file.
shared-csv = CSV

## The run bar: the preset, Run, the status line and the links

run-preset = Preset
run-button = Run
run-settings = Settings
run-unrun = Changed settings, not run yet: press Run or Enter. The address and “Copy link” describe the run on screen.
share-copy-link = Copy link
# Downloads an image of the plots.
export-png = PNG
share-copy-embed = Copy embed code
    .title = Copy an iframe snippet that shows the Trajectories plots in view, for this scenario

## The results: the tabs, the view bar and the figures

results =
    .aria-label = Results
tabs =
    .aria-label = Views
tab-plots = Trajectories
tab-walkthrough = Design walkthrough
tab-lessons = Lessons
tab-analysis = Analysis
tab-challenge = Challenge
present-button = Presentation mode
    .title = Larger text and plots for a projector; the settings move into a drawer
view-full-run = Full run
    .title = Show the whole run on every plot (also double-click a plot, or Escape)
view-fit = Fit y-axes after the start-up transient
# $ms is the time the start-up transient ends, in milliseconds (8.5).
view-fit-from = Fit y-axes after the start-up transient (t ≥ { $ms } ms)
view-fit-why = Why this time?
# $reason is the core's explanation of where the start-up transient ends.
view-transient-reason = Start-up transient: { $reason }.
figures-all = All figures
figures-fewer = Fewer figures
figures-strip =
    .aria-label = Figures of the run
plots-hint = Drag across a plot to zoom all of them; double-click, Escape or “Full run” returns to the whole run. The legend reads out the recorded values at the sample under the cursor; click a plot to inspect every term at that instant.

## The pins and their overlay (Trajectories tab)

pins-pin = Pin this run
# Labels the menu of the column the overlay compares.
pins-overlay = overlay
pins-column-omega = speed ω
pins-column-omega-hat = estimated speed ω̂
pins-column-flux = flux |φ|
pins-column-voltage = voltage u_sa
pins-unpin = Unpin
# A pinned run in the list: $n is its number (1), $legend how its settings differ from the current run's (k1=600).
pins-item = pin { $n }: { $legend }
# A pinned run's name in the overlay's legend; $n is its number (1).
pins-name = pin { $n }
# The current run, in the overlay's legend.
pins-current = current
# The difference between the current run and pinned run $n, in the overlay's legend.
pins-difference = current − pin { $n }
# The overlay's title; $column is the column compared, as the overlay's menu names it (speed ω).
pins-overlay-title = { $column }: current run and pinned runs
pins-difference-title = { $column }: current − pin
# $n is the pin being run (2), $count how many are run (3), $percent how much of it is done (45).
pins-status-running = Running pin { $n } of { $count }: { $percent } %
pins-status-done = Pinned
pins-status-cancelled = Pinning cancelled
# $length is the length of the address's pins part in characters, $max the most it may have.
pins-link-too-long = The pins in the address were not run: { $length } characters, more than the { $max } a pins fragment may hold.
# $pins lists the pins that could not be read, each quoted; $count is how many there are.
pins-link-malformed = Ignored a malformed pin in the address: { $pins }.
# $sent is how many pins were run (5), $dropped how many more the address held.
pins-link-dropped = Only the first { $sent } pins in the address were run; { $dropped } more were left out.
# A run that could not be pinned: the first of a list (the others follow with pins-rejected-next,
# separated by semicolons). $scenario is its scenario, $reason why.
pins-rejected-first = Could not pin { $scenario }: { $reason }
pins-rejected-next = could not pin { $scenario }: { $reason }
# The sentence of the runs that could not be pinned; $list holds them (pins-rejected-first, pins-rejected-next).
pins-rejected = { $list }.
# Why a run was not pinned: pinning was cancelled before it started, or while it ran.
pins-reason-unrun = not run: pinning was cancelled
pins-reason-cancelled = cancelled

## Lists in messages

# A list cut after its first few items; $list holds those, $count is how many more there are.
list-more = { $list } … and { $count } more

## The run's status line and messages

# $samples is the number of samples the run computes.
run-status-starting = Running { $samples } samples…
run-status-progress = Running: { $done } of { $total } samples
# $ms is how long the run took, in milliseconds.
run-status-done = { $rows } samples in { $ms } ms
run-status-ran-away = Ran away: { $rows } samples in { $ms } ms
run-status-stopped = Stopped after { $rows } samples
# $percent is how much of the run was done (45).
run-status-cancelled = Cancelled at { $percent } %
run-status-worker-failed = Stopped: the simulation worker failed
# $reason is the core's explanation of why the run stopped; $rows the samples computed before.
run-stopped-early = The run stopped early: { $reason }. The plots show the { $rows } samples before it.
# $warning is the core's sentence saying that the run ran away.
run-ran-away = { $warning } The plots show what the motor did.
run-worker-not-started = The simulation worker could not start ({ $reason }). Reload the page to try again.
run-worker-failed = The simulation worker failed ({ $reason }). It was restarted; press Run to try again.
# $pins lists the scenarios of the pinned runs, separated by semicolons.
run-worker-failed-pins = The simulation worker failed ({ $reason }). It was restarted; press Run to try again. The pinned runs were dropped: { $pins }.
# $language is the code of the language asked for (de).
page-language-failed = The page could not load its { $language } messages ({ $reason }): it is in English.
page-messages-failed = The rest of the page’s messages could not be loaded ({ $reason }). The tools, lessons and walkthrough need them: using one tries again.
page-challenge-tools-failed = The Challenge tab’s composer and grading could not be loaded: { $reason }. Open the tab again to retry.
page-lesson-map-failed = The lesson’s map could not be loaded: { $reason }.
# $lesson is the name the address asked for; $lessons lists the lessons' names.
page-no-lesson = No lesson named '{ $lesson }'. Lessons: { $lessons }.
# Why a lesson's link could not be compared with the lesson's run: these complete the lesson
# panel's sentence "This link holds settings of its own, … : …".
lesson-differences-refused = the core refused some of them ({ $reason })
lesson-differences-uncompared = they could not be compared with it

## Why the simulation worker failed (the $reason of the messages above)

worker-unknown-error = unknown error
worker-unreadable = a message from it could not be read
# $error is the browser's error; $panic the core's own message.
worker-crash-panic = { $error }; Rust panic: { $panic }
worker-crash-memory = { $error }; most likely the core ran out of memory
# A worker of the analyses' pool failed; $reason says why.
pool-worker-failed = a worker failed ({ $reason })
pool-worker-failed-restart = a worker failed ({ $reason }); the next run starts a fresh one
# $reason is the browser's error.
worker-tools-not-loaded = The tools could not be loaded ({ $reason }): check the connection and try again.
# $reason is the core's error.
compare-failed = Comparison failed: { $reason }
compare-running = Running both predictors…

## Exports

export-csv-starting = Exporting CSV…
export-csv-progress = Exporting CSV: { $rows } of { $total } rows
export-csv-done = CSV exported: { $total } rows
export-csv-cancelled = CSV export cancelled
export-csv-cancelled-by-run = The CSV export was cancelled: a new run started.
export-csv-stopped = CSV export stopped
export-csv-failed-status = CSV export failed
# $reason is the core's error, or export-csv-gone.
export-csv-failed = The CSV export failed: { $reason }.
export-csv-gone = this run is no longer held by the worker; run it again
# $megabytes is how much of the CSV the browser held; $error the browser's error's name;
# $command the command line that exports the run (not translated).
export-csv-refused = The browser refused to hold more than { $megabytes } MB of CSV ({ $error }). Export this run with the command line instead: { $command }
export-png-not-ready = These plots are still being drawn; export them in a moment.

## Sharing

share-link-copied = Link copied: it reproduces this run bit for bit.
# $link is the page's address.
share-copy-this-link = Copy this link: { $link }
# The title of an embedded frame, read by screen readers: $preset is the preset's name, $plots the plots' ids (speed, flux).
share-embed-title = IM Lab: { $preset }, { $plots }
# $plots lists the plots' ids (speed, flux); $count is how many.
share-embed-copied =
    Embed code copied: the { $plots } { $count ->
        [one] plot
       *[other] plots
    } of this run (the Trajectories plots in view). Paste it into a slide or a course page.
# $code is the HTML code to copy.
share-embed-copy-this =
    Copy this embed code for the { $plots } { $count ->
        [one] plot
       *[other] plots
    } of this run (the Trajectories plots in view): { $code }
# $names lists the unknown plot ids the address asked for, each quoted, $count how many;
# $shown the plots shown instead; $plots every plot's id.
embed-unknown-plots = No plot named { $names }; showing { $shown }. Plots: { $plots }.

## A result of an earlier scenario than the settings' ($scenario is that scenario)


## A step's own law (the settings form and the walkthrough)

# $step is the step's number (1 to 4); v{ $step } names its control law (v1).
law-paper-default = No law of your own yet: this step runs the paper’s v{ $step }.

## The settings form

settings-group-reference = Reference
settings-group-controller = Controller: backstepping or classical IFOC
settings-group-gains = Backstepping gains
settings-group-observer = Observer (EKF)
settings-group-noise = Noise and seed
settings-group-plant = Plant: the simulated motor
settings-group-model = Model: what the EKF and controller assume
settings-group-load = Unknown load: a step, or a table of points
settings-group-limits = Voltage limit (box), rating, duration and timing
settings-group-drive = Drive: computation delay, inverter limit and PWM
settings-group-law = Your own laws for the backstepping steps (empty: the paper’s)
# The values a field allows, under it and in its tooltip (settings-allowed).
settings-allowed-formula = a formula of the names the walkthrough’s “Write this step” lists; empty: the paper’s law
# $min and $max are the least and the largest value ($max with the field's unit: 20 s), $op is < or ≤,
# $key the field's key (duration).
settings-allowed-range = { $min } { $op } { $key } ≤ { $max }
# A table of points: $points points at most; $min and $max bound the values ($max with their unit).
settings-allowed-table = up to { $points } points t:value, such as 0:0,0.1:100, times rising from 0; values from { $min } to { $max }
settings-allowed-whole = { $min } { $op } { $key } ≤ { $max }, whole number
# $values is what the field allows (settings-allowed-range, or its options: euler | rk4).
settings-allowed = allowed: { $values }
# $list holds the core's reasons, separated by semicolons.
settings-link-rejected = Some settings in the address were rejected and left at the preset's values: { $list }.
# $preset is the preset shown instead.
settings-link-refused = The scenario in the address was rejected: { $reason }. Showing { $preset } instead.
# $description is the core's description of the preset; $fields lists the keys of the settings changed (k1, duration).
settings-preset-changed = Preset { $preset }: { $description }. This run changes { $fields }, so what the preset's description says of its run need not hold for this one.
# The preset's description ($changed: settings-preset-changed or the description alone), then the
# settings the run ignores ($idle: each a field-idle of the core, joined by settings-idle-separator).
settings-idle = { $changed } Ignored: { $idle }.
settings-idle-separator = {"; "}

## The figures strip and the key figures

# A current as a multiple of the motor's rated current: $value is the current (20.33 A),
# $ratio the multiple (5.08), $rated the rated current (4).
figures-to-rated = { $value } ({ $ratio }× the rated { $rated } A)
# The mean NIS ($value) and its 95 % band, from $low to $high.
figures-nis-inside = { $value } (95 % band { $low }–{ $high }: inside)
figures-nis-outside = { $value } (95 % band { $low }–{ $high }: outside)
# The tooltip of a figure: $value is its exact value with its unit, $window the core's words for the part of the run it covers.
figures-exact = exact: { $value }; { $window }
# The tooltip of a figure the run had not reached: $reason is the core's words for it.
figures-no-value = no value: { $reason }; { $window }
# Whether a final value had settled by the end of the run. $rate, $scatter, $tolerance and $to-go
# are values with their unit (0.5 rad/s).
figures-trend-settled = settled by the end of the run
figures-trend-ran-away = the run ran away: not a final value
figures-trend-drifting = drifting with the EKF’s random-walk estimate of the load or R_r: a longer run ends elsewhere
figures-trend-fluctuating = fluctuating by ±{ $scatter }: the last sample is not a final value
figures-trend-changing = still changing: { $rate } per s at the end; run longer
figures-trend-changing-to-go = still changing: { $rate } per s at the end; run longer (about { $to-go } still to go)
# The tooltip of a final value's trend: $ms is the length of the end of the run the line is fitted to.
figures-trend-fit = line through the last { $ms } ms: { $rate } per s, the samples scattering { $scatter } about it; settled means the line moves within { $tolerance } and four times the scatter fits it
figures-trend-fit-approach = line through the last { $ms } ms: { $rate } per s, the samples scattering { $scatter } about it; the means of the last three tenths approach a value { $to-go } away; settled means the line moves within { $tolerance } and four times the scatter fits it
# The key figures row: $value is a value with its unit; $ratio a multiple of the rated current.
figures-key-peak = peak |i_s| { $value } ({ $ratio }× rated)
figures-key-final =
    final ω − ω_d { $value } ({ $trend ->
        [settled] settled
        [changing] still changing
        [drifting] drifting
        [fluctuating] fluctuating
       *[ran-away] ran away
    })
figures-key-nis-inside = mean NIS { $value } (inside its 95 % band)
figures-key-nis-outside = mean NIS { $value } (outside its 95 % band)
# The plots' text alternative carries the figures: $figures lists them, separated by semicolons.
figures-caption = Figures of this run: { $figures }.

## The plots

plot-speed = Rotor speed
plot-speed-reference = ω_d reference
plot-speed-estimated = ω̂ estimated
plot-speed-true = ω true
plot-speed-error = Speed tracking error ω − ω_d
plot-flux = Rotor-flux modulus
plot-flux-target = √ψ_d target
plot-flux-estimated = |φ̂| estimated
plot-flux-true = |φ| true
plot-current = Stator currents
plot-current-a-estimated = î_sa estimated
plot-current-b-estimated = î_sb estimated
plot-current-a-true = i_sa true
plot-current-b-true = i_sb true
plot-voltage = Applied stator voltages (after the limit)
# The voltage limit's lines on the voltage plot.
plot-voltage-limit-high = +limit
plot-voltage-limit-low = −limit
plot-z13 = Tracking errors
# "right": the series is read on the plot's right-hand axis.
plot-z13-flux = z3 = |φ̂|² − ψ_d (Wb², right)
plot-z24 = Virtual-control errors
plot-z24-torque = z2 torque error (rad/s²)
plot-z24-flux = z4 flux-rate error (Wb²/s, right)
plot-est = Estimation errors
plot-est-flux = |φ| − |φ̂| (Wb, right)
# A backstepping plot's title ($title) when the classical IFOC drives the motor.
plot-not-driving = { $title } (computed for comparison; not driving the motor)
# A plot's text alternative: $title is its title, $unit its axis's unit, $signals its series' names.
plot-caption = { $title }, in { $unit } against time t in s. Signals: { $signals }.
plot-caption-two-axes = { $title }, in { $unit } (left) and { $unit2 } (right) against time t in s. Signals: { $signals }.
plot-caption-keys = Focus the plot and use the arrow keys to inspect the run sample by sample (Shift: 1 % of the window).

## The Analysis tab


## The Lessons tab


## The Challenge tab


## The challenge panel's controls, built with the page

challenge-progress =
    .aria-label = Challenge runs done
challenge-cancel = Cancel check
challenge-copy = Copy submission link
# $reason, here and in the messages below: the core's message.
challenge-open-failed = The challenge could not be opened: { $reason }. The page shows the default scenario instead.
law-checking = Checking your law against the designed dynamics…
# $reason is why, as the page's worker or the core says it.
law-verdict-failed = The verdict on your law could not be computed: { $reason }
# Said when the walkthrough is opened and its texts cannot be fetched.
walkthrough-load-failed = The walkthrough could not be loaded: check the connection and reload the page.
lesson-panel =
    .aria-label = Lesson
challenge-panel =
    .aria-label = Challenge
stale-back = Back to its scenario
