// The lesson The robust terms and the bound (59). Numbers are placeholders of the measurements
// table (web/teaching/measurements/robust-terms.csv).
export default {
  id: 'robust-terms',
  run: 'v=1&preset=step&robust=1&eps2=5208&h2=5000&eps4=833&h4=2000',
  tab: 'walkthrough',
  plot: 'stability-plot', // V against the bound (59)
  holds: [
    // "no draw runs away", with the ε sized and with ε = 1.
    'rt.away == 0',
    'rt.eps1.away == 0',
    // "far under the floor" ε/λ = (5208 + 833)/2400.
    'rt.quiet.v.end < 0.01 * (5208 + 833) / 2400',
    'rt.v.end.above > 0',
    'rt.sat.max == 0',
    // "still keeps every sample at the limit".
    'rt.jhigh.eps1.sat.min == 1',
    'rt.jlow.eps1.sat.min == 1',
    'rt.rrlow.eps1.sat.min == 1',
    // "at most": the largest of the three model errors is the quoted one.
    'rt.jhigh.rms.max <= rt.rrlow.rms.max',
    'rt.jlow.rms.max <= rt.rrlow.rms.max',
  ],
  givens: [
    '(robust = 1)',
    'h2 = 5000 rad/s³ and h4 = 2000 Wb²/s²',
    'ε2 = 5208, ε4 = 833',
    'h²/(4ε) ≈ 1200/s',
    'ε/λ = (ε2 + ε4)/(2·min k_i) ≈ 2.5',
    'set ε2 = ε4 = 1',
    'noise = 0',
    'For ε2 = ε4 = 1, work out h2²/(4ε2)',
    'Ts = 50 µs',
    'z ← (1 − k·Ts)·z, diverges for k·Ts > 2, that is for k > 40,000/s',
    '(robust = 0, so ε = 0)',
    'With ε2 = ε4 = 1',
    'h2²/(4ε2) = 6,250,000/s and h4²/(4ε4) = 1,000,000/s',
    '0.5 rad/s step',
    '20 % off',
    '10 % below',
    'ε2 = ε4 = 1 still',
  ],
};
