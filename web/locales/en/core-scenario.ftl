# The core's messages about a scenario: why a link, a setting or a run was refused. The CLI says
# them in English from this file; the page in the reader's language. Field names, keys, values,
# presets and settings (v=1, preset=NAME, 'duration', 'ts', law.v2, pwm=1) are the link's own
# words: keep them as they are. Quoted input keeps its quotes.

## A scenario refused

scenario-missing = field '{ $key }' is missing (a scenario starts with v={ $version }&preset=NAME)
scenario-unsupported-version = field 'v' = '{ $value }': unsupported codec version, allowed: { $version }
# $presets lists the presets' names.
scenario-unknown-preset = field 'preset' = '{ $name }': unknown preset, allowed: { $presets }
scenario-unknown-key = field '{ $key }' is not a scenario field (the settings form and `imlab describe` list them)
scenario-duplicate-key = field '{ $key }' is given more than once
scenario-malformed = '{ $piece }' is not of the form key=value
# $expected is one of the scenario-expected-* messages.
scenario-bad-value = field '{ $key }' = '{ $value }': not valid, expected { $expected }
# $allowed is one of the scenario-allowed-* messages.
scenario-out-of-range = field '{ $key }' = { $value }: out of range, allowed { $allowed }
# $reference is the kind of reference the scenario has (step, sine, ramp…).
scenario-not-applicable = field '{ $key }' does not apply to the reference '{ $reference }' (set ref= first)
# $which is "plant" or "model", the prefix of the fields; $error is a param-* message.
scenario-physics = { $which } parameters: { $error }
# $error says where and why the formula was refused (formula-at or another formula-* message of
# core-law.ftl).
scenario-bad-formula = field '{ $key }': { $error }
scenario-refused = field '{ $key }': { $why }
scenario-law-fw = an own law of step 3 or 4 is written for a constant flux target, and fw=1 moves it; turn fw off or leave the law empty
scenario-design = field 'design' = 'derived': { $why }
design-no-voltage = the rated voltage leaves { $available } V for steady operation, and rated flux with rated current needs { $needed } V even at rest
scenario-too-long = the scenario is { $bytes } bytes long, more than the { $max } bytes ({ $kib } KiB) allowed

## What a field takes

scenario-expected-formula = a formula, percent-encoded as UTF-8
scenario-expected-one-of = one of { $options }
scenario-expected-number = a decimal number
# A table of points: a reference or a load torque given as t:value pairs.
scenario-expected-table = points t:value separated by commas, such as 0:0,0.1:100, each a decimal number
scenario-expected-table-length = at most { $max } points; this table has { $count }
scenario-expected-table-rising = times that rise from point to point; { $after } s is not after { $before } s
scenario-expected-table-time = times from 0 to { $max } s; { $t } s is outside
# $unit is the values' unit (rad/s); $before and $after are the times of the two points.
scenario-expected-table-slope = a change of at most { $max } { $unit } a second between points; from { $before } s to { $after } s it is faster
scenario-allowed-choice = { $options }
scenario-allowed-formula = a formula of the names step { $step } may use (`imlab describe` lists them), or empty
# $values is the values' range (scenario-allowed-unit).
scenario-allowed-table = up to { $max } points t:value, times rising from 0 to { $duration } s, values { $values }; straight between points, held before the first and after the last
# A field's range: "0 < k1 ≤ 1000000"; $below is < or ≤.
scenario-allowed-range = { $min } { $below } { $key } ≤ { $max }
# $range is the range above, with its unit after it: "0 < k1 ≤ 1000000 (1/s)".
scenario-allowed-unit = { $range } ({ $unit })
scenario-allowed-whole = { $range }, whole number
scenario-allowed-pwm = pwm=1 with vlimit=circle or hex: a two-level inverter cannot make the box's corners

## A run too large

scenario-too-many-samples = 'duration'/'ts' = { $duration } s / { $ts } s = { $samples } samples is more than the { $max } allowed; shorten 'duration' or raise 'ts'
scenario-shorter-than-sample = 'duration' = { $duration } s is shorter than one sample, 'ts' = { $ts } s
# $how is one of the scenario-work-* messages; $pwm is yes when the run has PWM.
scenario-too-much-work = the run's work, { $samples } samples ('duration'/'ts' = { $duration } s / { $ts } s) × { $per_sample } plant RK4 steps a sample ({ $how }) = { $work } steps, is more than the { $max } allowed; lower 'substeps' or 'duration', or raise 'ts'{ $pwm ->
        [yes] , or turn 'pwm' off
       *[no] {""}
    }
scenario-work-substeps = 'substeps' = { $substeps }
scenario-work-substeps-pwm = 'substeps' = { $substeps } on each of 7 PWM intervals
scenario-work-prediction = { $plant }, and { $substeps } for the perfect observer's prediction ('delay.comp')
# $parts lists scenario-law-work-step and scenario-law-work-rates messages.
scenario-law-work = the laws' work, { $samples } samples ('duration'/'ts' = { $duration } s / { $ts } s) × { $per_sample } operations a sample ({ $parts }) = { $work }, is more than the { $max } allowed (a sine or cosine counts 64 operations, a power 32, exp, ln, tanh and atan2 12 each); write laws that take at most { $fits } operations a sample, or shorten 'duration' to { $duration_fit } s or raise 'ts' to { $ts_fit } s
scenario-law-work-step = law.v{ $step } { $work }
scenario-law-work-rates = the rates of the own v1 and v3 { $work }
# $fewer is yes when the caller can keep every n-th sample.
scenario-trace-too-large = recording { $rows } samples × { $columns } columns needs { $mib } MiB, more than the { $max } MiB allowed; shorten 'duration' or raise 'ts'{ $fewer ->
        [yes] , or keep fewer samples (a larger 'every')
       *[no] {""}
    }
sweep-run-too-large = each sweep run keeps its { $samples } samples, { $mib } MiB, more than the { $max } MiB allowed; shorten the sweep's run length or raise 'ts'

## Motor parameters that are not physical

param-not-positive = { $name } = { $value } must be a finite number > 0
param-negative = { $name } = { $value } must be a finite number ≥ 0
param-sigma = leakage σ = Ls − M²/Lr = { $sigma } H must be > 0 (M = { $m }, Ls = { $ls }, Lr = { $lr }): M² must be smaller than Ls·Lr
scenario-allowed-every = 1 ≤ every

## A sweep's run refused

sweep-allowed-amp = 0 < sine.amp for a sweep
sweep-allowed-nyquist = below the Nyquist frequency 1/(2·Ts) = { $nyquist } Hz
sweep-allowed-period = at least one period in the fit window: freq ≥ { $least } Hz for a { $duration } s run
# $reason is sweep-unresolved or sweep-too-small.
sweep-allowed-measurable = an amplitude the sweep can measure: { $reason }; raise the amplitude
sweep-unresolved = the fit of ω_d itself over the fit window finds { $found } rad/s, more than { $tolerance } % off (the amplitude's square underflows, or offset + amplitude rounds to the offset { $offset } rad/s)
# $name is a figure's column name, $value its value (NaN or inf).
sweep-too-small = at { $freq } Hz the response reads as { $name } = { $value }, too small for the fit

## Lists

# What separates the items of a list the core gives ("law.v1 12, law.v2 40").
core-list-separator = {", "}
# A field the link changes that the run does not read; $because: the settings that leave it idle,
# as the link writes them (controller=ifoc, robust=0).
field-idle = { $key } has no effect with { $because }
