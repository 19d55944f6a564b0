# What the core says about the page's analyses (sweeps, seed runs and maps).

# A sweep point that had not reached a periodic steady state. $periods: the periods compared;
# $gain (dB) and $phase (degrees): the changes from their first half to their second;
# $gain-bound and $phase-bound: the changes a settled point stays within.
sweep-not-settled = not settled: over the last { $periods } periods, from the first half to the second, the gain of ω changed by { $gain } dB and its phase by { $phase }° (settled: within ±{ $gain-bound } dB and ±{ $phase-bound }°)

## A model-error map's axes and seeds: why one is refused, and an axis's name.
# $axis: the axis as written (KEY=LO..HI:N); $key: its field.
map-axis-form = axis '{ $axis }': expected KEY=LO..HI:N, e.g. plant.rr=-10%..+10%:11 or k1=-20%..+20%:5
map-axis-unknown = axis '{ $axis }': { $key } is not a scenario field
map-axis-not-numeric = axis '{ $axis }': { $key } is not a number; a map varies numeric fields
map-axis-whole = axis '{ $axis }': { $key } takes whole numbers only; map a continuous field
map-axis-inactive = axis '{ $axis }': { $key } has no effect in this scenario, so every cell would run the same
# $end: LO or HI (as written in KEY=LO..HI:N); $text: what was given there.
map-axis-end = axis { $key }: { $end } '{ $text }': expected a number or a percentage such as -10%
map-axis-mixed = axis '{ $axis }': LO and HI must both be values or both percentages
map-axis-count = axis { $key }: N '{ $text }': expected a whole number from 1 to { $max }
# $other: the field the percentages are read against.
map-axis-zero = axis '{ $axis }': { $other } is 0, so a relative error of it is 0 too; give { $key } in values
map-axis-order = axis { $key }: LO ({ $lo }) is above HI ({ $hi })
# An axis given in per cent: of the model's value (for a motor parameter), of the motor's (for a
# model parameter), or of the base scenario's own value (for any other field).
map-axis-against-model = { $key } against the model (%)
map-axis-against-motor = { $key } against the motor (%)
map-axis-against-base = { $key } against the base (%)
map-axis-unit = { $key } ({ $unit })
map-seeds-form = seeds '{ $seeds }': expected A..B, whole numbers from 0 to { $max }
map-seeds-order = seeds '{ $seeds }': the first seed is above the last
map-seeds-many = seeds '{ $seeds }': { $count } seeds, more than the { $max } a map runs
map-seeds-twice = seeds are given twice: give them once
map-axes-count = { $count } axes: a map has one or two
map-axes-repeated = both axes vary { $key }: vary two different fields
map-axes-sides = the axes vary { $first } and { $second }, both sides of one parameter: vary one side, in values or as a relative error against the other
map-no-seeds = no seeds: a map runs at least one
map-runs-many = the map needs { $runs } runs ({ $cells } cells × { $seeds } seeds), more than the { $max } allowed; use fewer points or seeds
# $reason: why the field refuses the value (a scenario refusal).
map-cell-refused = { $key }={ $value }: { $reason }
map-work = the map needs { $work } plant steps ({ $cells } cells × { $seeds } seeds × the steps of a run), more than the { $max } allowed; use fewer points or seeds, or a shorter 'duration'
# $per-run: the operations of the costliest run; $runs: how many such runs fit.
map-law-work = the map's own laws take { $work } operations ({ $cells } cells × { $seeds } seeds × up to { $per-run } a run), more than the { $max } allowed; use at most { $runs } runs (cells × seeds), a shorter 'duration', or cheaper laws

## The derived design (design=derived): the rule behind each value, with its reason.
# $voltage: rated line-to-line voltage (V rms); $frequency: rated frequency (Hz).
design-rule-vdc = √2 × { $voltage } V, the rectified line voltage; vlimit=circle, so the voltage limit is the rated phase voltage's amplitude vdc/√3
design-rule-flux = the rotor flux at { $voltage } V, { $frequency } Hz and no load, M·V/|Rs + jωLs|: the motor's own magnetisation
design-rule-flux-capped = capped at M·i_rated/√2 (the no-load flux at { $voltage } V, { $frequency } Hz asks more): the magnetising current leaves half of i_rated² for torque
design-rule-psi = the square of the flux, the target of φa² + φb²
design-rule-id = magnetising current, flux/M
# $i_rated: the rated current amplitude (A).
design-rule-iq = torque current, √({ $i_rated }² − i_d²): the rest of the rated current
design-rule-torque = torque at rated current and flux, (3/2)·np·(M/Lr)·flux·i_q
design-rule-accel = rated acceleration, torque/J: the slope of the reversal the motor can make at rated current
# $share: per cent of the voltage limit.
design-rule-base = base speed: rated flux and rated torque current need { $share } % of the voltage limit in steady state there; above it fw=1 lowers the flux as base/ω, keeping the back-EMF, and the rest of the voltage is the current loops' headroom
# $kts: k·Ts; $share: per cent of the voltage limit; $sigma: leakage inductance σ (H).
design-rule-gain-ts = k2 = k3 = k4 = { $kts }/Ts: each error may fall by { $kts } of itself a sample, as the paper's 1200/s at 20 kHz; the voltage bound, { $share } % of the limit over σ·i_rated (σ = { $sigma } H), is higher
design-rule-gain-voltage = k2 = k3 = k4 = { $share } % of the voltage limit over σ·i_rated (σ = { $sigma } H): closing a rated-current error at that rate asks a quarter of the voltage; the sampling bound { $kts }/Ts is higher
# $ratio: k1 over k2.
design-rule-k1 = k1 = { $ratio } × k2: the speed loop is slower than the current it commands
design-rule-q = process noise: the model is the motor, integrated as the plant is, so Q is only a floor that keeps the filter's gain alive; the paper's 1e-3 would hold these motors' NIS below its band
design-rule-r = the current sensor's noise: R matches it
design-rule-r-none = no sensor noise: r_std = i_rated/1000, which keeps the filter's gain finite
# $time: seconds.
design-rule-q-load = torque²/{ $time } s: the load may move by its rated torque in { $time } s
design-rule-load-std = torque/4: the load starts unknown to a quarter of the rated torque
# Under the preset's description when the scenario has design=derived.
design-derived-heading = The design derived from the motor, and the rule behind each value
# $reason: why the core could not derive it.
design-failed = The derived design could not be shown: { $reason }

## A motor from its nameplate and lab tests (`imlab motor`, the Analysis tab)

# $key is the field (rs, no-load, locked, nema, rated, j, np), $value what was typed.
identify-bad-field = '{ $key }' = '{ $value }': expected { $expected }
identify-expect-positive = a positive number
identify-expect-whole = a whole number of at least 1
identify-expect-nema = A, B, C or D
identify-expect-rated = V,F,I: the rated line voltage (V rms), frequency (Hz) and current (A rms), positive and separated by commas
identify-expect-reading = V,I,P,F: line voltage (V rms), line current (A rms), input power (W) and frequency (Hz), separated by commas; the power may be 0, the others are positive
# $what is a reading's quantity as the code names it (voltage, current, frequency, power, rs).
identify-not-positive = { $what } must be a positive number
# $test is the test's field: no-load or locked.
identify-power-too-high = '{ $test }': the test's power is more than √3·V·I can carry, so its resistance would exceed its impedance
identify-no-rotor-resistance = 'locked': the locked-rotor resistance per phase, { $locked } Ω, is no more than the stator's { $rs } Ω, so no rotor resistance is left
identify-no-magnetising = 'no-load': the no-load reactance is no more than the stator's leakage reactance, so no magnetising reactance is left
# $stator and $rotor are the shares of the leakage (0.5 and 0.5), $letter the NEMA design letter.
identify-heading = the equivalent circuit from the no-load and locked-rotor tests (IEEE Std 112), the locked-rotor leakage split { $stator }/{ $rotor } between stator and rotor (NEMA design { $letter })
identify-how-rs = DC test
identify-how-rr = estimate: locked-rotor resistance less rs, through the magnetising branch
identify-how-m = estimate: no-load reactance less the stator's leakage
identify-how-ls = estimate: m and the stator's share of the locked-rotor leakage
identify-how-lr = estimate: m and the rotor's share of the locked-rotor leakage
identify-how-given = given
identify-link-heading = the motor in preset step, plant and model alike, with its rating and the derived design:
