// The lesson The remedy: the load as an EKF state. Its texts are messages of
// web/locales/LANG/lessons.ftl, whose numbers are variables of the measurements table
// (web/teaching/measurements/load-estimate.csv).
export default {
  id: 'load-estimate',
  run: 'v=1&preset=load-step-est',
  tab: 'walkthrough',
  plot: 'ekf-plot5', // the load estimate with its ±2σ band against the true load
  holds: [
    // one value written for the range.
    'le.load.max - le.load.min < 0.005',
    'le.load3.max - le.load3.min < 0.005',
    'le.band.max - le.band.min < 0.005',
    // "T0 + 2 N m to within a hundredth", at the end of the preset's run and of a 3 s run.
    'le.load.min > 2.49',
    'le.load.max < 2.51',
    'le.load3.min > 2.49',
    'le.load3.max < 2.51',
    // the inertia worst cases written are the worse of the two signs.
    'le.jlow.dip <= le.jhigh.dip',
    'le.jlow.back >= le.jhigh.back',
    // "holds": within 1.1 times the exact model's worst dip and 10 ms.
    'le.jlow.dip > 1.1 * le.dip.min',
    'le.jlow.back < 0.01',
    // "steady": little variation over the last second, and a 12 s run ends within 5 % of the 3 s value on each draw.
    'le.rrhigh.sd < 0.01 * -le.rrhigh.end.max',
    'le.rrhigh.ratio.min > 0.95',
    'le.rrhigh.ratio.max < 1.05',
    // the Euler predictor with the paper's Q: far worse than either change alone.
    'le.euler.max < -10 * le.eulersmallq.max',
    'le.rk4q.max < 0.1 * -le.euler.max',
    '-le.rk4q.min < 0.1 * -le.euler.max',
    'le.eulersmallq.min > 0',
    // R̂_r "takes up the load": well above the motor's 4.95 Ω on every draw.
    'le.rrstate.hat.min > 1.05 * 4.95',
  ],
  givens: [
    '2 N m',
    '0.15 s',
    '±2σ',
    'section 2',
    '0.14–0.2 s',
    'after 0.2 s',
    '10 % below',
    '0.05 rad/s',
    '0.1 s',
    'at 0.3 s',
    '3 s',
    '20 % off',
    '10 % above',
    '3 % below',
    'T0 = 0.5',
    '4.95 Ω',
  ],
};
