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
