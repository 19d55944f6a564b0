// The lesson Observer bias: Euler against RK4. Its texts are messages of
// web/locales/LANG/lessons.ftl, whose numbers are variables of the measurements table
// (web/teaching/measurements/observer-bias.csv).
export default {
  id: 'observer-bias',
  run: 'v=1&preset=sine200',
  tab: 'walkthrough',
  plot: 'ekf-plot4', // the NIS against its 95 % band
  holds: [
    // "far outside its band".
    'ob.nis.min > 10 * ob.band.high',
    // "most of the tracking error": RK4 removes more than half of the RMS on every draw.
    'ob.rk.ratio.max < 0.5',
    // The ranges quoted over the two inertia errors and both predictors.
    'ob.jlow.euler.min >= ob.jlow.rk4.min',
    'ob.jhigh.rk4.min >= ob.jlow.rk4.min',
    'ob.jhigh.euler.min >= ob.jlow.rk4.min',
    'ob.jlow.euler.max <= ob.jhigh.euler.max',
    'ob.jhigh.rk4.max <= ob.jhigh.euler.max',
    'ob.jlow.rk4.max <= ob.jhigh.euler.max',
    'ob.jlow.gain.min >= ob.jhigh.gain.min',
    'ob.jhigh.gain.max <= ob.jlow.gain.max',
    // "needs an exact model": with the model off RK4 keeps more than half of Euler's RMS.
    'ob.jhigh.gain.min > 0.5',
    'ob.rrlow.vs.exact.min > 10',
    'ob.rk.nis.max < 2',
    // The curvature removed (20 Hz): the mean NIS drops to near 2.
    'ob.f20.nis.max < 0.1 * ob.nis.min',
    // "the speed estimate's own offset": the estimate tracks ω_d with a mean under 5 % of the offset.
    'ob.z1.mean.max < 0.05 * ob.err.mean.min',
    'ob.z1.mean.min > -0.05 * ob.err.mean.min',
    'ob.err.share.min > 0.5',
    // RK4: no bias, under a twentieth of Euler's.
    'ob.rk.est.mean.max < 0.05 * ob.est.mean.min',
    'ob.rk.est.mean.min > -0.05 * ob.est.mean.min',
  ],
  givens: [
    'its 95 % band',
    'a mean of 2',
    'EKF section (2.)',
    'preset’s 0.25 s',
    '20 % off either way',
    '10 % below',
    '10 % above',
    'under 2:',
    'one 50 µs sample',
    '200 Hz currents',
    'at 20 Hz',
    'from 50 ms on',
  ],
};
