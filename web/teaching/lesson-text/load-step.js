// The lesson An unknown load step. Its texts are messages of web/locales/LANG/lessons.ftl, whose
// numbers are variables of the measurements table (web/teaching/measurements/load-step.csv).
export default {
  id: 'load-step',
  run: 'v=1&preset=load-step&duration=3',
  plot: 'speed', // the true speed and its estimate after the load step
  holds: [
    // "the loss is the observer's": the estimate sits on the reference while the speed is far off.
    'lst.z1 < 0.01 * -lst.end.max',
    'lst.est.min > 1.01 * lst.end.min',
    // one value written for the range: the ends differ by less than the last digit shown.
    'lst.end.min - lst.end.max > -0.05',
    'lst.est.min - lst.est.max > -0.05',
    // the perfect observer's run does not depend on the draw.
    'lst.perfect.min == lst.perfect.max',
    'lst.perfect.mean == lst.perfect.max',
    'lst.flux.min - lst.flux.max > -0.005',
    'lst.est.max < 0.99 * lst.end.max',
    // the model-error range written as one range: its ends are the extremes of all four.
    'lst.jlow.min <= lst.rrhigh.min',
    'lst.jlow.min <= lst.rrlow.min',
    'lst.jlow.min <= lst.jhigh.min',
    'lst.jhigh.max >= lst.rrhigh.max',
    'lst.jhigh.max >= lst.rrlow.max',
    'lst.jhigh.max >= lst.jlow.max',
    'lst.perfect.jlow <= lst.perfect.rrhigh',
    'lst.perfect.jlow <= lst.perfect.rrlow',
    'lst.perfect.jlow <= lst.perfect.jhigh',
    // "falls for about a second": within 3 % of its end value at 1 s.
    'lst.t1.min > 1.03 * lst.end.min',
    // settles: 12 s runs end within 0.1 % of the 3 s ones, seed by seed.
    'lst.long.ratio.min > 0.999',
    'lst.long.ratio.max < 1.001',
    // ΔT/J·(1/k1 + 1/k2) = (2/0.02)·(2/1200) = 0.16667 rad/s.
    'lst.perfect.min > -0.16667 - 0.0005',
    'lst.perfect.max < -0.16667 + 0.0005',
    // cause: with the load as a filter state the loss goes.
    'lst.loadstate.min > -0.01 * -lst.end.max',
    'lst.loadstate.max < 0.01 * -lst.end.max',
    // "a bias, not noise" at 1e6 and 1e8; "low".
    'lst.q1e6.share.min >= lst.q1e8.share.min',
    'lst.q1e8.share.min > 0.9',
    'lst.q1e6.mean.max < 0',
    'lst.q1e8.mean.max < 0',
    // "smallest near 1e7".
    'lst.q1e7.rms.max < lst.q3e6.rms.min',
    'lst.q1e7.rms.max < lst.q3e7.rms.min',
    'lst.q1e7.rms.max < lst.q1e6.rms.min',
    'lst.q1e7.rms.max < lst.q1e8.rms.min',
    // "holds" with the inertia off: within 1.5 times the exact model's worst draw.
    'lst.q7.jlow.max < 1.5 * lst.q1e7.rms.max',
    'lst.q7.jhigh.max < 1.5 * lst.q1e7.rms.max',
    'lst.q7.rrhigh.min > 3 * lst.q1e7.rms.max',
    'lst.q7.rrhigh.share > 0.9',
    'lst.q7.rrlow.share < 0.5',
  ],
  givens: [
    '0.15 s',
    '0.3 s',
    '0.2 s',
    '0.5 s',
    '2 N m',
    '3 s',
    '1 s',
    '10 % off',
    '20 % off',
    '5-state',
    'ΔT/J·(1/k1 + 1/k2)',
  ],
};
