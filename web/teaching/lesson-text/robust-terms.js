// The lesson The robust terms and the bound (59). Numbers are placeholders of the measurements
// table (web/teaching/measurements/robust-terms.csv); see web/teaching/measured.js.
export default {
  id: 'robust-terms',
  run: 'v=1&preset=step&robust=1&eps2=5208&h2=5000&eps4=833&h4=2000',
  title: 'The robust terms and the bound (59)',
  tab: 'walkthrough',
  plot: 'stability-plot', // V against the bound (59)
  look: 'The robust terms (38) and (53) are on (robust = 1), with h2 = 5000 rad/s³ and h4 = 2000 Wb²/s² taken as the bounds on |d̃2| and |d̃4|, and ε2 = 5208, ε4 = 833 chosen so that each term adds h²/(4ε) ≈ 1200/s, the paper’s k2 and k4, to the rate of z2 and z4. The stability section plots V against the bound (59), whose floor is now ε/λ = (ε2 + ε4)/(2·min k_i) ≈ 2.5 (in V’s mixed units).',
  question:
    'Does V stay under (59) here? If not, what does the run have that the theorem leaves out? Then set ε2 = ε4 = 1, the defaults: what happens to the voltage and the speed, and why?',
  hint: 'Compare with noise = 0 (settings, Noise and seed). For ε2 = ε4 = 1, work out h2²/(4ε2) and compare it with the rate a loop sampled at Ts = 50 µs can hold: a forward-Euler step of ż = −k·z, z ← (1 − k·Ts)·z, diverges for k·Ts > 2, that is for k > 40,000/s.',
  answer:
    'Over {rt.v.end.min#draws} noise draws V ends at {rt.v.end.min} to {rt.v.end.max}, above the floor on {rt.v.end.above} of them, and no draw runs away. The measurement noise enters z2 and z4 through the measured currents and the innovations, and the theorem has no noise: with noise = 0 V ends at {rt.quiet.v.end}, far under the floor. Without the robust terms (robust = 0, so ε = 0) V ends at up to {rt.off.v.end.max} on the same draws. The speed error’s RMS is {rt.rms.min} to {rt.rms.max} rad/s, against {rt.off.rms.min} to {rt.off.rms.max} rad/s without the robust terms, and no sample is at the voltage limit (at most {rt.sat.max} %). With ε2 = ε4 = 1 the robust terms add h2²/(4ε2) = 6,250,000/s and h4²/(4ε4) = 1,000,000/s to the rates of z2 and z4, far past what the sampled loop holds: the voltage is at its limit on {rt.eps1.sat.min} to {rt.eps1.sat.max} % of the samples and the speed error’s RMS is {rt.eps1.rms.min} to {rt.eps1.rms.max} rad/s on this 0.5 rad/s step, though no draw runs away ({rt.eps1.away} of {rt.eps1.away#draws}). A smaller ε lowers the floor of the bound and raises that rate, so ε is chosen against the sampling period, which the continuous-time theorem does not see. All this is on the exact model. With the model’s inertia 20 % off either way or the motor’s R_r 10 % below the model’s, ε2 = ε4 = 1 still keeps every sample at the limit, and with the ε above the speed error’s RMS rises to at most {rt.rrlow.rms.max} rad/s.',
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
