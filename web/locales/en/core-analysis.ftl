# What the core says about the page's analyses (sweeps, seed runs and maps).

# A sweep point that had not reached a periodic steady state. $periods: the periods compared;
# $gain (dB) and $phase (degrees): the changes from their first half to their second;
# $gain-bound and $phase-bound: the changes a settled point stays within.
sweep-not-settled = not settled: over the last { $periods } periods, from the first half to the second, the gain of ω changed by { $gain } dB and its phase by { $phase }° (settled: within ±{ $gain-bound } dB and ±{ $phase-bound }°)
