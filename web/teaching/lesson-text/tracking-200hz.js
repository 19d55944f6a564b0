// The lesson Why 200 Hz tracking needs a small amplitude. Numbers are placeholders of the measurements table
// (web/teaching/measurements/tracking-200hz.csv); see web/teaching/measured.js.
export default {
  id: 'tracking-200hz',
  run: 'v=1&preset=sine200-1rad',
  plot: 'voltage', // the voltages against the ±400 V limit
  title: 'Why 200 Hz tracking needs a small amplitude',
  look: 'Doubling the 200 Hz sine to 1 rad/s doubles the acceleration the motor must follow, and so raises the torque, the current and the voltage the drive needs: the voltage plot now reaches the ±400 V limit. Over the preset’s 0.25 s after the start-up transient, the figures strip gives the share of samples at the limit, the tracking error and the peak stator current against the motor’s 4 A rating.',
  question:
    'What share of samples is at the voltage limit, and does it stay so over a longer run (duration = 2)? How does the RMS of ω − ω_d compare with the 0.5 rad/s run (preset sine200)? Which limit does the motor reach first: the voltage or the current?',
  hint: 'Note the figures, then pick sine200 in the preset picker (or press Previous and come back) and read them again. Compare “peak stator current” with the rated 4 A, then drag across the current plot from 50 ms on: do the currents stay past it?',
  answer:
    'Ranges are over {t200.sat1.min#draws} noise draws, with an exact model unless a model error is named. At 200 Hz the current passes the motor’s rating well before the voltage limit matters, and doubling the amplitude roughly quadruples the tracking error. At 1 rad/s {t200.sat1.min} to {t200.sat1.max} % of the strip’s samples are at the limit and the RMS of ω − ω_d is {t200.rms1.min} to {t200.rms1.max} rad/s; at 0.5 rad/s the strip has a sample at the limit on {t200.sat05.n} of {t200.sat05.n#draws} draws and the RMS is {t200.rms05.min} to {t200.rms05.max} rad/s, {t200.ratio.min} to {t200.ratio.max} times less. Two causes each suffice for this, the Euler predictor and the clipping: without any limit (vmax=100000, from a correct initial estimate, init_err=0) the Euler filter’s ratio is {t200.nolim.ratio.min} to {t200.nolim.ratio.max}; with the RK4 predictor (ekf=rk4) and the limit it is {t200.rk4.ratio.min} to {t200.rk4.ratio.max}; only with both removed, RK4 and no limit, is it {t200.linear.ratio.min} to {t200.linear.ratio.max}, as for a linear loop. The share at the limit is not a constant of the run: over 2 s (duration=2) it is {t200.long.min} to {t200.long.max} %, and in 50 ms windows of a longer run (duration=2.1) it swings from {t200.w15.min} to {t200.w05.max} % around 0.5 s and 1.5 s to at most {t200.w10.max} % around 0.95 s and 2 s, about once a second. That comes from the box’s corners: with a round limit (vlimit=circle) the share over 2 s is {t200.circle.min} to {t200.circle.max} times the strip’s. The strip’s peak current, from the end of the start-up transient on, is what the tracking costs: {t200.ipk1.min} to {t200.ipk1.max} A at 1 rad/s and {t200.ipk05.min} to {t200.ipk05.max} A at the paper’s 0.5 rad/s, past the 4 A rating, and the current from 50 ms on reaches the same, {t200.i50_1.min} to {t200.i50_1.max} A and {t200.i50_05.min} to {t200.i50_05.max} A. The start-up itself, while the estimates converge from their 10 % error, draws more: up to {t200.su1.max} A at 1 rad/s and {t200.su05.max} A at 0.5 rad/s. Over a 1 s run (duration=1) the current from 50 ms on passes 4 A at 0.27 rad/s (sine.amp=0.27) on {t200.amp27.over} of {t200.amp27.over#draws} draws, peaking at most at {t200.amp27.max} A, and at 0.28 rad/s (sine.amp=0.28) on {t200.amp28.over} of {t200.amp28.over#draws}, peaking at {t200.amp28.min} to {t200.amp28.max} A. With the model off, the 0.5 rad/s run’s error is at least {t200.jlow.ratio.min} times the exact model’s, with the model’s inertia 20 % high or low or the motor’s R_r 10 % below the model’s; with R_r 10 % above, the 0.5 and the 1 rad/s runs run away on {t200.rrhigh05.away} and {t200.rrhigh1.away} of {t200.rrhigh05.away#draws} draws (see the lesson on low speed).',
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
