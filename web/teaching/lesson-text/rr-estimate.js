// The lesson The remedy: the rotor resistance as an EKF state, and when it can be seen. Its texts
// are messages of web/locales/LANG/lessons.ftl, whose numbers are variables of the measurements
// table (web/teaching/measurements/rr-estimate.csv).
export default {
  id: 'rr-estimate',
  run: 'v=1&preset=rr-mismatch-est&duration=4',
  tab: 'walkthrough',
  plot: 'ekf-plot6', // R̂_r with its ±2σ band against the motor’s
  holds: [
    // "removes the slow transient": a tenth of the smallest error without the state, and within 0.05 rad/s with the model errors.
    're.t03.max < 0.1 * -re.nostate03.max',
    '-re.t03.min < 0.1 * -re.nostate03.max',
    're.rrlow.t03.max < 0.05',
    're.rrlow.t03.min > -0.05',
    're.jhigh.t03.max < 0.05',
    're.jhigh.t03.min > -0.05',
    're.jlow.t03.max < 0.05',
    're.jlow.t03.min > -0.05',
    're.end.min > 0',
    're.nostate.end.max < 0',
    // biased high on every draw, by over 1 %, for each motor R_r and each length.
    're.hat4.min > 1.01',
    're.exact.hat4.min > 1.01',
    're.low.hat4.min > 1.01',
    're.hat8.min > 1.01',
    're.exact.hat8.min > 1.01',
    're.low.hat8.min > 1.01',
    're.hat16.min > 1.01',
    're.exact.hat16.min > 1.01',
    're.low.hat16.min > 1.01',
    // "better than a few per cent": the bias stays under 5 %.
    're.low.hat16.max < 1.05',
    're.low.hat8.max < 1.05',
    // the band is alike on every draw; the motor's value inside it on the smallest bias, outside on the largest.
    're.band8.max - re.band8.min < 0.005',
    '(re.hat8.min - 1) * 5.445 < re.band8.min',
    '(re.hat8.max - 1) * 5.445 > re.band8.max',
    // "little trace": the band without load is at least twice as wide.
    're.nl.vs.min > 2',
  ],
  givens: [
    '10 % rotor-resistance mismatch',
    'over 4 s',
    'Section 2',
    '±2σ',
    '5.445 Ω',
    'at 0.3 s',
    '0.05 rad/s',
    '10 % below',
    '10 % above',
    '20 % off',
    'At 4 s',
    'at 4 s',
    'at 8 s',
    'at 16 s',
  ],
};
