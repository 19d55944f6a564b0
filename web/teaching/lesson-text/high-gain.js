// The lesson Gains past what the observer supports. Its texts are messages of
// web/locales/LANG/lessons.ftl, whose numbers are variables of the measurements table
// (web/teaching/measurements/high-gain.csv).
export default {
  id: 'high-gain',
  run: 'v=1&preset=high-gain',
  tab: 'walkthrough',
  plot: 'step4-plot', // the voltage before and after the limit
  holds: [
    // "almost all the time".
    'hg.sat.min > 0.99',
    // The Euler predictor removed: the saturation goes. The noise removed: it stays.
    'hg.rk4.sat.max < 0.002',
    'hg.noise0.sat > 0.99',
    'hg.away == 0',
    'hg.rk4.away == 0',
    'hg.nis.min > 10 * hg.band.high',
    // The gains removed.
    'hg.g1200.sat.max < 0.002',
    // With each model error: the least Euler share and the largest RK4 share are the quoted ones.
    'hg.jhigh.euler.min >= hg.rrlow.euler.min',
    'hg.jlow.euler.min >= hg.rrlow.euler.min',
    'hg.rrlow.euler.min > 0.98',
    'hg.jlow.rk4.max <= hg.rrlow.rk4.max',
    'hg.jhigh.rk4.max <= hg.rrlow.rk4.max',
    // "in each of these six cases" as often as the first.
    'hg.jlow.euler.away == hg.jhigh.euler.away',
    'hg.rrlow.euler.away == hg.jhigh.euler.away',
    'hg.jhigh.rk4.away == hg.jhigh.euler.away',
    'hg.jlow.rk4.away == hg.jhigh.euler.away',
    'hg.rrlow.rk4.away == hg.jhigh.euler.away',
    // "all in the first 2 ms, before the strip's window starts".
    'hg.g1200.late == 0',
    'hg.g1200.tend.min > 0.002',
    // 20,000/s with a perfect observer: "settles".
    'hg.k20k.away == 0',
    'hg.k20k.reached > 0',
  ],
  givens: [
    '3000/s',
    '2.5× the paper’s',
    'k1–k4',
    'preset’s 0.1 s',
    '20,000/s',
    'at 20 kHz',
    'paper’s 1200/s',
    'at 1200/s',
    '20 % off',
    '10 % below',
    '10 % above',
    '0.5 rad/s step',
    'first 2 ms',
    'noise 0',
    'or 0.016',
    'or 5.445',
  ],
};
