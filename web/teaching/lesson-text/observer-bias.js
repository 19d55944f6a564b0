// The lesson Observer bias: Euler against RK4. Numbers are placeholders of the measurements table
// (web/teaching/measurements/observer-bias.csv); see web/teaching/measured.js.
export default {
  id: 'observer-bias',
  run: 'v=1&preset=sine200',
  title: 'Observer bias: Euler against RK4',
  tab: 'walkthrough',
  plot: 'ekf-plot4', // the NIS against its 95 % band
  look: 'The mean NIS in the figures strip is shown against its 95 % band: a consistent filter has a mean of 2. Then press “Compare Euler and RK4 predictors” in the EKF section (2.) of this walkthrough. The controller is the same in both runs, over the preset’s 0.25 s.',
  question:
    'Is the paper’s Euler EKF consistent on this run? What happens to the mean NIS and the tracking RMS with the RK4 predictor?',
  hint: 'A mean NIS far outside its band means the filter’s model of its own errors is wrong; the page says so above the figures. The comparison table lists both predictors on the same scenario and seed.',
  answer:
    'Ranges are over {ob.nis.min#draws} noise draws. No: the Euler filter’s mean NIS is {ob.nis.min} to {ob.nis.max}, against its 95 % band, whose lower edge is {ob.band.low}–{ob.band.low.max} and upper edge {ob.band.high.min}–{ob.band.high} over the draws, and its biased speed estimate makes most of the tracking error: RK4 brings the RMS of ω − ω_d from {ob.rms.min}–{ob.rms.max} down to {ob.rk.rms.min}–{ob.rk.rms.max} rad/s, at most {ob.rk.ratio.max} times the Euler filter’s on the same draw. That gain needs an exact model. With the model’s inertia 20 % off either way both predictors track to {ob.jlow.rk4.min}–{ob.jhigh.euler.max} rad/s RMS, RK4’s RMS {ob.jhigh.gain.min} to {ob.jlow.gain.max} times the Euler filter’s on the same draw; with the motor’s rotor resistance 10 % below the model’s Euler tracks to {ob.rrlow.euler.min}–{ob.rrlow.euler.max} and RK4 to {ob.rrlow.rk4.min}–{ob.rrlow.rk4.max} rad/s, at least {ob.rrlow.vs.exact.min} times its RMS with an exact model; with it 10 % above the run runs away on {ob.rrhigh.euler.away} and {ob.rrhigh.rk4.away} of {ob.rrhigh.euler.away#draws} draws with the Euler and the RK4 predictor. With RK4 the mean NIS is {ob.rk.nis.min}–{ob.rk.nis.max}, under 2: RK4 slightly overstates its errors. A forward-Euler prediction over one 50 µs sample misses the curvature of 200 Hz currents (at 20 Hz, sine.freq=20, the Euler filter’s mean NIS is {ob.f20.nis.min}–{ob.f20.nis.max}); the filter blames the miss on the states, so the estimates the controller uses are biased. The error plot shows it: from 50 ms on, with Euler, ω − ω_d swings about a mean of {ob.err.mean.min}–{ob.err.mean.max} rad/s, the speed estimate’s own offset (ω − ω̂ averages {ob.est.mean.min}–{ob.est.mean.max} rad/s, while ω̂ − ω_d averages under a twentieth of that), and that offset is most of the RMS: its square is {ob.err.share.min} to {ob.err.share.max} of the mean square of ω − ω_d. With RK4, ω − ω̂ averages {ob.rk.est.mean.min} to {ob.rk.est.mean.max} rad/s.',
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
