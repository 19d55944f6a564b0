// The lesson Why 200 Hz tracking needs a small amplitude. Its texts are messages of
// web/locales/LANG/lessons.ftl, whose numbers are variables of the measurements table
// (web/teaching/measurements/tracking-200hz.csv).
export default {
  id: 'tracking-200hz',
  run: 'v=1&preset=sine200-1rad',
  plot: 'voltage', // the voltages against the ±400 V limit
  holds: [
    't200.sat1.min > 0',
    't200.sat05.n == 0',
    // The clipping removed: no sample at the limit. The Euler predictor removed: RK4 still clips.
    't200.nolim.sat.max == 0',
    't200.rk4.sat.min > 0',
    // "each suffice": each cause alone gives more than 3.4 times; both removed, 2 within 1 %.
    't200.nolim.ratio.min > 3.4',
    't200.rk4.ratio.min > 3.4',
    't200.linear.ratio.min > 1.98',
    't200.linear.ratio.max < 2.02',
    // The windows' ranges quoted from one window hold for the other.
    't200.w05.min >= t200.w15.min',
    't200.w15.max <= t200.w05.max',
    't200.w20.max <= t200.w10.max',
    // "the same all through the run" with the round limit: within 1 %.
    't200.circle.min > 0.99',
    't200.circle.max < 1.01',
    // "reaches the same": the strip's peak and the current from 50 ms on agree within 1 %.
    't200.i50_1.min >= 0.99 * t200.ipk1.min',
    't200.i50_1.max <= 1.01 * t200.ipk1.max',
    't200.i50_05.min >= 0.99 * t200.ipk05.min',
    't200.i50_05.max <= 1.01 * t200.ipk05.max',
    't200.i50_05.min > 4',
    // "draws more": the start-up's peak passes the strip's on some draw.
    't200.su1.max > 1.05 * t200.ipk1.max',
    't200.su05.max > 1.05 * t200.ipk05.max',
    // The 4 A limit lies between 0.27 and 0.28 rad/s.
    't200.amp27.over < t200.amp28.over',
    // "at least": the least ratio is the low inertia's.
    't200.jhigh.ratio.min >= t200.jlow.ratio.min',
    't200.rrlow.ratio.min >= t200.jlow.ratio.min',
  ],
  givens: [
    'Why 200 Hz tracking',
    '200 Hz sine to 1 rad/s',
    '±400 V',
    '0.25 s after',
    '4 A rating',
    'the 0.5 rad/s run',
    'rated 4 A',
    'their 10 % error',
    'from 50 ms on',
    'At 200 Hz the current',
    'At 1 rad/s',
    'at 0.5 rad/s',
    'in 50 ms windows',
    'around 0.5 s and 1.5 s',
    'around 0.95 s and 2 s',
    'over 2 s',
    'A at 1 rad/s',
    'paper’s 0.5 rad/s',
    'passes 4 A',
    '0.27 rad/s',
    '0.28 rad/s',
    'Over a 1 s run',
    'the 0.5 rad/s run’s error',
    '20 % high or low',
    '10 % below',
    '10 % above',
    'the 0.5 and the 1 rad/s runs',
  ],
};
